#include "support/device_fixture.h"

#include <fstream>
#include <sstream>

#include "common/error.h"
#include "compile/kernel_features.h"

namespace pathcl::test {

ClDevice& test_device()
{
    static ClDevice dev = open_device(0);
    return dev;
}

std::string read_text_file(const std::string& path)
{
    std::ifstream f(path);
    if (!f)
        throw Error(path + ": cannot open");
    std::stringstream ss;
    ss << f.rdbuf();
    return ss.str();
}

cl::Program build_test_program(const std::string& file, std::uint32_t features, const std::vector<KernelPatch>& patches,
                               const std::string& extra_options)
{
    ProgramSource source;
    source.root = "tests/kernels/" + file;
    source.text = read_text_file(std::string(PATHCL_SOURCE_DIR) + "/" + source.root);
    source.patches = patches;
    std::string options = KernelFeatures{features}.define();
    if (!extra_options.empty())
        options += " " + extra_options;
    return build_program(test_device(), options, source).program;
}

std::vector<pcl_float4> sample_lights_on_device(const cl::Program& program, const SceneArrays& arrays, glm::vec3 ref,
                                                std::uint32_t seed, std::size_t n, std::vector<pcl_float4>* radiance)
{
    ClDevice& dev = test_device();
    DeviceArrays a = upload_arrays(dev, arrays, 1);
    cl::Buffer out(dev.context, CL_MEM_WRITE_ONLY, n * sizeof(pcl_float4));
    cl::Buffer radiance_out(dev.context, CL_MEM_WRITE_ONLY, n * sizeof(pcl_float4));
    cl::Kernel k(program, "test_light_sample");
    bind_kernel(k, a, static_cast<cl_uint>(arrays.lights.size()), pcl_float4{ref.x, ref.y, ref.z, 0.0f}, seed, out,
                radiance_out);
    dev.queue.enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(n));
    if (radiance)
        *radiance = read_back<pcl_float4>(radiance_out, n);
    return read_back<pcl_float4>(out, n);
}

} // namespace pathcl::test
