// glTF texture references on the host (no device): every material slot reads its own
// texture and texCoord set, samplers give the wrap modes and filter, and
// KHR_texture_transform follows the specification's example. Next to each test: a broken
// variant seen to fail it.
#include <numbers>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "compile/kernel_features.h"
#include "scene/gltf_loader.h"
#include "scene/gltf_textures.h"
#include "support/gltf_texture_fixtures.h"

namespace pathcl::test_gltf_texture_slots {
namespace {

using test::kClamp;
using test::kLinear;
using test::kMirror;
using test::kNearest;
using test::kRepeat;
using test::Quad;
using test::quad;
using test::texture_info;
using test::white_texture;

// ---------------------------------------------------------------------------------------
// What the loader reads

TEST(GltfTextures, EverySlotReadsItsTextureAndTexcoordSet)
{
    // Each slot gets its own image; occlusionTexture (here a nonexistent index) is never
    // read. Broken variant seen to fail: the normal texture read from the emissive slot.
    Quad q = quad();
    std::vector<int> tex;
    for (int i = 0; i < 10; ++i)
        tex.push_back(q.b.add_texture(q.b.add_png_image(1, 1, {static_cast<std::uint8_t>(i * 25), 0, 0, 255})));
    tinygltf::Material& m = q.mat();
    m.pbrMetallicRoughness.baseColorTexture.index = tex[0];
    m.pbrMetallicRoughness.baseColorTexture.texCoord = 1;
    m.pbrMetallicRoughness.metallicRoughnessTexture.index = tex[1];
    m.emissiveTexture.index = tex[2];
    m.emissiveFactor = {1.0, 1.0, 1.0};
    m.normalTexture.index = tex[3];
    m.normalTexture.scale = 0.7;
    m.occlusionTexture.index = 99;
    tinygltf::Value::Object spec;
    spec["specularTexture"] = texture_info(tex[4], 1);
    spec["specularColorTexture"] = texture_info(tex[5]);
    m.extensions["KHR_materials_specular"] = tinygltf::Value(spec);
    tinygltf::Value::Object trans;
    trans["transmissionFactor"] = tinygltf::Value(0.5);
    trans["transmissionTexture"] = texture_info(tex[6]);
    m.extensions["KHR_materials_transmission"] = tinygltf::Value(trans);
    tinygltf::Value::Object coat;
    coat["clearcoatFactor"] = tinygltf::Value(1.0);
    coat["clearcoatTexture"] = texture_info(tex[7], 1);
    coat["clearcoatRoughnessTexture"] = texture_info(tex[8]);
    coat["clearcoatNormalTexture"] = texture_info(tex[9]);
    m.extensions["KHR_materials_clearcoat"] = tinygltf::Value(coat);
    Scene s = import_gltf(q.b.model, "slots.gltf");
    const SceneMaterial& sm = s.materials[0];
    const SceneTexture* slots[10] = {&sm.textures[TEXTURE_SLOT_BASE_COLOR],
                                     &sm.textures[TEXTURE_SLOT_METALLIC_ROUGHNESS],
                                     &sm.textures[TEXTURE_SLOT_EMISSIVE],
                                     &sm.textures[TEXTURE_SLOT_NORMAL],
                                     &sm.textures[TEXTURE_SLOT_SPECULAR],
                                     &sm.textures[TEXTURE_SLOT_SPECULAR_COLOR],
                                     &sm.textures[TEXTURE_SLOT_TRANSMISSION],
                                     &sm.textures[TEXTURE_SLOT_CLEARCOAT],
                                     &sm.textures[TEXTURE_SLOT_CLEARCOAT_ROUGHNESS],
                                     &sm.textures[TEXTURE_SLOT_CLEARCOAT_NORMAL]};
    const int sets[10] = {1, 0, 0, 0, 1, 0, 0, 1, 0, 0};
    ASSERT_EQ(s.images.size(), 10u);
    for (int i = 0; i < 10; ++i) {
        ASSERT_TRUE(slots[i]->present()) << "slot " << i;
        EXPECT_EQ(s.images[static_cast<std::size_t>(slots[i]->image)].rgba8[0], i * 25) << "slot " << i;
        EXPECT_EQ(slots[i]->texcoord, sets[i]) << "slot " << i;
    }
    EXPECT_FLOAT_EQ(sm.normal_scale, 0.7f);
    // Both sets are carried per triangle; triangle 0 is (0,0,0), (1,0,0), (1,1,0).
    ASSERT_EQ(s.texcoords.size(), 2u);
    ASSERT_EQ(s.texcoords[0].size(), 2u);
    ASSERT_EQ(s.texcoords[1].size(), 2u);
    EXPECT_EQ(s.texcoords[0][0][1], glm::vec2(1.0f, 1.0f));
    EXPECT_EQ(s.texcoords[1][0][2], glm::vec2(1.0f, 1.0f));
    EXPECT_EQ(s.texcoords[1][0][1], glm::vec2(0.0f, 1.0f));
    KernelFeatures f = kernel_features(s, RenderOptions{});
    EXPECT_TRUE(f.has(FEATURE_TEXTURES));
    EXPECT_TRUE(f.has(FEATURE_NORMAL_MAPS));
    EXPECT_FALSE(f.has(FEATURE_VERTEX_COLORS));
}

TEST(GltfTextures, SamplersGiveWrapModesAndFilter)
{
    // Broken variant seen to fail: wrapS and wrapT exchanged.
    Quad q = quad();
    q.mat().pbrMetallicRoughness.baseColorTexture.index =
        white_texture(q.b, q.b.add_sampler(kNearest, kClamp, kMirror));
    q.mat().emissiveTexture.index = white_texture(q.b, q.b.add_sampler(kLinear, kMirror, kRepeat));
    q.mat().pbrMetallicRoughness.metallicRoughnessTexture.index = white_texture(q.b); // no sampler: defaults
    Scene s = import_gltf(q.b.model, "samplers.gltf");
    const SceneMaterial& m = s.materials[0];
    EXPECT_EQ(m.textures[TEXTURE_SLOT_BASE_COLOR].wrap_s, TextureWrap::ClampToEdge);
    EXPECT_EQ(m.textures[TEXTURE_SLOT_BASE_COLOR].wrap_t, TextureWrap::MirroredRepeat);
    EXPECT_TRUE(m.textures[TEXTURE_SLOT_BASE_COLOR].nearest);
    EXPECT_EQ(m.textures[TEXTURE_SLOT_EMISSIVE].wrap_s, TextureWrap::MirroredRepeat);
    EXPECT_EQ(m.textures[TEXTURE_SLOT_EMISSIVE].wrap_t, TextureWrap::Repeat);
    EXPECT_FALSE(m.textures[TEXTURE_SLOT_EMISSIVE].nearest);
    EXPECT_EQ(m.textures[TEXTURE_SLOT_METALLIC_ROUGHNESS].wrap_s, TextureWrap::Repeat);
    EXPECT_EQ(m.textures[TEXTURE_SLOT_METALLIC_ROUGHNESS].wrap_t, TextureWrap::Repeat);
    EXPECT_FALSE(m.textures[TEXTURE_SLOT_METALLIC_ROUGHNESS].nearest);
}

glm::vec2 apply(const SceneTexture& t, glm::vec2 uv)
{
    return {glm::dot(t.transform_u, glm::vec3(uv, 1.0f)), glm::dot(t.transform_v, glm::vec3(uv, 1.0f))};
}

TEST(GltfTextures, TextureTransformFollowsTheSpecificationsExample)
{
    // KHR_texture_transform's example: offset (0, 1), rotation pi/2, scale (1/2, 1/2)
    // "utilizes only the lower left quadrant of the source image, rotated clockwise 90
    // degrees": (0,0) -> (0,1), (1,0) -> (0,1/2), (1,1) -> (1/2,1/2), (0,1) -> (1/2,1).
    // Its texCoord overrides the textureInfo's. Broken variant seen to fail: the rotation
    // of the extension's GLSL read literally (column-major), which maps the square
    // outside [0, 1]^2.
    Quad q = quad();
    q.b.model.extensionsRequired.push_back("KHR_texture_transform");
    tinygltf::TextureInfo& info = q.mat().pbrMetallicRoughness.baseColorTexture;
    info.index = white_texture(q.b);
    tinygltf::Value::Object t;
    t["offset"] = tinygltf::Value(tinygltf::Value::Array{tinygltf::Value(0.0), tinygltf::Value(1.0)});
    t["rotation"] = tinygltf::Value(std::numbers::pi / 2.0);
    t["scale"] = tinygltf::Value(tinygltf::Value::Array{tinygltf::Value(0.5), tinygltf::Value(0.5)});
    t["texCoord"] = tinygltf::Value(1);
    info.extensions["KHR_texture_transform"] = tinygltf::Value(t);
    Scene s = import_gltf(q.b.model, "transform.gltf");
    const SceneTexture& tex = s.materials[0].textures[TEXTURE_SLOT_BASE_COLOR];
    EXPECT_EQ(tex.texcoord, 1);
    const std::pair<glm::vec2, glm::vec2> corners[4] = {
        {{0, 0}, {0, 1}}, {{1, 0}, {0, 0.5f}}, {{1, 1}, {0.5f, 0.5f}}, {{0, 1}, {0.5f, 1}}};
    for (const auto& [from, to] : corners) {
        glm::vec2 got = apply(tex, from);
        EXPECT_NEAR(got.x, to.x, 1e-7) << "(" << from.x << ", " << from.y << ")";
        EXPECT_NEAR(got.y, to.y, 1e-7) << "(" << from.x << ", " << from.y << ")";
    }
    // A small rotation turns +u towards -v: counter-clockwise as the image is shown (v down).
    glm::vec3 row_u, row_v;
    texture_transform_matrix(0.0, 0.0, 0.1, 1.0, 1.0, row_u, row_v);
    EXPECT_GT(row_u.x, 0.99f);
    EXPECT_LT(row_v.x, 0.0f);
}

} // namespace
} // namespace pathcl::test_gltf_texture_slots
