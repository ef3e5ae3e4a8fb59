#!/usr/bin/env bash
# Installs newtop's build and test dependencies from Debian's packages: GCC and clang (with the
# sanitizer runtimes of libclang-rt-14-dev and llvm's llvm-symbolizer for readable reports).
# Usage: scripts/install-deps.sh   (as root, or with sudo available)
set -euo pipefail
packages=(
  build-essential cmake ninja-build pkg-config clang-format
  libeigen3-dev libboost-dev libboost-math-dev
  libtomlplusplus-dev nlohmann-json3-dev libcli11-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  libomp-dev
  libhdf5-dev libopenmpi-dev openmpi-bin
  # pictures (python/newtop) and the 3D viewer (three.js embedded by the build; Chromium for its test)
  python3 python3-numpy python3-matplotlib python3-pil python3-pytest libjs-three chromium
  # the Python module (python/src)
  pybind11-dev python3-dev
  # HDF5 output of newtop sweep, and its reader for the tests
  python3-h5py
  # clang for the sanitizer build of scripts/test.sh
  clang libclang-rt-14-dev llvm
)
sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then sudo_cmd=(sudo); fi
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  export DEBIAN_FRONTEND=noninteractive
  "${sudo_cmd[@]}" apt-get update -qq
  "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
