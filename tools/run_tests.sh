#!/usr/bin/env bash
# Every test: install dependencies, check formatting, the include graph and the API reference
# (Doxygen, no warnings), build warning-free (Release) and run the
# whole suite (with the Python module's pytest suite), install into a temporary prefix and build
# examples/consumer/ against it (tools/check_install.sh), check the shipped tables against their
# scenes (tools/check_tables.sh), then rebuild with AddressSanitizer + UndefinedBehaviorSanitizer
# and run the suite again; then a short fuzz run (tools/fuzz.sh) and, last, execute the notebooks
# (tools/run_notebooks.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/install_dependencies.sh
jobs=$(nproc)

if command -v clang-format >/dev/null; then
  git ls-files '*.cpp' '*.hpp' | xargs clang-format --dry-run --Werror
  echo "run_tests: formatting ok"
fi
python3 tools/check_layers.py  # include graph: no arrow up the floors (docs/architecture.md)
bash tools/run_doxygen.sh build/doxygen  # API reference from the headers: any Doxygen warning fails (~1 s)

# GKT_BUILD_TESTS=ON is forced: build/ may come from tools/run_main.sh, which turns the tests off,
# and --no-tests=error makes an empty suite fail instead of passing silently (issue 17).
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DGKT_BUILD_TESTS=ON -DCMAKE_COMPILE_WARNING_AS_ERROR=ON \
  -DGKT_BUILD_PYTHON=ON
cmake --build build -j"$jobs"
ctest --test-dir build --output-on-failure --no-tests=error -j"$jobs"
bash tools/check_install.sh build
bash tools/check_tables.sh build

cmake -S . -B build-sanitize -DCMAKE_BUILD_TYPE=RelWithDebInfo -DGKT_SANITIZE=ON -DGKT_BUILD_TESTS=ON \
  -DGKT_BUILD_BENCHMARKS=OFF -DCMAKE_COMPILE_WARNING_AS_ERROR=ON
cmake --build build-sanitize -j"$jobs"
ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
  ctest --test-dir build-sanitize --output-on-failure --no-tests=error -j"$jobs"
bash tools/fuzz.sh                 # libFuzzer: scene parser and per-cell calls, 45 s each (docs/fuzzing.md)
bash tools/run_notebooks.sh build  # every notebook still executes (the module of the Release build)
