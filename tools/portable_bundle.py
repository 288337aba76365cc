#!/usr/bin/env python3
"""Copies pathcl and its test binary with every shared library they load into one folder
that runs on another x86-64 Linux machine without Debian's packages (a GPU node, say):

    python3 tools/portable_bundle.py BUILD_DIR OUT_DIR

OUT_DIR/bin holds pathcl, device_tests and bench_light_tree (stripped) with the image
module they load from their own folder (libpathcl_oiio.so, host/image/image_module.h),
OUT_DIR/lib their libraries, the OpenCL ICD loader among them; run them with
LD_LIBRARY_PATH=OUT_DIR/lib (and OCL_ICD_VENDORS pointing at a folder of .icd files where the machine registers none);
tools/device_check.sh does that. glibc, libstdc++ and libgcc stay the machine's own (newer
ones run older binaries).

Debian's OpenImageIO links video, DICOM, RAW, HEIF and OpenVDB libraries that pull in
over 300 MB (ffmpeg, GDAL, ICU, ...); pathcl reads and writes none of those formats. They
are replaced by stub libraries of the same names that define only the symbols their users
import, as functions returning a pointer to zeros (their version strings read as "") and
zeroed data: OpenImageIO loads, registers its plugins and never calls them. The bundle is
about 70 MB. The plots (`converge`, `samples --spectrum`) draw with PLplot's cairo
driver, a plugin PLplot finds by PLPLOT_DRV_DIR, and read its colour maps and fonts from
PLPLOT_LIB: the bundle carries both in OUT_DIR/lib/plplot-drivers and OUT_DIR/share/plplot,
the driver's libraries (cairo, pango) among the others.
"""
import collections
import glob
import os
import re
import shutil
import subprocess
import sys
import tempfile

LIB_DIRS = ["/lib/x86_64-linux-gnu", "/usr/lib/x86_64-linux-gnu"]
# The machine's own: its C library and C++ runtime.
SYSTEM = {"libc.so.6", "libm.so.6", "libstdc++.so.6", "libgcc_s.so.1", "ld-linux-x86-64.so.2", "libpthread.so.0",
          "libdl.so.2", "librt.so.1"}
# OpenImageIO's optional format libraries (and their own dependencies, which then go too).
STUBBED = ["libopencv_core.so.406", "libopencv_imgproc.so.406", "libopencv_videoio.so.406", "libdcmimage.so.17",
           "libdcmimgle.so.17", "libdcmdata.so.17", "liboflog.so.17", "libofstd.so.17", "libavcodec.so.59",
           "libavformat.so.59", "libavutil.so.57", "libswscale.so.6", "libopenvdb.so.10.0", "libheif.so.1",
           "libraw_r.so.20"]
BINARIES = ["pathcl", "tests/device_tests", "bench_light_tree", "libpathcl_oiio.so"]
PLPLOT_DRIVER = "cairo"  # host/plot/plot.cpp draws with its memcairo device


def run(*args):
    return subprocess.run(args, capture_output=True, text=True, check=True).stdout


def find_library(name):
    for d in LIB_DIRS:
        p = os.path.join(d, name)
        if os.path.exists(p):
            return os.path.realpath(p)
    sys.exit(f"portable_bundle: {name}: not found in {', '.join(LIB_DIRS)}")


def needed(path):
    return re.findall(r"\(NEEDED\).*\[(.*)\]", run("readelf", "-d", path))


def dynamic_symbols(path):
    """(name, version, size, type, defined) of each dynamic symbol."""
    rows = []
    for line in run("readelf", "--dyn-syms", "-W", path).splitlines():
        f = line.split()
        if len(f) < 8 or not f[0].endswith(":") or f[0] == "Num:":
            continue
        size, typ, ndx, name = f[2], f[3], f[6], f[7]
        version = None
        m = re.match(r"([^@]+)@+([^ (]+)", name)
        if m:
            name, version = m.group(1), m.group(2)
        size = int(size, 16) if size.startswith("0x") else int(size)
        rows.append((name, version, size, typ, ndx != "UND"))
    return rows


def write_stub(soname, importers, out_dir, work):
    """A library named `soname` defining what `importers` take from the real one."""
    wanted = collections.defaultdict(set)
    for lib in importers:
        for name, version, _, _, defined in dynamic_symbols(lib):
            if not defined:
                wanted[name].add(version)
    source = ["static char zero[256] __attribute__((aligned(64)));"]
    by_version = collections.defaultdict(list)
    stubbed = set()
    for i, (name, version, size, typ, defined) in enumerate(dynamic_symbols(find_library(soname))):
        if not defined or name not in wanted or name in stubbed:
            continue
        stubbed.add(name)
        if typ in ("FUNC", "IFUNC", "NOTYPE"):
            source.append(f'void* s{i}(void) __asm__("{name}");\nvoid* s{i}(void) {{ return zero; }}')
        elif typ == "TLS":
            source.append(f'__thread char s{i}[{max(size, 1)}] __asm__("{name}") __attribute__((aligned(16)));')
        else:
            source.append(f'char s{i}[{max(size, 1)}] __asm__("{name}") __attribute__((aligned(64)));')
        by_version[version].append(name)
    # Every version an importer asks of this library must exist, even with no symbol left.
    versions = set(v for v in by_version if v)
    for name in stubbed:
        versions |= {v for v in wanted[name] if v}
    script = [v + " { global: " + "".join(f'"{n}"; ' for n in by_version.get(v, [])) + "};" for v in sorted(versions)]
    if None in by_version:
        script.append("{ global: " + "".join(f'"{n}"; ' for n in by_version[None]) + "local: *; };")
    c, m = os.path.join(work, soname + ".c"), os.path.join(work, soname + ".map")
    open(c, "w").write("\n".join(source) + "\n")
    open(m, "w").write("\n".join(script) + "\n")
    run("gcc", "-shared", "-fPIC", "-O1", "-o", os.path.join(out_dir, soname), c, "-Wl,-soname," + soname,
        "-Wl,--version-script=" + m)


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__.split("\n\n")[1])
    build, out = sys.argv[1], sys.argv[2]
    bin_dir, lib_dir = os.path.join(out, "bin"), os.path.join(out, "lib")
    shutil.rmtree(out, ignore_errors=True)
    os.makedirs(bin_dir)
    os.makedirs(lib_dir)
    for b in BINARIES:
        shutil.copy(os.path.join(build, b), bin_dir)
    binaries = [os.path.join(bin_dir, os.path.basename(b)) for b in BINARIES]
    run("strip", *binaries)
    drivers = glob.glob(f"/usr/lib/x86_64-linux-gnu/plplot*/drivers/{PLPLOT_DRIVER}.so")
    plplot_data = glob.glob("/usr/share/plplot*/")
    if not drivers or not plplot_data:
        sys.exit("portable_bundle: PLplot's cairo driver or data not found (Debian packages plplot-driver-cairo, "
                 "libplplot-data)")
    driver_dir, data_dir = os.path.join(lib_dir, "plplot-drivers"), os.path.join(out, "share", "plplot")
    os.makedirs(driver_dir)
    os.makedirs(data_dir)
    for f in (drivers[0], drivers[0][:-3] + ".driver_info"):
        shutil.copy(f, driver_dir)
    for f in glob.glob(os.path.join(plplot_data[0], "*.fnt")) + glob.glob(os.path.join(plplot_data[0], "*.pal")):
        shutil.copy(f, data_dir)
    driver = os.path.join(driver_dir, PLPLOT_DRIVER + ".so")
    run("strip", "--strip-unneeded", driver)
    # The libraries the binaries and the driver load, but for the system's own and the
    # stubbed ones.
    copied, todo = [], binaries + [driver]
    while todo:
        for name in needed(todo.pop()):
            if name in SYSTEM or name in STUBBED or name in copied:
                continue
            copied.append(name)
            path = find_library(name)
            shutil.copy(path, os.path.join(lib_dir, name))
            todo.append(path)
    run("strip", "--strip-unneeded", *[os.path.join(lib_dir, n) for n in copied])
    importers = [os.path.join(lib_dir, n) for n in copied]
    with tempfile.TemporaryDirectory() as work:
        for soname in STUBBED:
            write_stub(soname, importers, lib_dir, work)
    # Where the test binary looks for the source tree and pathcl (compiled in).
    cache = open(os.path.join(build, "CMakeCache.txt")).read()
    source_dir = re.search(r"^CMAKE_HOME_DIRECTORY:INTERNAL=(.*)$", cache, re.M).group(1)
    open(os.path.join(out, "paths.txt"), "w").write(f"{source_dir} {os.path.abspath(build)}/pathcl\n")
    size = sum(os.path.getsize(os.path.join(d, f)) for d, _, files in os.walk(out) for f in files)
    print(f"{out}: {len(binaries)} binaries and modules, {len(copied)} libraries, {len(STUBBED)} stubs, {size / 2**20:.1f} MiB")


if __name__ == "__main__":
    main()
