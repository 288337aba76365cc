// The device program's structure: every kernel file includes what it uses, so the order
// in which the tree is embedded never matters. Each file of kernels/ is compiled on its
// own (OpenCL's compile step, no link), once with no optional feature and once with every
// feature, on the test device: a file that uses a name from a file it does not include
// fails here even where the render program, which includes everything, happens to
// compile. Broken variant seen to fail: closure/fresnel_layer.cl without its include of
// util/math.cl (max3).
#include <gtest/gtest.h>

#include "cl/kernel_source.h"
#include "compile/kernel_features.h"
#include "features.h"
#include "support/device_fixture.h"

namespace pathcl::test_kernel_source {
namespace {

// Compiles `file` alone with the feature mask; returns the first error line, or "".
std::string compile_alone(const std::string& file, std::uint32_t features)
{
    ClDevice& dev = test::test_device();
    ProgramSource source;
    source.root = file;
    std::string text = assemble_kernel_source(source);
    cl::Program program(dev.context, text);
    std::string defines = KernelFeatures{features}.define();
    std::string options = base_build_options(dev.info, defines) + " " + defines;
    try {
        program.compile(options.c_str());
    } catch (const cl::Error&) {
        std::string log = program.getBuildInfo<CL_PROGRAM_BUILD_LOG>(dev.device);
        std::size_t at = log.find("error");
        return log.substr(at == std::string::npos ? 0 : at, 300);
    }
    return "";
}

TEST(KernelSource, EveryKernelFileCompilesOnItsOwn)
{
    std::vector<std::string> files = kernel_file_names();
    ASSERT_GT(files.size(), 30u);
    for (const std::string& file : files)
        for (std::uint32_t features : {0u, FEATURE_ALL}) {
            std::string error = compile_alone(file, features);
            EXPECT_EQ(error, "") << file << " with features " << features;
        }
}

} // namespace
} // namespace pathcl::test_kernel_source
