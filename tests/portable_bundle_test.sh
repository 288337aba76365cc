#!/bin/sh
# tools/portable_bundle.py, the way pathcl reaches a machine without Debian's packages (a
# GPU node): the bundle's binaries and image module load no library from outside it but
# the system's C and C++ runtimes, OpenImageIO's video and VDB libraries are stubs, and the
# bundled pathcl renders and writes PNG and EXR through the bundled image module and
# OpenImageIO, and plots through the bundled PLplot driver; its bench_light_tree runs.
#   sh tests/portable_bundle_test.sh BUILD_DIR SOURCE_DIR
set -eu
BUILD=$1
SRC=$2
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
B=$WORK/bundle
python3 "$SRC/tools/portable_bundle.py" "$BUILD" "$B"
outside=$(LD_LIBRARY_PATH="$B/lib" ldd "$B/bin/pathcl" "$B/bin/device_tests" "$B/bin/bench_light_tree" \
    "$B/bin/libpathcl_oiio.so" "$B/lib/plplot-drivers/cairo.so" |
    grep "=>" | grep -v "=> $B/lib/" |
    grep -v -E "^\s*(libc|libm|libstdc\+\+|libgcc_s|libpthread|libdl|librt)\.so" || true)
if [ -n "$outside" ]; then
    echo "portable_bundle_test: libraries from outside the bundle:"
    echo "$outside"
    exit 1
fi
for lib in libavcodec.so.59 libopenvdb.so.10.0 libopencv_core.so.406; do
    size=$(stat -c %s "$B/lib/$lib")
    if [ "$size" -gt 100000 ]; then
        echo "portable_bundle_test: $lib is not a stub ($size bytes)"
        exit 1
    fi
done
read -r source_dir binary <"$B/paths.txt"
[ "$source_dir" = "$SRC" ] || { echo "portable_bundle_test: paths.txt names $source_dir, not $SRC"; exit 1; }
[ "$binary" = "$(cd "$BUILD" && pwd)/pathcl" ] || { echo "portable_bundle_test: paths.txt names $binary"; exit 1; }
LD_LIBRARY_PATH="$B/lib" "$B/bin/pathcl" render "$SRC/scenes/textured.gltf" -o "$WORK/t.png" -o "$WORK/t.exr" \
    --width 16 --height 16 --spp 1 --quiet
LD_LIBRARY_PATH="$B/lib" "$B/bin/pathcl" compare "$WORK/t.exr" "$WORK/t.exr" --bitwise >/dev/null
test -s "$WORK/t.png"
# The light tree's build benchmark, which device_check.sh runs from the bundle.
LD_LIBRARY_PATH="$B/lib" "$B/bin/bench_light_tree" --lights 100 --runs 1 >/dev/null
# A plot through the bundled PLplot driver and data.
PLPLOT_DRV_DIR="$B/lib/plplot-drivers" PLPLOT_LIB="$B/share/plplot" LD_LIBRARY_PATH="$B/lib" "$B/bin/pathcl" samples \
    --sampler sobol --spp 16 --pixel 0,0 --dims 0,1 --spectrum -o "$WORK/plot.png"
test -s "$WORK/plot.png"
echo "portable_bundle_test: PASS ($(du -sh "$B" | cut -f1))"
