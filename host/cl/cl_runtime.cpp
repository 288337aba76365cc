#include "cl/cl_runtime.h"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

#include "cl/device_workarounds.h"
#include "cl/program_cache.h"
#include "common/elapsed.h"
#include "common/error.h"

namespace pathcl {
namespace {

std::string device_type_name(cl_device_type t)
{
    if (t & CL_DEVICE_TYPE_GPU)
        return "GPU";
    if (t & CL_DEVICE_TYPE_CPU)
        return "CPU";
    if (t & CL_DEVICE_TYPE_ACCELERATOR)
        return "accelerator";
    return "other";
}

std::string strip_nuls(std::string s)
{
    while (!s.empty() && s.back() == '\0')
        s.pop_back();
    return s;
}

std::string lower(std::string s)
{
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return s;
}

// PATHCL_PLATFORM, when set: only the platforms whose name contains it (ignoring case), as
// if no other were installed, for every command and the test suite alike (on a machine
// with several OpenCL implementations, device 0 is otherwise whichever the ICD loader
// lists first). One that matches no platform is an error, not an empty list.
std::vector<cl::Platform> selected_platforms(const std::vector<cl::Platform>& platforms)
{
    const char* wanted = std::getenv("PATHCL_PLATFORM");
    if (!wanted || !*wanted)
        return platforms;
    std::vector<cl::Platform> out;
    std::string names;
    for (const cl::Platform& p : platforms) {
        std::string name = strip_nuls(p.getInfo<CL_PLATFORM_NAME>());
        if (lower(name).find(lower(wanted)) != std::string::npos)
            out.push_back(p);
        names += (names.empty() ? "" : ", ") + name;
    }
    if (out.empty())
        throw Error(std::string("PATHCL_PLATFORM=") + wanted +
                    " matches no OpenCL platform (there are: " + (names.empty() ? "none" : names) + ")");
    return out;
}

struct Enumerated {
    DeviceInfo info;
    cl::Device device;
};

std::vector<cl::Platform> platforms()
{
    std::vector<cl::Platform> out;
    try {
        cl::Platform::get(&out);
    } catch (const cl::Error&) {
        out.clear(); // no ICD installed or no platform: an empty list, not a crash
    }
    return out;
}

std::vector<cl::Device> devices_of(const cl::Platform& p)
{
    std::vector<cl::Device> devices;
    try {
        p.getDevices(CL_DEVICE_TYPE_ALL, &devices);
    } catch (const cl::Error&) {
        devices.clear(); // a platform without devices reports CL_DEVICE_NOT_FOUND
    }
    return devices;
}

std::vector<Enumerated> enumerate()
{
    std::vector<Enumerated> out;
    for (const cl::Platform& p : selected_platforms(platforms())) {
        for (const cl::Device& d : devices_of(p)) {
            DeviceInfo info;
            info.index = static_cast<int>(out.size());
            info.platform = p.getInfo<CL_PLATFORM_NAME>();
            info.name = d.getInfo<CL_DEVICE_NAME>();
            info.type = device_type_name(d.getInfo<CL_DEVICE_TYPE>());
            info.version = d.getInfo<CL_DEVICE_VERSION>();
            info.driver = d.getInfo<CL_DRIVER_VERSION>();
            info.compute_units = d.getInfo<CL_DEVICE_MAX_COMPUTE_UNITS>();
            info.global_memory = d.getInfo<CL_DEVICE_GLOBAL_MEM_SIZE>();
            info.max_allocation = d.getInfo<CL_DEVICE_MAX_MEM_ALLOC_SIZE>();
            info.fp64 = d.getInfo<CL_DEVICE_EXTENSIONS>().find("cl_khr_fp64") != std::string::npos;
            info.correctly_rounded_divide_sqrt =
                (d.getInfo<CL_DEVICE_SINGLE_FP_CONFIG>() & CL_FP_CORRECTLY_ROUNDED_DIVIDE_SQRT) != 0;
            out.push_back({info, d});
        }
    }
    return out;
}

// The first line of a compiler log that reports an error (else its first line), so the
// CLI's error stays one line.
std::string first_error_line(const std::string& log)
{
    std::istringstream in(log);
    std::string line, first;
    while (std::getline(in, line)) {
        if (first.empty() && !line.empty())
            first = line;
        if (line.find("error") != std::string::npos)
            return line;
    }
    return first.empty() ? "(empty build log)" : first;
}

// Writes a build log to a file in the temporary directory; returns its path.
std::string save_build_log(const std::string& log)
{
    std::filesystem::path path =
        std::filesystem::temp_directory_path() / ("pathcl-build-log-" + std::to_string(::getpid()) + ".txt");
    std::ofstream(path) << log;
    return path.string();
}

} // namespace

std::vector<PlatformInfo> list_platforms()
{
    std::vector<PlatformInfo> out;
    for (const cl::Platform& p : platforms())
        out.push_back({strip_nuls(p.getInfo<CL_PLATFORM_NAME>()), strip_nuls(p.getInfo<CL_PLATFORM_VENDOR>()),
                       strip_nuls(p.getInfo<CL_PLATFORM_VERSION>()), devices_of(p).size()});
    return out;
}

void load_opencl_platforms()
{
    (void)platforms();
}

std::vector<DeviceInfo> list_devices()
{
    std::vector<DeviceInfo> out;
    for (const Enumerated& e : enumerate())
        out.push_back(e.info);
    return out;
}

ClDevice open_device(int index)
{
    std::vector<Enumerated> all = enumerate();
    if (all.empty())
        throw Error("no OpenCL device found (install an OpenCL driver, e.g. pocl-opencl-icd)");
    if (index < 0 || index >= static_cast<int>(all.size()))
        throw ParameterError("device", "there is no device " + std::to_string(index) + " (" +
                                           std::to_string(all.size()) + " found)");
    ClDevice dev;
    dev.info = all[static_cast<std::size_t>(index)].info;
    dev.device = all[static_cast<std::size_t>(index)].device;
    try {
        dev.context = cl::Context(dev.device);
        dev.queue = cl::CommandQueue(dev.context, dev.device);
    } catch (const cl::Error& e) {
        throw Error("device " + std::to_string(index) + " (" + strip_nuls(dev.info.name) +
                    "): cannot create a context: " + e.what() + " " + std::to_string(e.err()));
    }
    return dev;
}

std::string base_build_options(const DeviceInfo& device, const std::string& options)
{
    // No -cl-fast-relaxed-math: it lets the compiler drop NaN checks and break the
    // compensated film sums. Division and square root correctly rounded, so that every
    // device computes the same floats: OpenCL allows 2.5 ulps for a float division and 3
    // for a square root by default, and with NVIDIA's default ones the Halton sampler's
    // radical inverses were no longer exact, the environment's arctangent was 3.4 ulps
    // off, and a coated glass's pdf missed its double-precision reference by 0.25 %. It
    // costs NVIDIA's H200 a quarter to a third of its samples per second (docs/gpu.md);
    // PoCL on CPUs divides correctly rounded either way. --fast-math gives it up.
    bool exact = device.correctly_rounded_divide_sqrt && options.find(kUnsafeMathOption) == std::string::npos;
    return std::string("-cl-std=CL1.2") + (exact ? " -cl-fp32-correctly-rounded-divide-sqrt" : "") +
           workaround_options(device);
}

ProgramBuild build_program(const ClDevice& dev, const std::string& options, const ProgramSource& program_source,
                           CacheStore store)
{
    auto start = std::chrono::steady_clock::now();
    std::string source = assemble_kernel_source(program_source);
    std::string full_options = base_build_options(dev.info, options) + " " + options;
    std::string identity = dev.info.platform + '|' + dev.info.name + '|' + dev.info.driver + '|' + dev.info.version;
    std::string key = program_cache_key(identity, full_options, source);

    ProgramBuild result;
    result.cache_key = key;
    if (auto binary = program_source.use_cache ? program_cache_load(key) : std::nullopt) {
        try {
            cl::Program::Binaries bins{*binary};
            cl::Program program(dev.context, {dev.device}, bins);
            program.build({dev.device}, full_options.c_str());
            result.program = program;
            result.from_cache = true;
        } catch (const cl::Error&) {
            // A stale or foreign binary: fall through to a fresh compile.
        }
    }
    if (!result.from_cache) {
        cl::Program program(dev.context, source);
        // An uncached build is for a cold compile time: a define no code reads makes the
        // driver's own cache (PoCL keeps one) miss too.
        std::string build_options = full_options;
        if (!program_source.use_cache)
            build_options += " -DPATHCL_UNCACHED_BUILD=" +
                             std::to_string(std::chrono::steady_clock::now().time_since_epoch().count());
        try {
            program.build({dev.device}, build_options.c_str());
        } catch (const cl::Error&) {
            std::string log = program.getBuildInfo<CL_PROGRAM_BUILD_LOG>(dev.device);
            throw Error("kernel build failed on " + strip_nuls(dev.info.name) + ": " + first_error_line(log) +
                        " (full build log: " + save_build_log(log) + ")");
        }
        result.program = program;
        result.store_pending = program_source.use_cache;
        if (store == CacheStore::AtBuild)
            store_pending_program(result);
    }
    result.seconds = seconds_since(start);
    return result;
}

void store_pending_program(ProgramBuild& build) noexcept
{
    if (!build.store_pending)
        return;
    build.store_pending = false;
    try {
        auto binaries = build.program.getInfo<CL_PROGRAM_BINARIES>();
        if (binaries.size() == 1)
            program_cache_store(build.cache_key, binaries[0]);
    } catch (...) {
        // Some drivers cannot return binaries (cl::Error), or memory ran out; caching is
        // only an optimization.
    }
}

} // namespace pathcl
