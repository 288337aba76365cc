#!/bin/sh
# Where the megakernel's and the wavefront's time per sample goes, stage by stage: perf
# profiles (cpu-clock, 4 kHz) of `pathcl bench` with each integrator on the Cornell box and
# the dense box (tools/make_cornell_box.py --variant dense), the wavefront with its shading
# in eight lanes and in one. pathcl is built from a copy of the working tree's tracked
# files in $OUT/src with the two traversal functions out of line, as tools/profile_split.sh
# does, so that perf tells traversal from the rest (a call per ray costs a little). Prints
# nanoseconds of CPU time per sample (both cores' together) per stage, then the renders'
# samples per second from interleaved `pathcl bench` runs of the unmodified build in
# ${BUILD:-build}. Output: ${OUT:-wavefront-split}. 256x256, 16 spp, 7 bounces.
set -eu
cd "$(dirname "$0")/.."
OUT=${OUT:-wavefront-split}
BUILD=${BUILD:-build}
ROUNDS=${ROUNDS:-2}
if ! command -v perf >/dev/null; then
    SUDO=""
    [ "$(id -u)" -eq 0 ] || SUDO=sudo
    $SUDO apt-get install -y -q linux-perf
fi
SRC=$OUT/src
rm -rf "$SRC"
mkdir -p "$SRC"
git ls-files -z | tar --null -T - -cf - | tar -xf - -C "$SRC"
TRAVERSAL=$SRC/kernels/bvh/traversal.cl
sed -i -e 's/^static inline Hit bvh_closest_hit(/static __attribute__((noinline)) Hit bvh_closest_hit(/' \
    -e 's/^static inline float bvh_visibility(/static __attribute__((noinline)) float bvh_visibility(/' "$TRAVERSAL"
if [ "$(grep -c '__attribute__((noinline))' "$TRAVERSAL")" -ne 2 ]; then
    echo "wavefront_split.sh: $TRAVERSAL: bvh_closest_hit and bvh_visibility not found as expected" >&2
    exit 1
fi
cmake -S "$SRC" -B "$OUT/build" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$OUT/build" --target pathcl >/dev/null
cmake --build "$BUILD" --target pathcl >/dev/null
DENSE=$OUT/cornell-box-dense.gltf
[ -e "$DENSE" ] || python3 tools/make_cornell_box.py --variant dense "$DENSE"
export PATHCL_CACHE_DIR="$OUT/kernel-cache"
PIXELS=65536
SPP=16

# flags for `pathcl bench` of variant $1
variant_flags() {
    case $1 in
    megakernel) echo "--integrator megakernel" ;;
    wavefront-8) echo "--integrator wavefront --wavefront-lanes 8" ;;
    wavefront-1) echo "--integrator wavefront --wavefront-lanes 1" ;;
    esac
}

echo "CPU nanoseconds per sample by stage (both cores together; perf cpu-clock at 4 kHz):"
echo "| scene | integrator | traversal | extend | shade | shadow | camera, start, film | megakernel | all but traversal |"
echo "|---|---|---|---|---|---|---|---|---|"
for scene in scenes/cornell-box.gltf "$DENSE"; do
    name=$(basename "$scene" .gltf)
    runs=5
    [ "$scene" = "$DENSE" ] && runs=3
    for v in megakernel wavefront-8 wavefront-1; do
        flags=$(variant_flags $v)
        # shellcheck disable=SC2086
        "$OUT/build/pathcl" bench "$scene" --max-bounces 7 --runs 1 $flags >/dev/null 2>&1 # kernels compiled
        # shellcheck disable=SC2086
        perf record -q -F 4000 -e cpu-clock -o "$OUT/$name-$v.data" \
            "$OUT/build/pathcl" bench "$scene" --max-bounces 7 --runs $runs $flags >/dev/null 2>&1
        samples=$(((runs + 1) * PIXELS * SPP)) # the warm-up render and the timed ones
        perf report -i "$OUT/$name-$v.data" --sort sym --stdio -n 2>/dev/null | grep -v '^#' |
            awk -v scene="$name" -v v="$v" -v samples="$samples" '
            /bvh_closest_hit|bvh_visibility/ {trav += $2; next}
            /_pocl_kernel_wavefront_extend/ {ext += $2; next}
            /_pocl_kernel_wavefront_shade/ {shade += $2; next}
            /_pocl_kernel_wavefront_shadow/ {shd += $2; next}
            /_pocl_kernel_trace_paths/ {mega += $2; next}
            /camera_rays|wavefront_start|wavefront_film|sampler_value|permute_element/ {misc += $2; next}
            END {
                ns = 1e9 / 4000 / samples
                printf "| %s | %s | %.1f | %.1f | %.1f | %.1f | %.1f | %.1f | %.1f |\n", scene, v, trav * ns,
                       ext * ns, shade * ns, shd * ns, misc * ns, mega * ns, (ext + shade + shd + misc + mega) * ns
            }'
    done
done

echo
echo "Renders (\`pathcl bench SCENE --max-bounces 7\`, unmodified build, $ROUNDS interleaved rounds), Msamples/s min / median / max:"
for scene in scenes/cornell-box.gltf "$DENSE"; do
    for r in $(seq 1 "$ROUNDS"); do
        for v in megakernel wavefront-8 wavefront-1; do
            # shellcheck disable=SC2086
            "$BUILD/pathcl" bench "$scene" --max-bounces 7 --runs 3 $(variant_flags $v) 2>/dev/null | tail -1 |
                sed -n "s|.*samples/s min \([^ ]*\) median \([^ ]*\) max \([^ ]*\) .*|$(basename "$scene" .gltf) round $r $v: \1 \2 \3|p"
        done
    done
done
