# Sourced by tools/compare_mitsuba.sh when Cycles is compared: makes the venv with Blender's
# bpy module from PyPI (under ${PATHCL_CYCLES_VENV:-$HOME/.cache/pathcl-cycles}; bpy
# 4.5 is built for Python 3.11 only) and installs the X11 and GL client libraries that
# bpy links against even without a display (it renders headless; Debian 12 packages).
# Sets CYCLES_PY (its python, which runs tools/cycles_render.py).
# bpy is pinned so that a figure names the Cycles it measured: 4.5 is the LTS series, with
# the light tree (since 3.5) and per-material emission sampling.
CYCLES_VENV=${PATHCL_CYCLES_VENV:-$HOME/.cache/pathcl-cycles}
CYCLES_PY=$CYCLES_VENV/bin/python
CYCLES_BPY=4.5.15
if [ ! -x "$CYCLES_PY" ]; then
    python3 -m venv "$CYCLES_VENV"
    "$CYCLES_VENV/bin/pip" install -q "bpy==$CYCLES_BPY" numpy OpenEXR
fi
if ! "$CYCLES_PY" -c "import bpy" 2>/dev/null; then
    SUDO=""
    [ "$(id -u)" -eq 0 ] || SUDO=sudo
    export DEBIAN_FRONTEND=noninteractive
    $SUDO apt-get update -q
    $SUDO apt-get install -y -q --no-install-recommends libx11-6 libxrender1 libxfixes3 libxi6 libxkbcommon0 libxext6 \
        libsm6 libice6 libgl1
    "$CYCLES_PY" -c "import bpy"
fi
