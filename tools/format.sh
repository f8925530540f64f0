#!/usr/bin/env bash
# Formats every C++ file of the project, tracked or new (what the CI formatting gate checks).
set -euo pipefail
cd "$(dirname "$0")/.."
{ git ls-files; git ls-files --others --exclude-standard; } | grep -E '\.(cpp|hpp)$' | xargs clang-format -i
