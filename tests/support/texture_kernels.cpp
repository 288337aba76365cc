#include "support/texture_kernels.h"

#include "compile/texture_lookup.h"
#include "support/device_fixture.h"

namespace pathcl::test {

const cl::Program& texture_program()
{
    static cl::Program p = test::build_test_program("texture_test_kernels.cl", kTextureFeatures);
    return p;
}

std::vector<pcl_float4> read_back(const cl::Buffer& b, std::size_t n)
{
    return test::read_back<pcl_float4>(b, n);
}

glm::vec4 texel8(const std::uint8_t* c, bool srgb)
{
    glm::vec4 v;
    for (int i = 0; i < 4; ++i)
        v[i] = (srgb && i < 3) ? srgb8_to_linear(c[i]) : static_cast<float>(c[i]) * (1.0f / 255.0f);
    return v;
}

} // namespace pathcl::test
