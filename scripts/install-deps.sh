#!/usr/bin/env bash
# Install what Roller needs from Debian 12 packages, skipping what is present. Idempotent; run as root
# (or with sudo available).
set -euo pipefail

packages=(
  build-essential cmake pkg-config
  petsc-dev slepc-dev libopenmpi-dev openmpi-bin libhdf5-openmpi-dev
  libmetis-dev gmsh libgmsh-dev libyaml-dev liblapack-dev clang-format
  python3 python3-numpy python3-scipy python3-h5py python3-matplotlib
  chromium ffmpeg   # the squeak report's page opened headless (tests/report_page.py), its MP4 (rollerreport.animation)
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi
echo "install-deps: installing ${missing[*]}"
SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO="sudo"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -q
$SUDO apt-get install -y -q --no-install-recommends "${missing[@]}"
