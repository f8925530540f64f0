#!/usr/bin/env bash
# Builds the API reference from the public headers (docs/Doxyfile) and fails on any Doxygen warning
# (WARN_AS_ERROR = FAIL_ON_WARNINGS): a malformed doc comment, or a public member without one
# (WARN_IF_UNDOCUMENTED), breaks the build of the reference.
#
#   bash tools/run_doxygen.sh [OUTPUT_DIR]      (default: build/doxygen; HTML in OUTPUT_DIR/html)
set -euo pipefail
cd "$(dirname "$0")/.."
command -v doxygen >/dev/null || { echo "run_doxygen: doxygen not found (Debian package doxygen; tools/install_dependencies.sh)" >&2; exit 2; }
output=${1:-build/doxygen}
mkdir -p "$output"
version=$(sed -n 's/^project(gkt VERSION \([0-9.]*\).*/\1/p' CMakeLists.txt)
log="$output/warnings.log"
if ! GKT_VERSION="$version" GKT_DOXYGEN_OUTPUT="$output" doxygen docs/Doxyfile 2>"$log"; then
  cat "$log" >&2
  echo "run_doxygen: doxygen reported warnings (above); fix the doc comments" >&2
  exit 1
fi
if [[ -s $log ]]; then  # belt and braces: FAIL_ON_WARNINGS already fails on these
  cat "$log" >&2
  exit 1
fi
echo "run_doxygen: API reference in $output/html ($(find "$output/html" -name '*.html' | wc -l) pages), no warnings" \
  "(every public member documented)"
