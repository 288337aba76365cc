# Sourced by tools/compare_mitsuba.sh and tools/profile_split.sh: makes the venv with
# Mitsuba 3 and Dr.Jit from PyPI (under ${PATHCL_MITSUBA_VENV:-$HOME/.cache/pathcl-mitsuba})
# and installs Debian's libLLVM 19 for Dr.Jit's LLVM backend if missing (LLVM 14 and 15
# crash it). Sets VENV (its python: $VENV/bin/python) and LLVM (for DRJIT_LIBLLVM_PATH).
VENV=${PATHCL_MITSUBA_VENV:-$HOME/.cache/pathcl-mitsuba}
LLVM=/usr/lib/x86_64-linux-gnu/libLLVM-19.so
if [ ! -e "$LLVM" ]; then
    SUDO=""
    [ "$(id -u)" -eq 0 ] || SUDO=sudo
    $SUDO apt-get install -y -q libllvm19
    [ -e "$LLVM" ] || $SUDO ln -s "$(ls /usr/lib/x86_64-linux-gnu/libLLVM-19.so.* | head -1)" "$LLVM"
fi
if [ ! -x "$VENV/bin/python" ]; then
    python3 -m venv "$VENV"
    "$VENV/bin/pip" install -q mitsuba drjit numpy OpenEXR
fi
