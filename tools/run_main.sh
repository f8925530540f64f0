#!/usr/bin/env bash
# The main job: install dependencies, build (Release), and print the elastic hard-sphere
# coefficient table (Sonine orders 1..20, d = 3 and 2, with error estimates).
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/install_dependencies.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DGKT_BUILD_TESTS=OFF
cmake --build build -j"$(nproc)"
build/bin/gkt table tables/scenes/hard_spheres_convergence.toml
