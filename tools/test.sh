#!/bin/sh
# Installs what is missing, builds, and runs the whole test suite (the README's test
# command; .ci/run calls this): every test in a release build, then the unit tests (the
# hostile corpus included) and the commands end to end (label cli: render, resume, merge,
# converge, info) again in a build with AddressSanitizer and UndefinedBehaviorSanitizer.
# Kernel binaries are cached in build/kernel-cache.
set -eu
cd "$(dirname "$0")/.."
sh tools/install_deps.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release
cmake --build build
export PATHCL_CACHE_DIR="$PWD/build/kernel-cache"
ctest --test-dir build --output-on-failure

cmake -S . -B build-sanitize -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DPATHCL_SANITIZE=ON
cmake --build build-sanitize --target unit_tests cli_tests pathcl
LSAN_OPTIONS="suppressions=$PWD/tools/lsan.supp:print_suppressions=0" UBSAN_OPTIONS=print_stacktrace=1 \
    ctest --test-dir build-sanitize -L 'unit|cli' --output-on-failure
