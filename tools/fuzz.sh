#!/usr/bin/env bash
# Short fuzz run (issue 17): builds the libFuzzer targets of tests/fuzz with clang (GKT_FUZZ=ON,
# AddressSanitizer + UndefinedBehaviorSanitizer) in build-fuzz/ and runs each for a bounded time
# from the seed corpus in tests/fuzz/corpus/<target>/ (read only: new inputs go to a temporary
# directory). Fails on any crash, sanitizer report, uncaught exception other than
# std::invalid_argument, timeout or out-of-memory; the failing input is left in build-fuzz/artifacts/.
#   bash tools/fuzz.sh              # 45 s per target (about 2 minutes with the table builds)
#   FUZZ_SECONDS=600 bash tools/fuzz.sh
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${FUZZ_SECONDS:-45}
jobs=$(nproc)
command -v clang++-14 >/dev/null || bash tools/install_dependencies.sh

cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_C_COMPILER=clang-14 \
  -DCMAKE_CXX_COMPILER=clang++-14 -DGKT_FUZZ=ON -DGKT_BUILD_TESTS=OFF -DGKT_BUILD_BENCHMARKS=OFF >/dev/null
cmake --build build-fuzz -j"$jobs" --target fuzz_scene fuzz_per_cell

mkdir -p build-fuzz/artifacts
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
for target in fuzz_scene fuzz_per_cell; do
  corpus=tests/fuzz/corpus/${target#fuzz_}
  mkdir -p "$scratch/$target"
  echo "fuzz: $target for ${seconds} s (seeds: $corpus)"
  log=$scratch/$target.log
  status=0
  TMPDIR="$scratch" build-fuzz/bin/"$target" "$scratch/$target" "$corpus" -max_total_time="$seconds" \
    -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 -artifact_prefix=build-fuzz/artifacts/"$target"- \
    >"$log" 2>&1 || status=$?
  grep -E '^(#[0-9]+.*DONE|stat::number_of_executed_units|stat::average_exec_per_sec)' "$log" || true
  if ((status != 0)); then
    tail -n 60 "$log" >&2
    echo "fuzz: $target FAILED (exit $status); inputs in build-fuzz/artifacts/" >&2
    exit 1
  fi
done
echo "fuzz: no findings"
