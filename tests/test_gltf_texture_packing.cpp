// Textures packed for the device on the host (no device needed): texel bytes, views
// shared between materials, sRGB only where the slot is a colour, and the power of a
// textured emitter following the texture under each triangle. Next to each test: a broken
// variant seen to fail it.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

#include "compile/texture_lookup.h"
#include "scene/gltf_loader.h"
#include "support/compiled_scene.h"
#include "support/gltf_texture_fixtures.h"

namespace pathcl::test_gltf_texture_packing {
namespace {

using test::kNearest;
using test::Quad;
using test::quad;

// ---------------------------------------------------------------------------------------
// Device packing

TEST(DeviceTextures, PacksTexelsAndSharesViews)
{
    // Two materials using the same texture the same way share one view; the same image as
    // a linear metallic-roughness texture is another view (not sRGB). 8-bit texels take 4
    // bytes, 16-bit 8. Broken variant seen to fail: no de-duplication of views.
    Quad q = quad(false);
    int tex8 = q.b.add_texture(q.b.add_png_image(3, 2, std::vector<std::uint8_t>(24, 100)));
    int tex16 = q.b.add_texture(q.b.add_png_image16(2, 2, std::vector<std::uint16_t>(16, 1000)));
    q.mat().pbrMetallicRoughness.baseColorTexture.index = tex8;
    q.mat().pbrMetallicRoughness.metallicRoughnessTexture.index = tex8;
    q.mat().emissiveTexture.index = tex16;
    q.mat().emissiveFactor = {1.0, 1.0, 1.0};
    q.b.model.materials.push_back(q.mat()); // an identical second material
    int pos = q.b.add_positions({{0, 0, 1}, {1, 0, 1}, {0, 1, 1}});
    int mesh = q.b.add_mesh(pos, -1, 1);
    q.b.set_attribute(mesh, "TEXCOORD_0", q.b.add_texcoords({{0, 0}, {1, 0}, {0, 1}}));
    q.b.add_root(q.b.add_node(mesh));
    CompiledScene cs = test::compile_default(import_gltf(q.b.model, "pack.gltf"));
    EXPECT_EQ(cs.texel_bytes(), 3u * 2u * 4u + 2u * 2u * 8u);
    ASSERT_EQ(cs.arrays.texture_views.size(), 3u);
    const pcl_int* a = cs.arrays.materials[0].textures;
    const pcl_int* b = cs.arrays.materials[1].textures;
    EXPECT_EQ(a[TEXTURE_SLOT_BASE_COLOR], b[TEXTURE_SLOT_BASE_COLOR]);
    EXPECT_NE(a[TEXTURE_SLOT_BASE_COLOR], a[TEXTURE_SLOT_METALLIC_ROUGHNESS]);
    auto view = [&](int slot) { return cs.arrays.texture_views[static_cast<std::size_t>(a[slot])]; };
    EXPECT_EQ(view(TEXTURE_SLOT_BASE_COLOR).flags & TEXTURE_SRGB, TEXTURE_SRGB);
    EXPECT_EQ(view(TEXTURE_SLOT_METALLIC_ROUGHNESS).flags & TEXTURE_SRGB, 0u);
    EXPECT_EQ(a[TEXTURE_SLOT_NORMAL], TEXTURE_NONE);
    EXPECT_TRUE(cs.arrays.tangents.empty());
    EXPECT_TRUE(cs.arrays.colors.empty());
}

TEST(DeviceTextures, TexturedEmitterPowerFollowsTheTextureUnderIt)
{
    // An emissive quad whose texture is black on its left half and white on its right;
    // the diagonal splits it into a triangle over mostly white and one over mostly black
    // texels. Light selection must follow: the pmf ratio is the ratio of the texture's
    // means over the two footprints. Broken variant seen to fail: power from the bare
    // factor (equal pmfs).
    Quad q = quad(false);
    std::vector<std::uint8_t> texels;
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x)
            for (int c = 0; c < 4; ++c)
                texels.push_back(c == 3 ? 255 : (x < 4 ? 0 : 255));
    q.mat().emissiveTexture.index = q.b.add_texture(q.b.add_png_image(8, 8, texels), q.b.add_sampler(kNearest));
    q.mat().emissiveFactor = {2.0, 2.0, 2.0};
    Scene s = import_gltf(q.b.model, "emitter.gltf");
    CompiledScene cs = test::compile_default(s);
    ASSERT_EQ(cs.arrays.lights.size(), 2u);
    std::vector<double> mean;
    for (std::size_t t = 0; t < 2; ++t)
        mean.push_back(texture_mean_over_triangle(s.images[0], s.materials[0].textures[TEXTURE_SLOT_EMISSIVE], true,
                                                  s.texcoords[0][t])
                           .x);
    EXPECT_GT(std::max(mean[0], mean[1]), 0.6);
    EXPECT_LT(std::min(mean[0], mean[1]), 0.4);
    // Light i names its triangle by leaf index; map back to scene triangles.
    double pmf_of_scene_triangle[2] = {0, 0};
    for (std::size_t i = 0; i < cs.arrays.lights.size(); ++i) {
        const TriangleLight& l = cs.arrays.lights[i].data.triangle;
        pmf_of_scene_triangle[cs.bvh.triangle_order[static_cast<std::size_t>(l.triangle)]] =
            cs.arrays.light_distribution[i].pmf;
        EXPECT_EQ(l.texture, cs.arrays.materials[0].textures[TEXTURE_SLOT_EMISSIVE]);
    }
    EXPECT_NEAR(pmf_of_scene_triangle[0] / pmf_of_scene_triangle[1], mean[0] / mean[1], 1e-5);
}

} // namespace
} // namespace pathcl::test_gltf_texture_packing
