#!/usr/bin/env bash
# Rewrites the golden CLI outputs in tests/golden/ from tests/golden/manifest.tsv with an already
# built gkt: each file is one header line naming its command and the gkt version, then what the
# command prints. They are regression data: regenerate only after a deliberate change and say why
# in the commit (tests/golden/README.md); `git diff` shows what moved.
#
#   bash tools/regenerate_goldens.sh [BUILD_DIR]      (default: build)
set -euo pipefail
cd "$(dirname "$0")/.."
gkt=${1:-build}/bin/gkt
[[ -x $gkt ]] || { echo "regenerate_goldens: no $gkt; build gkt first (README)" >&2; exit 2; }
version=$("$gkt" --version)
version=${version#gkt }
count=0
while IFS= read -r line; do
  [[ -z $line || $line == \#* ]] && continue
  IFS=$'\t' read -r golden subcommand scene options <<<"$line"
  command="$subcommand $scene${options:+ $options}"
  tmp=$(mktemp "tests/golden/.$golden.XXXXXX")
  printf '# regression data: gkt %s (gkt %s); regenerate: bash tools/regenerate_goldens.sh\n' "$command" "$version" >"$tmp"
  # The options are shell-quoted in the manifest (as tests/test_cli.cpp passes them to the shell).
  if ! eval "\"\$gkt\" $command" >>"$tmp" 2>"$tmp.err"; then
    echo "regenerate_goldens: gkt $command failed:" >&2
    cat "$tmp.err" >&2
    rm -f "$tmp" "$tmp.err"
    exit 1
  fi
  rm -f "$tmp.err"
  mv "$tmp" "tests/golden/$golden"
  count=$((count + 1))
done <tests/golden/manifest.tsv
echo "regenerate_goldens: wrote $count files in tests/golden/ (gkt $version)"
