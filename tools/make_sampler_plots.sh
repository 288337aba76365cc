#!/bin/sh
# Regenerates the sample-visualizer PNGs docs/cameras-and-samplers.md shows (docs/samplers/).
#   tools/make_sampler_plots.sh [build-dir]
set -eu
cd "$(dirname "$0")/.."
BUILD=${1:-build}
OUT=docs/samplers
mkdir -p "$OUT"
"$BUILD/pathcl" samples --sampler independent --spp 64 --spectrum -o "$OUT/independent-64.png"
"$BUILD/pathcl" samples --sampler multi-jittered --spp 64 --spectrum -o "$OUT/multi-jittered-64.png"
"$BUILD/pathcl" samples --sampler sobol --spp 64 --spectrum -o "$OUT/sobol-64.png"
# Two 1D decisions of one bounce (technique coin, dim 4; BSDF, dim 9): padding.
"$BUILD/pathcl" samples --sampler sobol --spp 64 --dims 4,9 -o "$OUT/sobol-64-dims-4-9.png"
