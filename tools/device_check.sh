#!/bin/bash
# Runs pathcl's checks on another machine's OpenCL device (a GPU node) from a bundle made by
# tools/portable_bundle.py, in a checkout of the same tree:
#
#   bash tools/device_check.sh BUNDLE OUT_DIR
#
# Lists the devices, renders the default scene twice (cold and cached build), runs the
# device test suite in parallel shards (one log per shard), and benchmarks the committed
# scenes at 1024x1024 (sobol and independent) and each stage of two of them, the light
# samplers on the many-light scenes of tools/make_many_lights.py (where python3 is found)
# and the light tree's build on the machine's cores. Device 0 is the one tested: where
# NVIDIA's driver is found (libnvidia-opencl.so.1), a private ICD folder naming only it
# makes the GPU device 0 (PATHCL_KEEP_ICD=1 keeps the machine's own). OUT_DIR gets
# check.log, shard*.log (at most 6) and the render, cornell-box.png.
#
# PATHCL_CHECK_OTHER=PATH names another build's pathcl (made on the same build machine, so
# that the bundle's libraries serve it): each scene benchmark then runs it and the
# bundle's pathcl in turn, twice, so that the two compare in interleaved runs.
# PATHCL_CHECK_TEST_SECONDS (default 900) limits each test shard.
set -u
bundle=$(cd "$1" && pwd)
out=$2
mkdir -p "$out"
out=$(cd "$out" && pwd)
cd "$(dirname "$0")/.."
start=$(date +%s)
log() { echo "[$(($(date +%s) - start)) s] $*" | tee -a "$out/check.log"; }
run() {
    "$@" 2>&1 | tee -a "$out/check.log"
    return "${PIPESTATUS[0]}"
}

if [ -z "${PATHCL_KEEP_ICD:-}" ]; then
    for lib in /usr/local/nvidia/lib64 /usr/lib/x86_64-linux-gnu /usr/lib64; do
        if [ -e "$lib/libnvidia-opencl.so.1" ]; then
            mkdir -p /tmp/pathcl-icd
            echo "$lib/libnvidia-opencl.so.1" >/tmp/pathcl-icd/nvidia.icd
            export OCL_ICD_VENDORS=/tmp/pathcl-icd
            break
        fi
    done
fi
export LD_LIBRARY_PATH="$bundle/lib:${LD_LIBRARY_PATH:-}"
export PLPLOT_DRV_DIR="$bundle/lib/plplot-drivers" PLPLOT_LIB="$bundle/share/plplot"
export PATHCL_CACHE_DIR="${TMPDIR:-/tmp}/pathcl-check-cache"
# The test binary names the source tree and pathcl by the build machine's paths.
read -r source_dir binary <"$bundle/paths.txt"
if [ ! -e "$source_dir" ]; then
    mkdir -p "$(dirname "$source_dir")" && ln -s "$PWD" "$source_dir" || { log "cannot link $source_dir here"; exit 2; }
elif [ "$(cd "$source_dir" && pwd -P)" != "$(pwd -P)" ]; then
    log "note: the test binary reads its kernels from $source_dir, not from this checkout"
fi
[ -e "$binary" ] || { mkdir -p "$(dirname "$binary")" && cp "$bundle/bin/pathcl" "$binary"; }
pathcl=$bundle/bin/pathcl

run "$pathcl" devices
log devices
rm -rf "$PATHCL_CACHE_DIR"
for pass in cold cached; do
    png="$out/cornell-box.png"
    [ "$pass" = cached ] && png="${TMPDIR:-/tmp}/pathcl-check-cornell-box.png"
    run timeout -k 5 300 "$pathcl" render scenes/cornell-box.gltf -o "$png"
    log "render ($pass build) exit $?"
done

test_seconds=${PATHCL_CHECK_TEST_SECONDS:-900}
shards=$(($(nproc) / 2))
[ "$shards" -gt 6 ] && shards=6 # at most 8 files in OUT_DIR
[ "$shards" -lt 1 ] && shards=1
pids=""
for k in $(seq 0 $((shards - 1))); do
    GTEST_TOTAL_SHARDS=$shards GTEST_SHARD_INDEX=$k timeout -k 5 "$test_seconds" "$bundle/bin/device_tests" --gtest_brief=1 \
        >"$out/shard$k.log" 2>&1 &
    pids="$pids $!"
done
wait $pids
grep -h "FAILED\|PASSED\|SKIPPED \]" "$out"/shard*.log | tee -a "$out/check.log"
log "device tests ($shards shards)"

other=${PATHCL_CHECK_OTHER:-}
builds=("$pathcl")
[ -n "$other" ] && builds=("$other" "$pathcl" "$other" "$pathcl")
for scene in cornell-box cornell-box-glass-mirror material-spheres textured; do
    for sampler in sobol independent; do
        for build in "${builds[@]}"; do
            log "bench $scene $sampler: $build"
            run timeout -k 5 120 "$build" bench "scenes/$scene.gltf" --width 1024 --height 1024 --spp 64 --runs 3 \
                --sampler "$sampler"
        done
    done
done
for scene in cornell-box material-spheres; do
    for build in "${builds[@]}"; do
        log "stages $scene: $build"
        run timeout -k 5 120 "$build" bench --kernels --width 1024 --height 1024 "scenes/$scene.gltf"
    done
done

# The light samplers where lights are many (docs/accuracy.md, Light samplers): samples per
# second and the relMSE estimate of each, two seeds, interleaved.
lights=${TMPDIR:-/tmp}/pathcl-check-lights
if command -v python3 >/dev/null; then
    mkdir -p "$lights"
    for scene in lamps emissive-mesh near-light; do
        python3 tools/make_many_lights.py "$scene" "$lights/$scene.gltf" >/dev/null || continue
        for seed in 1 2; do
            for sampler in power tree; do
                log "light sampler $sampler, $scene, seed $seed"
                run timeout -k 5 120 "$pathcl" render "$lights/$scene.gltf" -o "$lights/$scene.exr" --width 512 \
                    --height 512 --spp 256 --max-bounces 5 --light-sampler "$sampler" --seed "$seed"
            done
        done
    done
else
    log "no python3: the many-light scenes are not made"
fi
run timeout -k 5 120 "$bundle/bin/bench_light_tree" --runs 5
[ -e "$lights/emissive-mesh.gltf" ] &&
    run timeout -k 5 120 "$bundle/bin/bench_light_tree" "$lights/emissive-mesh.gltf" --runs 9
log done
