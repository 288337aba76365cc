// Light samples on a textured emitter, through the kernels' light sampling
// (tests/kernels/trace_test_kernels.cl): each sample carries the texel at its point.
// Next to each test: the deliberately broken variant of the kernel that was seen to fail it.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

#include "scene/gltf_loader.h"
#include "support/compiled_scene.h"
#include "support/device_fixture.h"
#include "support/gltf_builder.h"
#include "support/gltf_texture_fixtures.h"
#include "support/texture_kernels.h"

namespace pathcl::test_textured_emitter {
namespace {

using test::kClamp;
using test::kNearest;
using test::kTextureFeatures;
using test::texel8;

TEST(TexturedEmitter, LightSamplesCarryTheTexelAtTheirPoint)
{
    // A unit emissive quad at z = 1 facing down, emissiveFactor 3 times a 2 x 2 nearest
    // texture of four colours. Every light sample from below must carry 3 x the texel
    // under its point (found on the host from the sample's direction). Broken variants
    // seen to fail: the light sample carrying the bare factor; the texture read at the
    // barycentrics of the wrong vertex order.
    test::GltfBuilder b;
    std::vector<glm::vec3> p = {{0, 0, 1}, {0, 1, 1}, {1, 1, 1}, {1, 0, 1}}; // counter-clockwise from below
    int pos = b.add_positions(p);
    int idx = b.add_indices({0, 1, 2, 0, 2, 3}, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT);
    int mat = b.add_material(glm::vec3(0.0f), glm::vec3(3.0f));
    int mesh = b.add_mesh(pos, idx, mat);
    std::vector<glm::vec2> uv;
    for (const glm::vec3& v : p)
        uv.push_back({v.x, 1.0f - v.y});
    b.set_attribute(mesh, "TEXCOORD_0", b.add_texcoords(uv));
    const std::vector<std::uint8_t> texels = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 255};
    b.model.materials.back().emissiveTexture.index =
        b.add_texture(b.add_png_image(2, 2, texels), b.add_sampler(kNearest, kClamp, kClamp));
    b.add_root(b.add_node(mesh));
    Scene scene = import_gltf(b.model, "emitter.gltf");
    CompiledScene cs = test::compile_default(scene);
    ASSERT_EQ(cs.arrays.lights.size(), 2u);

    const std::size_t n = 20000;
    const glm::vec3 ref(0.3f, 0.6f, 0.0f);
    static cl::Program program =
        test::build_test_program("trace_test_kernels.cl", kTextureFeatures | FEATURE_AREA_LIGHTS);
    glm::vec3 ref_render(glm::dvec3(ref) - scene.render_origin); // the loader's render space
    std::vector<pcl_float4> rad;
    auto dirs = test::sample_lights_on_device(program, cs.arrays, ref_render, 77u, n, &rad);
    std::size_t checked = 0;
    for (std::size_t i = 0; i < n; ++i) {
        ASSERT_GT(dirs[i].w, 0.0f) << "sample " << i << " failed";
        glm::dvec3 w(dirs[i].x, dirs[i].y, dirs[i].z);
        glm::dvec3 hit = glm::dvec3(ref) + w * ((1.0 - ref.z) / w.z);
        double u = hit.x, v = 1.0 - hit.y;
        if (std::fabs(u - 0.5) < 1e-3 || std::fabs(v - 0.5) < 1e-3)
            continue; // too close to a texel edge to tell which texel the kernel read
        std::size_t texel = (v < 0.5 ? 0 : 2) + (u < 0.5 ? 0 : 1);
        glm::vec3 expected = 3.0f * glm::vec3(texel8(&texels[texel * 4], true));
        EXPECT_NEAR(rad[i].x, expected.x, 1e-6f) << "sample " << i << " texel " << texel;
        EXPECT_NEAR(rad[i].y, expected.y, 1e-6f) << "sample " << i << " texel " << texel;
        EXPECT_NEAR(rad[i].z, expected.z, 1e-6f) << "sample " << i << " texel " << texel;
        ++checked;
    }
    EXPECT_GT(checked, n * 9 / 10);
}

} // namespace
} // namespace pathcl::test_textured_emitter
