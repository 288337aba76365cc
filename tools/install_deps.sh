#!/bin/sh
# Installs what pathcl needs to build and test, from Debian 12 packages, skipping what is
# already there. Run as root (or with sudo available). Idempotent.
set -eu
PACKAGES="build-essential cmake ninja-build pkg-config
  pocl-opencl-icd ocl-icd-opencl-dev opencl-c-headers opencl-clhpp-headers
  libopenimageio-dev libpng-dev libtinygltf-dev libdraco-dev draco nlohmann-json3-dev libglm-dev libcli11-dev libgtest-dev libembree-dev
  libplplot-dev plplot-driver-cairo fonts-dejavu-core clang-format python3 python3-venv"
missing=""
for p in $PACKAGES; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing="$missing $p"
done
if [ -z "$missing" ]; then
    echo "install_deps: all packages present"
    exit 0
fi
echo "install_deps: installing$missing"
SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO=sudo
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -q
# shellcheck disable=SC2086
$SUDO apt-get install -y -q --no-install-recommends $missing
