#include "support/device_fixture.h"

#include <fstream>
#include <sstream>

#include "common/error.h"

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

cl::Program build_test_program(const std::string& file, const std::string& defines)
{
    std::string src = read_text_file(std::string(PATHCL_SOURCE_DIR) + "/tests/kernels/" + file);
    return build_program(test_device(), defines, {src}).program;
}

std::vector<pcl_float4> sample_lights_on_device(const cl::Program& program, const std::vector<Light>& lights,
                                                const EnvironmentMap* env, glm::vec3 ref, std::uint32_t seed,
                                                std::size_t n, std::vector<pcl_float4>* radiance,
                                                const TextureData* textures)
{
    ClDevice& dev = test_device();
    auto buffer = [&](const void* data, std::size_t bytes) {
        static const float zero[4] = {0, 0, 0, 0}; // kernels need a valid buffer even when unused
        return bytes ? cl::Buffer(dev.context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, bytes, const_cast<void*>(data))
                     : cl::Buffer(dev.context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, sizeof zero,
                                  const_cast<float*>(zero));
    };
    cl::Buffer lb = buffer(lights.data(), lights.size() * sizeof(Light));
    cl::Buffer env_texels = buffer(env ? env->texels.data() : nullptr, env ? env->texels.size() * sizeof(pcl_float4) : 0);
    cl::Buffer marginal = buffer(env ? env->marginal_cdf.data() : nullptr, env ? env->marginal_cdf.size() * sizeof(float) : 0);
    cl::Buffer conditional =
        buffer(env ? env->conditional_cdf.data() : nullptr, env ? env->conditional_cdf.size() * sizeof(float) : 0);
    const TextureData none;
    const TextureData& t = textures ? *textures : none;
    cl::Buffer texels = buffer(t.texels.data(), t.texels.size() * sizeof(pcl_uint));
    cl::Buffer images = buffer(t.images.data(), t.images.size() * sizeof(TextureImage));
    cl::Buffer views = buffer(t.views.data(), t.views.size() * sizeof(TextureView));
    cl::Buffer texcoords = buffer(t.texcoords.data(), t.texcoords.size() * sizeof(TriangleTexcoords));
    cl::Buffer out(dev.context, CL_MEM_WRITE_ONLY, n * sizeof(pcl_float4));
    cl::Buffer radiance_out(dev.context, CL_MEM_WRITE_ONLY, n * sizeof(pcl_float4));
    cl::Kernel k(program, "test_light_sample");
    k.setArg(0, lb);
    k.setArg(1, static_cast<cl_uint>(lights.size()));
    k.setArg(2, pcl_float4{ref.x, ref.y, ref.z, 0.0f});
    k.setArg(3, seed);
    k.setArg(4, env_texels);
    k.setArg(5, marginal);
    k.setArg(6, conditional);
    k.setArg(7, out);
    k.setArg(8, radiance_out);
    k.setArg(9, texels);
    k.setArg(10, images);
    k.setArg(11, views);
    k.setArg(12, texcoords);
    dev.queue.enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(n));
    std::vector<pcl_float4> result(n);
    dev.queue.enqueueReadBuffer(out, CL_TRUE, 0, n * sizeof(pcl_float4), result.data());
    if (radiance) {
        radiance->resize(n);
        dev.queue.enqueueReadBuffer(radiance_out, CL_TRUE, 0, n * sizeof(pcl_float4), radiance->data());
    }
    return result;
}

} // namespace pathcl::test
