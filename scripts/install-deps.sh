#!/usr/bin/env bash
# Installs the Debian packages mfwave needs. Safe to re-run: packages already present are skipped.
# Uses sudo only when not running as root.
set -euo pipefail

packages=(
  build-essential cmake ninja-build git pkg-config
  libsundials-dev libeigen3-dev libsuitesparse-dev libfftw3-dev libvtk9-dev
  libgtest-dev libbenchmark-dev libtomlplusplus-dev libcli11-dev nlohmann-json3-dev
  libx11-dev xvfb xauth python3-matplotlib python3-numpy
  clang libclang-rt-14-dev libomp-dev
  libopenmpi-dev openmpi-bin
  dpkg-dev file  # CPack's Debian package: dpkg-shlibdeps finds the programs' dependencies (scripts/check-install.sh)
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages already installed"
  exit 0
fi

if [ "$(id -u)" -eq 0 ]; then
  run_as_root() { "$@"; }
else
  run_as_root() { sudo "$@"; }
fi

echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
run_as_root apt-get update -qq
run_as_root apt-get install -y -qq --no-install-recommends "${missing[@]}"
