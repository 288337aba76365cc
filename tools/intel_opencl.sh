#!/bin/sh
# Intel's OpenCL CPU runtime from PyPI beside the machine's own OpenCL platforms, for one
# command or one shell (the test suite's second implementation; docs/devices.md):
#
#   sh tools/intel_opencl.sh CMD [ARG...]    runs CMD with both platforms visible
#   eval "$(sh tools/intel_opencl.sh)"       exports that environment into this shell
#
# Installs the wheels intel-opencl-rt and intel-cmplr-lib-rt ($PATHCL_INTEL_OPENCL_VERSION,
# by default the tested 2026.2.0) into a virtual environment under
# ${PATHCL_INTEL_OPENCL_DIR:-$HOME/.cache/pathcl-intel-opencl}, once; writes an ICD folder
# beside it naming the wheel's libintelocl.so and holding a copy of every ICD file in
# /etc/OpenCL/vendors; and sets OCL_ICD_VENDORS to that folder and puts the wheel's lib/
# first on LD_LIBRARY_PATH. The latter serves programs that load OpenImageIO, and with it
# Debian's TBB, before they list OpenCL platforms: libintelocl.so needs the wheel's newer
# TBB and otherwise fails to load, and the ICD loader then leaves the platform out without
# a word (pathcl's own commands list them first; docs/devices.md). Nothing outside the
# cache folder changes.
#
# Without PyPI (or pip) the install fails with one line and exit status 2, as any other
# missing dependency of the test suite does; an interrupted install is never taken for a
# finished one (the environment is moved into place when complete).
set -eu
version=${PATHCL_INTEL_OPENCL_VERSION:-2026.2.0}
root=${PATHCL_INTEL_OPENCL_DIR:-$HOME/.cache/pathcl-intel-opencl}
venv=$root/$version
fail() {
    echo "intel_opencl: $*" >&2
    exit 2
}

if [ ! -e "$venv/installed" ]; then
    command -v python3 >/dev/null || fail "python3 not found (tools/install_deps.sh installs it)"
    echo "intel_opencl: installing Intel's OpenCL CPU runtime $version into $venv" >&2
    mkdir -p "$root"
    rm -rf "$venv.partial"
    python3 -m venv "$venv.partial" >&2 ||
        fail "cannot make a Python virtual environment (Debian's python3-venv; tools/install_deps.sh)"
    "$venv.partial/bin/python" -m pip install -q --disable-pip-version-check "intel-opencl-rt==$version" \
        "intel-cmplr-lib-rt==$version" >&2 || fail "pip could not install intel-opencl-rt $version from PyPI"
    touch "$venv.partial/installed"
    rm -rf "$venv"
    mv "$venv.partial" "$venv"
fi

# The wheel's data files land in lib/ of the environment; found rather than assumed.
lib=$(find "$venv" -name libintelocl.so -print | head -n 1)
[ -n "$lib" ] || fail "no libintelocl.so in $venv (remove it to reinstall)"
libdir=$(dirname "$lib")
icd=$root/icd-$version
mkdir -p "$icd"
rm -f "$icd"/*.icd
for f in /etc/OpenCL/vendors/*.icd; do
    [ -e "$f" ] && cp "$f" "$icd/"
done
echo "$lib" >"$icd/intel-cpu.icd"

OCL_ICD_VENDORS=$icd
LD_LIBRARY_PATH=$libdir${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}
export OCL_ICD_VENDORS LD_LIBRARY_PATH
if [ $# -eq 0 ]; then
    echo "export OCL_ICD_VENDORS='$OCL_ICD_VENDORS' LD_LIBRARY_PATH='$LD_LIBRARY_PATH'"
else
    exec "$@"
fi
