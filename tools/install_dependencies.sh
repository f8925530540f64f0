#!/usr/bin/env bash
# Installs gkt's build and test dependencies from Debian packages (Debian 12 "bookworm").
# Skips apt-get entirely when every package is already installed.
set -euo pipefail
packages=(
  build-essential cmake pkg-config python3   # python3: tools/check_layers.py
  libflint-dev libgmp-dev libmpfr-dev   # exact arithmetic (FLINT fmpq/fmpq_poly/fmpq_mat, MPFR rounding)
  libeigen3-dev libgsl-dev              # floating-point linear algebra; GSL ODEs (viscoelastic contact), RNG (Monte Carlo checks)
  libsundials-dev                       # CVODE: time evolution of the cooling gas
  libtomlplusplus-dev libcli11-dev nlohmann-json3-dev   # scenes, command line, JSON output
  libgtest-dev libbenchmark-dev         # tests and benchmarks
  gfortran python3                      # the Fortran module over the C API and its example (GKT_BUILD_FORTRAN); its check against gkt table
  python3-dev python3-pybind11 python3-numpy python3-pytest   # the Python module (GKT_BUILD_PYTHON) and its tests
  jupyter-nbconvert python3-nbclient python3-ipykernel python3-matplotlib   # executed notebooks (tools/run_notebooks.sh)
  clang-14 libclang-rt-14-dev           # libFuzzer targets of tests/fuzz (tools/fuzz.sh)
  doxygen                               # API reference from the headers, checked without warnings (tools/run_doxygen.sh)
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]} == 0)); then
  echo "install_dependencies: all ${#packages[@]} packages present"
  exit 0
fi
sudo_cmd=()
if [[ $(id -u) -ne 0 ]]; then sudo_cmd=(sudo); fi
echo "install_dependencies: installing ${missing[*]}"
"${sudo_cmd[@]}" apt-get update -qq
DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
