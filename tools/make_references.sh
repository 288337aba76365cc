#!/bin/sh
# Regenerates the committed reference images the render tests compare against. Run after
# a change that is meant to change the images (and say why in the commit).
#   tools/make_references.sh [build-dir]
set -eu
cd "$(dirname "$0")/.."
BUILD=${1:-build}
"$BUILD/pathcl" render scenes/cornell-box.gltf -o tests/references/cornell-box-64.exr \
    --width 64 --height 64 --spp 8192 --max-bounces 8 --seed 12345
