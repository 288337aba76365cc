#!/bin/bash
# Runs pathcl's checks on another machine's OpenCL device (a GPU node) from a bundle made by
# tools/portable_bundle.py, in a checkout of the same tree:
#
#   bash tools/device_check.sh BUNDLE OUT_DIR
#
# Lists the devices, renders the default scene twice (cold and cached build), runs the
# device test suite in parallel shards (one log per shard), and benchmarks the committed
# scenes at 1024x1024 (sobol and independent) and each stage of two of them. Device 0 is
# the one tested: where NVIDIA's driver is found (libnvidia-opencl.so.1), a private ICD
# folder naming only it makes the GPU device 0 (PATHCL_KEEP_ICD=1 keeps the machine's
# own). OUT_DIR gets check.log, shard*.log (at most 6) and the render, cornell-box.png.
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

shards=$(($(nproc) / 2))
[ "$shards" -gt 6 ] && shards=6 # at most 8 files in OUT_DIR
[ "$shards" -lt 1 ] && shards=1
pids=""
for k in $(seq 0 $((shards - 1))); do
    GTEST_TOTAL_SHARDS=$shards GTEST_SHARD_INDEX=$k timeout -k 5 900 "$bundle/bin/device_tests" --gtest_brief=1 \
        >"$out/shard$k.log" 2>&1 &
    pids="$pids $!"
done
wait $pids
grep -h "FAILED\|PASSED\|SKIPPED \]" "$out"/shard*.log | tee -a "$out/check.log"
log "device tests ($shards shards)"

for scene in cornell-box cornell-box-glass-mirror material-spheres textured; do
    for sampler in sobol independent; do
        run timeout -k 5 120 "$pathcl" bench "scenes/$scene.gltf" --width 1024 --height 1024 --spp 64 --runs 3 \
            --sampler "$sampler"
    done
done
for scene in cornell-box material-spheres; do
    run timeout -k 5 120 "$pathcl" bench --kernels --width 1024 --height 1024 "scenes/$scene.gltf"
done
log done
