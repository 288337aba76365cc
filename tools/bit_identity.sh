#!/bin/sh
# Bit-identity check for refactors that must not change a single pixel: renders every
# committed scene (and the option variants that reach the rest of the kernel code:
# samplers, strategies, bounce limits, the light tree, thin lens, environments, single
# scattering, odd image sizes, the ray log and the sample visualizer) with the pathcl
# built from BASE and with the one built from the working tree, and compares the pixel
# data bit for bit (`pathcl compare --bitwise`; ray logs byte for byte).
#
#   sh tools/bit_identity.sh [BASE]      BASE: a git revision (default HEAD)
#
# PATHCL_BIT_NEW_OPTIONS adds render options to the working tree's side only: a new option
# whose one setting must reproduce BASE's default (PATHCL_BIT_NEW_OPTIONS="--triangle-sampling
# area" against a BASE from before that option).
#
# BASE is checked out with `git worktree` and built once per commit under
# ${PATHCL_BIT_DIR:-/tmp/pathcl-bit-identity}; the working tree is built in build/.
# Prints one line per case and exits 1 if any case differs.
set -eu
cd "$(dirname "$0")/.."
ROOT=$PWD
BASE_REV=${1:-HEAD}
WORK=${PATHCL_BIT_DIR:-/tmp/pathcl-bit-identity}
SHA=$(git rev-parse "$BASE_REV^{commit}")
BASE_SRC=$WORK/src-$SHA
BASE_BUILD=$WORK/build-$SHA
OUT=$WORK/out
mkdir -p "$WORK"

if [ ! -x "$BASE_BUILD/pathcl" ]; then
    git worktree prune
    [ -d "$BASE_SRC" ] || git worktree add --detach "$BASE_SRC" "$SHA" >/dev/null 2>&1
    cmake -S "$BASE_SRC" -B "$BASE_BUILD" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
    cmake --build "$BASE_BUILD" --target pathcl >/dev/null
fi
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build --target pathcl >/dev/null
OLD=$BASE_BUILD/pathcl
NEW=$ROOT/build/pathcl
# Each side keeps its own kernel cache, so neither can hand the other a binary.
export POCL_KERNEL_CACHE=0

rm -rf "$OUT"
mkdir -p "$OUT/old" "$OUT/new"
failed=0
cases=0

# render NAME SCENE [pathcl render options...]
render() {
    name=$1
    scene=$2
    shift 2
    cases=$((cases + 1))
    size="--width 48 --height 40"
    case "$*" in *--width*) size="" ;; esac
    spp="--spp 8"
    case "$*" in *--spp*) spp="" ;; esac
    for side in old new; do
        bin=$OLD
        extra=""
        [ $side = new ] && bin=$NEW && extra=${PATHCL_BIT_NEW_OPTIONS:-}
        # shellcheck disable=SC2086
        PATHCL_CACHE_DIR=$WORK/cache-$side "$bin" render "$ROOT/scenes/$scene.gltf" -o "$OUT/$side/$name.exr" \
            $size $spp "$@" $extra >/dev/null
    done
    if "$NEW" compare --bitwise "$OUT/old/$name.exr" "$OUT/new/$name.exr" >"$OUT/$name.txt"; then
        echo "identical  $name"
    else
        echo "DIFFERENT  $name: $(head -1 "$OUT/$name.txt")"
        failed=$((failed + 1))
    fi
}

# samples NAME [pathcl samples options...]: the visualizer's PNG, pixel for pixel
samples() {
    name=$1
    shift
    cases=$((cases + 1))
    PATHCL_CACHE_DIR=$WORK/cache-old "$OLD" samples -o "$OUT/old/$name.png" "$@" >/dev/null
    PATHCL_CACHE_DIR=$WORK/cache-new "$NEW" samples -o "$OUT/new/$name.png" "$@" >/dev/null
    if cmp -s "$OUT/old/$name.png" "$OUT/new/$name.png"; then
        echo "identical  $name"
    else
        echo "DIFFERENT  $name"
        failed=$((failed + 1))
    fi
}

for gltf in scenes/*.gltf; do
    s=$(basename "$gltf" .gltf)
    render "$s" "$s"
    render "$s-independent-nee" "$s" --sampler independent --strategy nee
    render "$s-one-sample" "$s" --strategy one-sample --seed 3
    render "$s-bsdf" "$s" --strategy bsdf --max-bounces 3
done
for sampler in independent jittered multi-jittered n-rooks sobol halton hammersley; do
    render "cornell-box-$sampler" cornell-box --sampler "$sampler" --spp 9
done
for b in 0 1 2; do
    render "cornell-box-bounces-$b" cornell-box --max-bounces "$b"
done
render cornell-box-odd-size cornell-box --width 37 --height 23 --seed 11
render cornell-box-thin-lens cornell-box --aperture 0.02 --focus-distance 1.0
render cornell-box-camera-overrides cornell-box --fov 30 --look-from 0.3,0.3,1.2 --look-at 0.27,0.27,0 --up 0,1,0.1
render cornell-box-background cornell-box --background 0.3,0.4,0.5 --strategy mis
render cornell-box-glass-mirror-single-scattering cornell-box-glass-mirror --single-scattering
render material-spheres-single-scattering material-spheres --single-scattering --sampler halton
render sky-spheres-rotated sky-spheres --env-rotation 30 --env-strength 0.7
render textured-long textured --max-bounces 12 --spp 16 --sampler multi-jittered
render cornell-box-batches cornell-box --spp 24 --batch-spp 8 --seed 3
# The light tree's code (the committed scenes take the power table by default).
render cornell-box-features-tree cornell-box-features --light-sampler tree --max-bounces 6
render cornell-box-sphere-tree cornell-box-sphere --light-sampler tree --strategy one-sample
render sky-spheres-tree sky-spheres --light-sampler tree

# The ray log of a thin-lens render.
cases=$((cases + 1))
for side in old new; do
    bin=$OLD
    [ $side = new ] && bin=$NEW
    PATHCL_CACHE_DIR=$WORK/cache-$side "$bin" render scenes/cornell-box.gltf -o "$OUT/$side/rays.exr" \
        --width 32 --height 32 --spp 4 --aperture 0.02 --focus-distance 1.0 --ray-log "$OUT/$side/rays.ply" >/dev/null
done
if cmp -s "$OUT/old/rays.ply" "$OUT/new/rays.ply"; then
    echo "identical  ray-log"
else
    echo "DIFFERENT  ray-log"
    failed=$((failed + 1))
fi

for sampler in independent jittered multi-jittered n-rooks sobol halton hammersley; do
    samples "samples-$sampler" --sampler "$sampler" --spp 64 --pixel 3,5
done
samples samples-sobol-spectrum --sampler sobol --spp 64 --spectrum
samples samples-halton-dims --sampler halton --spp 32 --dims 4,9

echo "bit identity against $(git rev-parse --short "$SHA"): $((cases - failed)) of $cases cases identical"
[ "$failed" -eq 0 ]
