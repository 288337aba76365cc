#!/bin/sh
# The studies behind docs/accuracy.md, "On the committed scenes": `pathcl converge` on the Cornell
# box and the glass-and-mirror box at 128x128, varying one group of knobs at a time, and
# (when no scenes are named) the build options on sky-glass (glass under an environment).
# Each study writes OUT/<scene>/<study>/ (convergence.csv, summary.md and two plots).
# The studies at 8 bounces share one reference (8192 Sobol' spp, rendered by the first
# study and cached there); the bounce study renders its own at 16 bounces, so that it
# measures what cutting paths short costs. About 30 minutes on 2 x86-64 cores with PoCL
# 3.1; run it on an otherwise idle machine, the times are what it compares.
#   tools/accuracy_costs.sh [build-dir] [out-dir] [scenes...]
set -eu
cd "$(dirname "$0")/.."
BUILD=${1:-build}
OUT=${2:-docs/accuracy}
[ $# -gt 2 ] && shift 2 || set --
ALL=$([ $# -eq 0 ] && echo 1 || echo 0)
SCENES=${*:-"cornell-box cornell-box-glass-mirror"}
COMMON="--width 128 --height 128 --max-bounces 8 --seeds 3 --quiet"
LADDER="--spp-ladder 1,2,4,8,16,32,64,128,256"

study() { # scene study-name converge-arguments...
    scene=$1 name=$2
    shift 2
    echo "== $scene: $name" >&2
    # shellcheck disable=SC2086 # COMMON and LADDER are lists of words
    "$BUILD/pathcl" converge "scenes/$scene.gltf" -o "$OUT/$scene/$name" $COMMON "$@"
}

for scene in $SCENES; do
    ref="$OUT/$scene/sampler-strategy/reference.exr"
    study "$scene" sampler-strategy $LADDER --reference-spp 8192 \
        --vary sampler=independent,jittered,multi-jittered,n-rooks,sobol,halton,hammersley \
        --vary strategy=mis,nee,one-sample,bsdf
    study "$scene" max-bounces $LADDER --reference-spp 8192 --vary max-bounces=1,2,3,4,6,8,12,16
    study "$scene" build-options $LADDER --reference "$ref" --vary fast-math=off,on --vary specialization=scene,all
    # An adaptive render takes at least two 16-spp batches: its ladder starts there.
    study "$scene" adaptive --spp-ladder 16,32,64,128,256,512 --reference "$ref" --vary adaptive=off,on
    study "$scene" batch-spp $LADDER --reference "$ref" --vary batch-spp=0,4,16,64
    study "$scene" stratified-bounces $LADDER --reference "$ref" --vary stratified-bounces=0,1,2,8
done
# What specializing saves where the scene uses more: glass, a mirror and an environment.
[ "$ALL" -eq 0 ] || study sky-glass build-options $LADDER --reference-spp 8192 \
    --vary fast-math=off,on --vary specialization=scene,all
