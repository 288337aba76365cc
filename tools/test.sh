#!/bin/sh
# Installs what is missing, builds, and runs the whole test suite (the README's test
# command; .ci/run calls this): every test in a release build on PoCL, the device tests
# that check exact results again on Intel's OpenCL CPU runtime (a second OpenCL
# implementation; docs/devices.md), then the unit tests (the hostile corpus included) and
# the commands end to end (label cli: render, resume, merge, converge, info) again in a
# build with AddressSanitizer and UndefinedBehaviorSanitizer. Kernel binaries are cached
# in build/kernel-cache.
set -eu
cd "$(dirname "$0")/.."
sh tools/install_deps.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release
cmake --build build
export PATHCL_CACHE_DIR="$PWD/build/kernel-cache"
# The PoCL and Intel runs take a test a core at once (at most four): each test is its own
# process with its own scratch directory (named by its pid), the kernel cache stores
# atomically, and much of a test's time is on one core (PoCL's kernel compiles, host-side
# checks). Two at once took those runs from about 510 s to 300 s on two cores
# (docs/testing.md).
jobs=$(getconf _NPROCESSORS_ONLN 2>/dev/null || echo 1)
[ "$jobs" -le 4 ] || jobs=4

# Intel's runtime comes from PyPI into ~/.cache (tools/intel_opencl.sh), once; where PyPI
# cannot be reached the suite fails here, as it does for any other missing dependency.
# `pathcl devices` must list both platforms; PATHCL_PLATFORM then aims each run at one.
pocl="Portable Computing Language"
intel="Intel(R) OpenCL"
devices=$(sh tools/intel_opencl.sh ./build/pathcl devices)
echo "$devices"
for platform in "$pocl" "$intel"; do
    echo "$devices" | grep -qF ": $platform |" || {
        echo "test.sh: no OpenCL device of the platform '$platform'" >&2
        exit 1
    }
done

# PoCL compiles each kernel twice by default: the program's generic work-group function,
# and at the first launch one specialized to its local size. The tests run the generic
# one alone: a test's programs build a third faster from an empty cache (a fresh
# machine's), and the kernels' arithmetic per work-item is the same (docs/testing.md).
export POCL_WORK_GROUP_SPECIALIZATION=0
PATHCL_PLATFORM="$pocl" ctest --test-dir build --output-on-failure -j "$jobs"

# On Intel's runtime: the tests of exact results (traversal, intersection, BSDFs,
# samplers, film, lights, the kernels' own math and the compiler checks) and the
# wavefront integrator's; the statistical image tests run on PoCL only, to keep CI's time.
exact='^(BvhTraversal|SelfIntersection|Robustness|BsdfSampling|BsdfEval|BsdfEnergy|BsdfDelta|BsdfRoughness'
exact="$exact|Samplers|Film|LightSampling|LightTreeSampling|PointLight|SpotLight|SphereLight|DirectionalLight|TextureLookup"
exact="$exact|MaterialInputs|KernelMath|KernelSource|DeviceCompiler|Wavefront|WavefrontTool)\\."
PATHCL_PLATFORM="$intel" sh tools/intel_opencl.sh ctest --test-dir build -L device -R "$exact" --output-on-failure -j "$jobs"

# A textured scene rendered on Intel's runtime with its ICD file alone, without the wheel's
# lib/ on the library path, as where the runtime is installed system-wide: pathcl loads the
# OpenCL implementations before OpenImageIO brings Debian's TBB, older than the one the
# runtime needs, or the platform drops out of the list (docs/devices.md).
(
    library_path=${LD_LIBRARY_PATH-}
    eval "$(sh tools/intel_opencl.sh)"
    out=$(mktemp -d)
    LD_LIBRARY_PATH=$library_path PATHCL_PLATFORM="$intel" ./build/pathcl render scenes/textured.gltf --width 32 \
        --height 32 --spp 1 --quiet -o "$out/textured.exr"
    rm -rf "$out"
)

# -O1 with line tables only (-g1): the sanitizers' reports keep their files and lines, and
# the build takes about half the time it takes at -O2 -g (a command-line source: 17 s
# against 36 s).
cmake -S . -B build-sanitize -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" \
    -DPATHCL_SANITIZE=ON
cmake --build build-sanitize --target unit_tests image_tests cli_tests pathcl tls_probe
export LSAN_OPTIONS="suppressions=$PWD/tools/lsan.supp:print_suppressions=0" UBSAN_OPTIONS=print_stacktrace=1
# unit_tests and image_tests run once each, all their tests in one process (in ctest's working directory): with
# a process a test, their starts under the sanitizers took three quarters of the time
# (219 s against 54 s on two cores). Then ctest runs the command-line tests and the
# hostile corpus, a test a core, and the check that the sanitized programs' default
# options (host/common/sanitizer_options.cpp) keep LeakSanitizer's tracer alive
# (tests/sanitizer/tls_probe.cpp); the checks of the sources and the repository's text
# ran above.
(cd build-sanitize/tests && ./unit_tests --gtest_brief=1 && ./image_tests --gtest_brief=1)
ctest --test-dir build-sanitize -L 'cli|corpus|sanitizer' --output-on-failure -j "$jobs"
