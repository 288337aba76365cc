#!/bin/sh
# The speed comparison against Mitsuba 3 (docs/performance.md), in one command: makes the venv
# with Mitsuba 3 and Dr.Jit (tools/mitsuba_venv.sh), builds pathcl, writes the
# million-triangle scene, and runs tools/compare_mitsuba.py on the Cornell box, the
# glass-and-mirror box and the dense box. Arguments go to the script (e.g. --runs 5,
# --spp 64); --cycles (no value here) also makes the bpy venv (tools/cycles_venv.sh) and
# adds Cycles' rows where a scene is Lambertian (not the glass-and-mirror box). Output
# and cached references: ${OUT:-compare-mitsuba}.
set -eu
cd "$(dirname "$0")/.."
OUT=${OUT:-compare-mitsuba}
. tools/mitsuba_venv.sh
for a in "$@"; do
    if [ "$a" = --cycles ]; then
        . tools/cycles_venv.sh
        # --cycles becomes --cycles PYTHON (the loop walks the arguments as they were).
        for b in "$@"; do
            shift
            if [ "$b" = --cycles ]; then set -- "$@" --cycles "$CYCLES_PY"; else set -- "$@" "$b"; fi
        done
        break
    fi
done
sh tools/install_deps.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build --target pathcl >/dev/null
mkdir -p "$OUT"
[ -e "$OUT/cornell-box-dense.gltf" ] || python3 tools/make_cornell_box.py --variant dense "$OUT/cornell-box-dense.gltf"
DRJIT_LIBLLVM_PATH=$LLVM "$VENV/bin/python" tools/compare_mitsuba.py --pathcl build/pathcl --out "$OUT" \
    scenes/cornell-box.gltf scenes/cornell-box-glass-mirror.gltf "$OUT/cornell-box-dense.gltf" "$@"
