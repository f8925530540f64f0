#!/usr/bin/env bash
# Checks that every shipped table tables/*.csv is what its scene prints now: runs each command
# written in the scene headers (`#   build/bin/gkt ... --output tables/NAME.csv`) with the gkt of
# BUILD_DIR into a temporary directory and compares float-tolerantly with the shipped file:
# same header and shape, numeric cells within relative 1e-12 (2e-2 on the 3-digit *_error columns),
# other cells (exact rationals, text) equal — the tolerances of the golden tests (tests/golden/README.md).
# Every tables/*.csv must have exactly one such command. See tables/README.md.
#
#   bash tools/check_tables.sh [--regenerate] [BUILD_DIR]     (default: build)
#
# --regenerate writes the new tables over the shipped ones instead (then `git diff tables/`).
set -euo pipefail
cd "$(dirname "$0")/.."
regenerate=0
if [[ ${1:-} == --regenerate ]]; then
  regenerate=1
  shift
fi
gkt=$(realpath "${1:-build}")/bin/gkt
[[ -x $gkt ]] || { echo "check_tables: no $gkt; build gkt first (README)" >&2; exit 2; }
work=$(mktemp -d "${TMPDIR:-/tmp}/gkt_check_tables.XXXXXX")
trap 'rm -rf "$work"' EXIT
jobs=$(nproc)

# The commands, one per shipped table.
declare -A command=()
while IFS= read -r line; do
  cmd=${line#\#   build/bin/gkt }
  [[ $cmd =~ --output\ tables/([A-Za-z0-9_.-]+\.csv)$ ]] || continue
  name=${BASH_REMATCH[1]}
  if [[ -n ${command[$name]:-} ]]; then
    echo "check_tables: two commands write tables/$name" >&2
    exit 1
  fi
  cmd=${cmd%--output tables/"$name"}
  command[$name]=${cmd%"${cmd##*[![:space:]]}"}
done < <(grep -h '^#   build/bin/gkt ' tables/scenes/*.toml)
status=0
for table in tables/*.csv; do
  name=$(basename "$table")
  [[ -n ${command[$name]:-} ]] || { echo "check_tables: no scene header writes $table" >&2; status=1; }
done
for name in "${!command[@]}"; do
  [[ -f tables/$name || $regenerate == 1 ]] || { echo "check_tables: tables/$name is not shipped" >&2; status=1; }
done
((status == 0)) || exit 1

# Run them, $jobs at a time (the options are shell-quoted in the headers, hence eval).
for name in "${!command[@]}"; do
  while (($(jobs -rp | wc -l) >= jobs)); do wait -n || true; done
  (
    if eval "\"\$gkt\" ${command[$name]} --output \"\$work/\$name\"" 2>"$work/$name.err"; then
      echo 0 >"$work/$name.status"
    else
      echo 1 >"$work/$name.status"
    fi
  ) &
done
wait

compare() {  # new shipped
  awk -F, '
    function number(s) { return s ~ /^[-+]?([0-9]+\.?[0-9]*|\.[0-9]+)([eE][-+]?[0-9]+)?$/ }
    NR == FNR { row[FNR] = $0; rows = FNR; next }
    {
      if (FNR > rows) { print "  more rows than printed"; bad = 1; exit }
      if (FNR == 1) { n = split($0, head, ","); if (row[1] != $0) { print "  header differs"; bad = 1; exit } next }
      m = split(row[FNR], got, ",")
      if (m != NF) { print "  row " FNR - 1 ": " m " cells, shipped " NF; bad = 1; next }
      for (i = 1; i <= NF; ++i) {
        if (number(got[i]) && number($i)) {
          x = got[i] + 0; y = $i + 0; d = x - y; if (d < 0) d = -d; t = (y < 0 ? -y : y) * (head[i] ~ /_error$/ ? 2e-2 : 1e-12)
          if (d > t) { printf "  row %d %s: printed %s, shipped %s\n", FNR - 1, head[i], got[i], $i; bad = 1 }
        } else if (got[i] != $i) { printf "  row %d %s: printed %s, shipped %s\n", FNR - 1, head[i], got[i], $i; bad = 1 }
      }
    }
    END { if (!bad && FNR != rows) { print "  fewer rows than printed"; bad = 1 } exit bad }' "$1" "$2"
}

failed=()
for name in $(printf '%s\n' "${!command[@]}" | sort); do
  if [[ $(cat "$work/$name.status") != 0 ]]; then
    echo "check_tables: gkt ${command[$name]} failed:" >&2
    cat "$work/$name.err" >&2
    failed+=("$name")
  elif ((regenerate)); then
    mv "$work/$name" "tables/$name"
  elif ! compare "$work/$name" "tables/$name" >"$work/$name.diff"; then
    echo "check_tables: tables/$name differs from what its scene prints (gkt ${command[$name]}):" >&2
    head -n 10 "$work/$name.diff" >&2
    failed+=("$name")
  fi
done
if ((${#failed[@]})); then
  echo "check_tables: ${#failed[@]} of ${#command[@]} tables fail: ${failed[*]}" >&2
  echo "check_tables: after a deliberate change: bash tools/check_tables.sh --regenerate, and say why in the commit" >&2
  exit 1
fi
if ((regenerate)); then
  echo "check_tables: regenerated ${#command[@]} tables in tables/"
else
  echo "check_tables: all ${#command[@]} tables in tables/ equal what their scenes print (relative 1e-12, errors 2e-2)"
fi
