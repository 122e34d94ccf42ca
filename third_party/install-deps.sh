#!/usr/bin/env bash
# Installs every Debian package pdrt needs. Idempotent: safe to run again.
# Usage (as root on Debian 12): bash third_party/install-deps.sh
set -euo pipefail

PACKAGES=(
  build-essential cmake pkg-config
  libembree-dev embree-tools
  libopenimageio-dev openimageio-tools
  libtinyobjloader-dev
  libassimp-dev
  libosd-dev
  openmpi-bin libopenmpi-dev
  libtbb-dev
  libfftw3-dev
  nlohmann-json3-dev
  libcli11-dev
  libpcg-cpp-dev
  libgtest-dev libgmock-dev
  libbenchmark-dev
  python3 python3-matplotlib
  clang libclang-rt-dev  # the fuzzers (tests/fuzz/): clang with libFuzzer and the sanitizer runtimes
)

missing=()
for p in "${PACKAGES[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#PACKAGES[@]} packages already installed"
  exit 0
fi

SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
