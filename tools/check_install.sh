#!/usr/bin/env bash
# Installs gkt into a temporary prefix and builds examples/consumer/ against the installed tree
# twice — with CMake (find_package(gkt CONFIG REQUIRED), gkt::gkt) and with
# `pkg-config --cflags --libs gkt` — runs both and checks their numbers against the installed
# `gkt table` on the same states (relative 1e-12 + absolute 1e-15: the per-cell closed forms carry
# their coefficients rounded to double, `gkt table` rounds the exact rational once).
#
#   bash tools/check_install.sh [BUILD_DIR]
#
# BUILD_DIR: a configured gkt build tree to (re)build and install from, e.g. the Release `build`
# of tools/run_tests.sh; without it a Release tree is configured in the temporary directory.
set -euo pipefail
cd "$(dirname "$0")/.."
work=$(mktemp -d "${TMPDIR:-/tmp}/gkt_check_install.XXXXXX")
trap 'rm -rf "$work"' EXIT
jobs=$(nproc)

if (($# >= 1)); then
  build=$(realpath "$1")
else
  build=$work/build
  cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DGKT_BUILD_TESTS=OFF -DGKT_BUILD_BENCHMARKS=OFF >/dev/null
fi
cmake --build "$build" -j"$jobs" --target gkt gkt_cli >/dev/null
prefix=$work/prefix
cmake --install "$build" --prefix "$prefix" >/dev/null
for f in include/gkt/transport/closed_forms/first_sonine_formulas.hpp bin/gkt; do
  [[ -e $prefix/$f ]] || { echo "check_install: $f not installed" >&2; exit 1; }
done
config=$(find "$prefix" -name gktConfig.cmake -print -quit)
pc=$(find "$prefix" -name gkt.pc -print -quit)
[[ -n $config && -n $pc ]] || { echo "check_install: gktConfig.cmake or gkt.pc not installed" >&2; exit 1; }

# 0. Every public header is installed, and all of them compile with only the installed tree and
#    the dependencies' flags (no include of a private lib/ header).
if ! diff <(cd include && find gkt -name '*.hpp' | sort) <(cd "$prefix/include" && find gkt -name '*.hpp' | sort); then
  echo "check_install: the installed headers differ from include/gkt/ (< source, > installed)" >&2
  exit 1
fi
(cd "$prefix/include" && find gkt -name '*.hpp' | sort | sed 's/.*/#include "&"/') >"$work/all_headers.cpp"
# shellcheck disable=SC2046  # the flags are words
"${CXX:-c++}" -std=c++20 -fsyntax-only -Wall -Wextra -Wpedantic -Werror "$work/all_headers.cpp" \
  $(PKG_CONFIG_PATH="$(dirname "$pc")" pkg-config --cflags gkt)

# 1. CMake: the consumer sees only the installed prefix.
cmake -S examples/consumer -B "$work/consumer-cmake" -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$prefix" \
  -DCMAKE_FIND_PACKAGE_NO_PACKAGE_REGISTRY=ON >/dev/null
cmake --build "$work/consumer-cmake" -j"$jobs" >/dev/null
# 2. pkg-config.
pkg_flags=$(PKG_CONFIG_PATH="$(dirname "$pc")" pkg-config --cflags --libs gkt)
# shellcheck disable=SC2086  # the flags are words
"${CXX:-c++}" -std=c++20 -O2 examples/consumer/main.cpp $pkg_flags -o "$work/consumer-pkg-config"

# 3. libgkt's private dependencies come along: a program that pulls in the CVODE (time evolution)
#    and GSL (viscoelastic contact) parts of the static library links both ways.
mkdir -p "$work/private-deps"
cat >"$work/private-deps/main.cpp" <<'CPP'
#include <cstdio>

#include "gkt/collision/viscoelastic_contact.hpp"
#include "gkt/evolution/homogeneous_cooling_evolution.hpp"

int main() {
  const auto evolve = &gkt::evolve_homogeneous_cooling;
  std::printf("%d %g\n", evolve != nullptr, gkt::viscoelastic_restitution_c1());
}
CPP
printf '%s\n' 'cmake_minimum_required(VERSION 3.24)' 'project(private_deps LANGUAGES C CXX)' \
  'find_package(gkt CONFIG REQUIRED)' 'add_executable(private_deps main.cpp)' \
  'target_link_libraries(private_deps PRIVATE gkt::gkt)' >"$work/private-deps/CMakeLists.txt"
cmake -S "$work/private-deps" -B "$work/private-deps/build" -DCMAKE_PREFIX_PATH="$prefix" >/dev/null
cmake --build "$work/private-deps/build" >/dev/null
"$work/private-deps/build/private_deps" >/dev/null
# shellcheck disable=SC2086  # the flags are words
"${CXX:-c++}" -std=c++20 "$work/private-deps/main.cpp" $pkg_flags -o "$work/private-deps/pkg-config"
"$work/private-deps/pkg-config" >/dev/null

# Every numeric column the consumer prints must equal the same column of `gkt table`.
compare() {  # consumer.csv table.csv label
  awk -F, -v label="$3" '
    NR == FNR { if (FNR == 1) for (i = 1; i <= NF; ++i) name[i] = $i; else for (i = 1; i <= NF; ++i) got[name[i]] = $i; n = NF; next }
    FNR == 1 { for (i = 1; i <= NF; ++i) col[$i] = i; next }
    FNR == 2 {
      for (i = 3; i <= n; ++i) {
        c = name[i]
        if (!(c in col)) { print "check_install: " label ": gkt table has no column " c > "/dev/stderr"; bad = 1; continue }
        x = got[c] + 0; y = $(col[c]) + 0; d = x - y; if (d < 0) d = -d; m = y < 0 ? -y : y
        if (d > 1e-12 * m + 1e-15) { printf "check_install: %s: %s = %.17g, gkt table %.17g\n", label, c, x, y > "/dev/stderr"; bad = 1 }
        ++checked
      }
    }
    END { if (checked < 5) { print "check_install: " label ": compared " checked + 0 " values" > "/dev/stderr"; bad = 1 }
          exit bad }' "$1" "$2"
}

names='["a2", "cooling_rate", "shear_viscosity", "thermal_conductivity", "density_heat_coefficient"]'
for state in "3 0.8" "2 0.5" "3 1"; do
  read -r d a <<<"$state"
  "$prefix/bin/gkt" table tables/scenes/navier_stokes_first_sonine.toml --set dimension="$d" --set "alpha=[$a]" \
    --set "coefficients=$names" >"$work/table.csv"
  for consumer in consumer-cmake/gkt_consumer consumer-pkg-config; do
    "$work/$consumer" "$d" "$a" >"$work/consumer.csv"
    compare "$work/consumer.csv" "$work/table.csv" "$(basename "$consumer") d=$d alpha=$a"
  done
done
echo "check_install: $(wc -l <"$work/all_headers.cpp") headers (compiled against the installed tree), libgkt, gkt, gktConfig.cmake and gkt.pc installed;" \
  "consumer built with CMake and pkg-config, values equal gkt table (3 states); CVODE and GSL users link"
