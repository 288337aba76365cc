// The options every kernel program is built with: division and square root correctly
// rounded where the device offers it (NVIDIA's default ones broke the Halton sampler's
// exact radical inverses and the arctangent's ulp bound), and not under --fast-math.
#include <string>

#include <gtest/gtest.h>

#include "cl/cl_runtime.h"
#include "compile/kernel_features.h"

namespace pathcl::test_build_options {
namespace {

bool has(const std::string& options, const std::string& flag)
{
    return options.find(flag) != std::string::npos;
}

TEST(BuildOptions, DivisionAndSquareRootAreCorrectlyRoundedWhereTheDeviceCan)
{
    const std::string exact = "-cl-fp32-correctly-rounded-divide-sqrt";
    DeviceInfo can, cannot;
    can.correctly_rounded_divide_sqrt = true;
    RenderOptions plain, fast;
    fast.fast_math = true;
    KernelFeatures features{FEATURE_AREA_LIGHTS};
    std::string plain_options = program_build_options(features, plain);
    std::string fast_options = program_build_options(features, fast);

    EXPECT_TRUE(has(base_build_options(can, plain_options), exact));
    EXPECT_TRUE(has(base_build_options(can, plain_options), "-cl-std=CL1.2"));
    // A device without it would take the flag as implementation-defined: not passed.
    EXPECT_FALSE(has(base_build_options(cannot, plain_options), exact));
    // --fast-math gives it up with the rest of the exactness.
    EXPECT_TRUE(has(fast_options, kUnsafeMathOption));
    EXPECT_FALSE(has(base_build_options(can, fast_options), exact));
    EXPECT_FALSE(has(base_build_options(can, plain_options), "-cl-fast-relaxed-math"));
}

TEST(BuildOptions, IntelsCpuRuntimeAloneGetsTheKernelWidthHint)
{
    // Its vectorizer miscompiles calls with float3 arguments (docs/devices.md); PoCL and
    // Intel's GPU runtime (another compiler) build the kernels as written.
    DeviceInfo intel_cpu, intel_gpu, pocl;
    intel_cpu.platform = "Intel(R) OpenCL";
    intel_cpu.type = "CPU";
    intel_gpu.platform = "Intel(R) OpenCL Graphics";
    intel_gpu.type = "GPU";
    pocl.platform = "Portable Computing Language";
    pocl.type = "CPU";
    const std::string hint = "-DPATHCL_KERNEL_WIDTH_HINT";
    EXPECT_TRUE(has(base_build_options(intel_cpu, ""), hint));
    EXPECT_FALSE(has(base_build_options(intel_gpu, ""), hint));
    EXPECT_FALSE(has(base_build_options(pocl, ""), hint));
}

} // namespace
} // namespace pathcl::test_build_options
