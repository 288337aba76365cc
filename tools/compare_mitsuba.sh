#!/bin/sh
# The speed comparison against Mitsuba 3 (README "Speed"), in one command: makes a venv
# with Mitsuba 3 and Dr.Jit from PyPI (under ${PATHCL_MITSUBA_VENV:-$HOME/.cache/pathcl-mitsuba}),
# installs Debian's libLLVM 19 for Dr.Jit's LLVM backend if missing (LLVM 14 and 15 crash
# it), builds pathcl, writes the million-triangle scene, and runs tools/compare_mitsuba.py
# on the Cornell box, the glass-and-mirror box and the dense box. Arguments go to the
# script (e.g. --runs 5, --spp 64). Output and cached references: ${OUT:-compare-mitsuba}.
set -eu
cd "$(dirname "$0")/.."
VENV=${PATHCL_MITSUBA_VENV:-$HOME/.cache/pathcl-mitsuba}
OUT=${OUT:-compare-mitsuba}
LLVM=/usr/lib/x86_64-linux-gnu/libLLVM-19.so
if [ ! -e "$LLVM" ]; then
    SUDO=""
    [ "$(id -u)" -eq 0 ] || SUDO=sudo
    $SUDO apt-get install -y -q libllvm19
    [ -e "$LLVM" ] || ln -s "$(ls /usr/lib/x86_64-linux-gnu/libLLVM-19.so.* | head -1)" "$LLVM"
fi
if [ ! -x "$VENV/bin/python" ]; then
    python3 -m venv "$VENV"
    "$VENV/bin/pip" install -q mitsuba drjit numpy OpenEXR
fi
sh tools/install_deps.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build --target pathcl >/dev/null
mkdir -p "$OUT"
[ -e "$OUT/cornell-box-dense.gltf" ] || python3 tools/make_cornell_box.py --variant dense "$OUT/cornell-box-dense.gltf"
DRJIT_LIBLLVM_PATH=$LLVM "$VENV/bin/python" tools/compare_mitsuba.py --pathcl build/pathcl --out "$OUT" \
    scenes/cornell-box.gltf scenes/cornell-box-glass-mirror.gltf "$OUT/cornell-box-dense.gltf" "$@"
