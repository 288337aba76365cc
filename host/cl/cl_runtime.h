// OpenCL devices and programs: enumerates every platform's devices under one global
// index, and builds the kernel program for a device with the scene's feature defines
// (binaries cached on disk, see program_cache.h).
#pragma once

#include <string>
#include <vector>

#include <CL/opencl.hpp>

#include "cl/kernel_source.h"

namespace pathcl {

struct DeviceInfo {
    int index = 0; // global index across platforms, as --device takes it
    std::string platform, name, type, version, driver;
    unsigned compute_units = 0;
    unsigned long long global_memory = 0;
    unsigned long long max_allocation = 0; // the largest single buffer (CL_DEVICE_MAX_MEM_ALLOC_SIZE)
    bool fp64 = false;
    // CL_FP_CORRECTLY_ROUNDED_DIVIDE_SQRT: the device can divide and take square roots
    // correctly rounded, as IEEE 754 does, when a program asks for it (PoCL on CPUs
    // does either way; NVIDIA's driver only when asked).
    bool correctly_rounded_divide_sqrt = false;
};

std::vector<DeviceInfo> list_devices();

struct PlatformInfo {
    std::string name, vendor, version; // CL_PLATFORM_NAME, _VENDOR, _VERSION
    std::size_t devices = 0;           // of every type
};

// Every OpenCL platform the ICD loader finds; empty when there is none (or no loader
// configuration), which is not an error.
std::vector<PlatformInfo> list_platforms();

// Has the ICD loader load every OpenCL implementation it knows of, as the first listing
// of platforms or devices does. Rendering commands do this before OpenImageIO's
// libraries are loaded (set_image_module_prelude): Debian's TBB comes with them, and
// Intel's CPU runtime, which needs its own newer TBB, fails to load after it and drops
// out of the list without a word (docs/devices.md).
void load_opencl_platforms();

// A device with its context and in-order queue.
struct ClDevice {
    DeviceInfo info;
    cl::Device device;
    cl::Context context;
    cl::CommandQueue queue;
};

// Opens the device with the given global index; throws pathcl::Error if there is none.
ClDevice open_device(int index);

struct ProgramBuild {
    cl::Program program;
    double seconds = 0.0;       // wall time to get a ready program (compile or cache load)
    bool from_cache = false;    // loaded from pathcl's binary cache
    std::string cache_key;      // its key in that cache (host/cl/program_cache.h)
    bool store_pending = false; // compiled with CacheStore::Deferred, not stored yet
};

// When a compiled program goes into pathcl's binary cache. Fetching the binary is not
// free: PoCL compiles every kernel once more to produce it (longer than the build itself:
// docs/performance.md, "Each stage on its own"), so a render defers it until its image
// is written, and a full disk fails the render at its outputs, not in the cache.
enum class CacheStore { AtBuild, Deferred };

// Builds the program assembled from `source` (by default the render program,
// kernels/program.cl) with `options` (the feature define). Compile failures throw
// pathcl::Error naming the first error line of the build log.
ProgramBuild build_program(const ClDevice& dev, const std::string& options, const ProgramSource& source = {},
                           CacheStore store = CacheStore::AtBuild);

// Stores a build's program in pathcl's binary cache if it is pending (compiled, store
// deferred), once. Never throws: a failed store only costs the next run a compile.
void store_pending_program(ProgramBuild& build) noexcept;

// The option `--fast-math` adds to a program's build options.
inline constexpr const char* kUnsafeMathOption = "-cl-unsafe-math-optimizations";

// The options every program is built with on `device`, before the program's own
// `options`: OpenCL C 1.2, division and square root correctly rounded wherever the
// device offers it, unless `options` ask for unsafe math, and the device's workarounds
// (cl/device_workarounds.h).
std::string base_build_options(const DeviceInfo& device, const std::string& options);

} // namespace pathcl
