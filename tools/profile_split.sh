#!/bin/sh
# Where pathcl's and Mitsuba 3's time per sample goes, traversal against everything else
# (docs/performance.md), in one command: perf profiles of both renderers on the scenes of
# tools/compare_mitsuba.sh. pathcl is built from a copy of the working tree's tracked
# files in $OUT/src with its two traversal functions out of line (so that perf names
# them; a call per ray costs a little, so pathcl's figures are upper bounds), the venv
# comes from tools/mitsuba_venv.sh, perf from Debian's linux-perf. Arguments go to
# tools/profile_split.py (e.g. --spp 64); SCENES (paths separated by spaces, relative to
# the repository like OUT) replaces the three scenes. Output: ${OUT:-profile-split}.
set -eu
cd "$(dirname "$0")/.."
OUT=${OUT:-profile-split}
. tools/mitsuba_venv.sh
if ! command -v perf >/dev/null; then
    SUDO=""
    [ "$(id -u)" -eq 0 ] || SUDO=sudo
    $SUDO apt-get install -y -q linux-perf
fi
sh tools/install_deps.sh
SRC=$OUT/src
rm -rf "$SRC"
mkdir -p "$SRC"
git ls-files -z | tar --null -T - -cf - | tar -xf - -C "$SRC"
TRAVERSAL=$SRC/kernels/bvh/traversal.cl
sed -i -e 's/^static inline Hit bvh_closest_hit(/static __attribute__((noinline)) Hit bvh_closest_hit(/' \
    -e 's/^static inline float bvh_visibility(/static __attribute__((noinline)) float bvh_visibility(/' "$TRAVERSAL"
if [ "$(grep -c '__attribute__((noinline))' "$TRAVERSAL")" -ne 2 ]; then
    echo "profile_split.sh: $TRAVERSAL: bvh_closest_hit and bvh_visibility not found as expected" >&2
    exit 1
fi
cmake -S "$SRC" -B "$OUT/build" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$OUT/build" --target pathcl >/dev/null
if [ -z "${SCENES:-}" ]; then
    [ -e "$OUT/cornell-box-dense.gltf" ] || python3 tools/make_cornell_box.py --variant dense "$OUT/cornell-box-dense.gltf"
    SCENES="scenes/cornell-box.gltf scenes/cornell-box-glass-mirror.gltf $OUT/cornell-box-dense.gltf"
fi
# shellcheck disable=SC2086 # SCENES is a list of paths
DRJIT_LIBLLVM_PATH=$LLVM "$VENV/bin/python" tools/profile_split.py --pathcl "$OUT/build/pathcl" --out "$OUT" \
    $SCENES "$@"
