#!/usr/bin/env bash
# Executes every notebook in notebooks/ with the Python module gkt and Debian's jupyter-nbconvert
# (kernel: Debian's /usr/bin/python3); exits non-zero if one no longer executes. The committed
# notebooks keep their outputs (figures) so they read on a repository page; the check runs on
# copies and leaves them alone.
#
#   bash tools/run_notebooks.sh [BUILD_DIR]            check (default BUILD_DIR: build)
#   bash tools/run_notebooks.sh --update [BUILD_DIR]   execute in place, refreshing the outputs
#
# Builds the module (target gkt_python) in BUILD_DIR first, configuring it with
# -DGKT_BUILD_PYTHON=ON if it is not yet. Each notebook runs in well under 30 s.
set -euo pipefail
cd "$(dirname "$0")/.."
update=0
if [[ ${1:-} == --update ]]; then
  update=1
  shift
fi
build=${1:-build}
if ! grep -q '^GKT_BUILD_PYTHON:BOOL=ON$' "$build/CMakeCache.txt" 2>/dev/null; then
  cmake -S . -B "$build" -DGKT_BUILD_PYTHON=ON >/dev/null
fi
cmake --build "$build" --target gkt_python -j"$(nproc)" >/dev/null
export PYTHONPATH="$PWD/$build/python${PYTHONPATH:+:$PYTHONPATH}"
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
export JUPYTER_RUNTIME_DIR="$scratch/runtime" IPYTHONDIR="$scratch/ipython"  # nothing written to $HOME
status=0
for notebook in notebooks/*.ipynb; do
  start=$(date +%s%N)
  where=(--output-dir "$scratch")
  ((update)) && where=(--inplace)
  if /usr/bin/python3 -m nbconvert --to notebook --execute --ExecutePreprocessor.kernel_name=python3 \
    --ExecutePreprocessor.timeout=120 --ExecutePreprocessor.record_timing=False "${where[@]}" "$notebook" >"$scratch/log" 2>&1; then
    elapsed=$((($(date +%s%N) - start) / 100000000))
    echo "run_notebooks: $notebook ok ($((elapsed / 10)).$((elapsed % 10)) s)"
  else
    echo "run_notebooks: $notebook FAILED:" >&2
    tail -n 30 "$scratch/log" >&2
    status=1
  fi
done
exit $status
