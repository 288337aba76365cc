#!/bin/sh
# Installs what is missing, builds, and renders the default scene (the README's render
# command): scenes/cornell-box.gltf to cornell-box.png and cornell-box.exr.
set -eu
cd "$(dirname "$0")/.."
sh tools/install_deps.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release
cmake --build build --target pathcl
./build/pathcl render scenes/cornell-box.gltf -o cornell-box.exr -o cornell-box.png "$@"
