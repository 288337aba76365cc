#!/bin/sh
# Regenerates the committed reference images the render tests compare against. Run after
# a change that is meant to change the images (and say why in the commit). Instanced
# meshes are rendered as copies (--copy-instances): the one-level BVH draws the reference
# the two-level one is tested against.
#   tools/make_references.sh [build-dir] [scene names...]   (default: all)
set -eu
cd "$(dirname "$0")/.."
BUILD=${1:-build}
[ $# -gt 0 ] && shift
SCENES=${*:-"cornell-box cornell-box-point cornell-box-sphere cornell-box-spot cornell-box-rect-spot cornell-box-directional sky-spheres cornell-box-glass-mirror cornell-box-features cornell-box-instanced material-spheres textured"}
for scene in $SCENES; do
    "$BUILD/pathcl" render "scenes/$scene.gltf" -o "tests/references/$scene-64.exr" \
        --width 64 --height 64 --spp 8192 --max-bounces 8 --seed 12345 --sampler independent --copy-instances
done
