#!/usr/bin/env bash
# Every test: install dependencies, check formatting, build warning-free (Release) and run the
# whole suite (with the Python module's pytest suite), then rebuild with AddressSanitizer +
# UndefinedBehaviorSanitizer and run it again; last, execute the notebooks (tools/run_notebooks.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/install_dependencies.sh
jobs=$(nproc)

if command -v clang-format >/dev/null; then
  git ls-files '*.cpp' '*.hpp' | xargs clang-format --dry-run --Werror
  echo "run_tests: formatting ok"
fi
python3 tools/check_layers.py  # include graph: no arrow up the floors (docs/architecture.md)

cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DCMAKE_COMPILE_WARNING_AS_ERROR=ON -DGKT_BUILD_PYTHON=ON
cmake --build build -j"$jobs"
ctest --test-dir build --output-on-failure -j"$jobs"

cmake -S . -B build-sanitize -DCMAKE_BUILD_TYPE=RelWithDebInfo -DGKT_SANITIZE=ON -DGKT_BUILD_BENCHMARKS=OFF \
  -DCMAKE_COMPILE_WARNING_AS_ERROR=ON
cmake --build build-sanitize -j"$jobs"
ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
  ctest --test-dir build-sanitize --output-on-failure -j"$jobs"
bash tools/run_notebooks.sh build  # every notebook still executes (the module of the Release build)
