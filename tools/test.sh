#!/bin/sh
# Installs what is missing, builds, and runs the whole test suite (the README's test
# command; .ci/run calls this). Kernel binaries are cached in build/kernel-cache.
set -eu
cd "$(dirname "$0")/.."
sh tools/install_deps.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release
cmake --build build
export PATHCL_CACHE_DIR="$PWD/build/kernel-cache"
ctest --test-dir build --output-on-failure
