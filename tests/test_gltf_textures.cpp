// glTF textures on the host (no device): texture references and their texCoord sets,
// samplers, KHR_texture_transform, COLOR_0 in every allowed form, tangents from the file
// and computed (orthonormal, right-handed on mirrored layouts), images decoded by
// OpenImageIO (PNG 8/16-bit, grey, alpha kept unassociated, JPEG, data: URIs, files
// relative to the glTF file, .glb), the device packing (texel bytes, shared views, the
// power of textured emitters), and bad input: each a one-line pathcl::Error naming the
// file and what is wrong. Next to each test: a broken variant seen to fail it.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <numbers>

#include <unistd.h>

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include "common/error.h"
#include "render/texture_lookup.h"
#include "support/compiled_scene.h"
#include "scene/gltf_images.h"
#include "scene/gltf_loader.h"
#include "scene/gltf_textures.h"
#include "scene/tangents.h"
#include "support/expect_error.h"
#include "support/gltf_builder.h"

namespace pathcl {
namespace {

namespace fs = std::filesystem;
using test::GltfBuilder;

constexpr int kNearest = 9728, kLinear = 9729;
constexpr int kRepeat = 10497, kClamp = 33071, kMirror = 33648;
constexpr int kU8 = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, kU16 = TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;

// Hand-made PNGs (Python zlib), so decoding is not checked against OpenImageIO's own writer.
// 2 x 1 RGBA8 (200, 100, 50, 128), (10, 20, 30, 0)
const std::vector<unsigned char> kPngRgba8 = {
    0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d, 0x49, 0x48, 0x44, 0x52,
    0x00, 0x00, 0x00, 0x02, 0x00, 0x00, 0x00, 0x01, 0x08, 0x06, 0x00, 0x00, 0x00, 0xf4, 0x22, 0x7f,
    0x8a, 0x00, 0x00, 0x00, 0x11, 0x49, 0x44, 0x41, 0x54, 0x78, 0xda, 0x63, 0x38, 0x91, 0x62, 0xd4,
    0xc0, 0x25, 0x22, 0xc7, 0x00, 0x00, 0x0d, 0x51, 0x02, 0x1b, 0xcf, 0xa8, 0xbc, 0x2b, 0x00, 0x00,
    0x00, 0x00, 0x49, 0x45, 0x4e, 0x44, 0xae, 0x42, 0x60, 0x82,
};
// 2 x 1 RGBA16 (1000, 20000, 40000, 65535), (65535, 1, 32768, 300)
const std::vector<unsigned char> kPngRgba16 = {
    0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d, 0x49, 0x48, 0x44, 0x52,
    0x00, 0x00, 0x00, 0x02, 0x00, 0x00, 0x00, 0x01, 0x10, 0x06, 0x00, 0x00, 0x00, 0xa4, 0xb2, 0xa3,
    0xc9, 0x00, 0x00, 0x00, 0x18, 0x49, 0x44, 0x41, 0x54, 0x78, 0xda, 0x63, 0x60, 0x7e, 0xe1, 0xa7,
    0x30, 0xc7, 0xe1, 0x3f, 0x10, 0x30, 0x30, 0x36, 0x30, 0x30, 0xea, 0x00, 0x00, 0x41, 0xde, 0x06,
    0xe0, 0x39, 0xfc, 0xad, 0x41, 0x00, 0x00, 0x00, 0x00, 0x49, 0x45, 0x4e, 0x44, 0xae, 0x42, 0x60,
    0x82,
};
// 2 x 1 grey 8-bit: 7, 250
const std::vector<unsigned char> kPngGrey8 = {
    0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d, 0x49, 0x48, 0x44, 0x52,
    0x00, 0x00, 0x00, 0x02, 0x00, 0x00, 0x00, 0x01, 0x08, 0x00, 0x00, 0x00, 0x00, 0xd1, 0x49, 0x20,
    0x56, 0x00, 0x00, 0x00, 0x0b, 0x49, 0x44, 0x41, 0x54, 0x78, 0xda, 0x63, 0x60, 0xff, 0x05, 0x00,
    0x01, 0x0b, 0x01, 0x02, 0x54, 0xf9, 0x8c, 0xc4, 0x00, 0x00, 0x00, 0x00, 0x49, 0x45, 0x4e, 0x44,
    0xae, 0x42, 0x60, 0x82,
};
// 1 x 1 grey-alpha 8-bit: (90, 33)
const std::vector<unsigned char> kPngGreyAlpha8 = {
    0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d, 0x49, 0x48, 0x44, 0x52,
    0x00, 0x00, 0x00, 0x01, 0x00, 0x00, 0x00, 0x01, 0x08, 0x04, 0x00, 0x00, 0x00, 0xb5, 0x1c, 0x0c,
    0x02, 0x00, 0x00, 0x00, 0x0b, 0x49, 0x44, 0x41, 0x54, 0x78, 0xda, 0x63, 0x88, 0x52, 0x04, 0x00,
    0x00, 0xd8, 0x00, 0x7c, 0x70, 0x39, 0x52, 0x6d, 0x00, 0x00, 0x00, 0x00, 0x49, 0x45, 0x4e, 0x44,
    0xae, 0x42, 0x60, 0x82,
};

using test::contains;
using test::error_of;

// A unit quad (two triangles) in the z = 0 plane facing +z, with normals, TEXCOORD_0 =
// (x, 1 - y) and TEXCOORD_1 = (y, x); one material (index `material`), one mesh.
struct Quad {
    GltfBuilder b;
    int material = 0, mesh = 0;
    tinygltf::Material& mat() { return b.model.materials[static_cast<std::size_t>(material)]; }
    tinygltf::Primitive& prim() { return b.model.meshes[static_cast<std::size_t>(mesh)].primitives[0]; }
};

Quad quad(bool with_texcoord1 = true)
{
    Quad q;
    std::vector<glm::vec3> p = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    int pos = q.b.add_positions(p);
    int nrm = q.b.add_normals({{0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {0, 0, 1}});
    int idx = q.b.add_indices({0, 1, 2, 0, 2, 3}, kU16);
    q.material = q.b.add_material(glm::vec3(1.0f));
    q.mesh = q.b.add_mesh(pos, idx, q.material, 4, nrm);
    std::vector<glm::vec2> uv0, uv1;
    for (const glm::vec3& v : p) {
        uv0.push_back({v.x, 1.0f - v.y});
        uv1.push_back({v.y, v.x});
    }
    q.b.set_attribute(q.mesh, "TEXCOORD_0", q.b.add_texcoords(uv0));
    if (with_texcoord1)
        q.b.set_attribute(q.mesh, "TEXCOORD_1", q.b.add_texcoords(uv1));
    q.b.add_root(q.b.add_node(q.mesh));
    return q;
}

int white_texture(GltfBuilder& b, int sampler = -1)
{
    return b.add_texture(b.add_png_image(1, 1, {255, 255, 255, 255}), sampler);
}

tinygltf::Value texture_info(int index, int texcoord = 0)
{
    tinygltf::Value::Object o;
    o["index"] = tinygltf::Value(index);
    o["texCoord"] = tinygltf::Value(texcoord);
    return tinygltf::Value(o);
}

// ---------------------------------------------------------------------------------------
// What the loader reads

TEST(GltfTextures, EverySlotReadsItsTextureAndTexcoordSet)
{
    // Each slot gets its own image; occlusionTexture (here a nonexistent index) is never
    // read. Broken variant seen to fail: the normal texture read from the emissive slot.
    Quad q = quad();
    std::vector<int> tex;
    for (int i = 0; i < 7; ++i)
        tex.push_back(q.b.add_texture(q.b.add_png_image(1, 1, {static_cast<std::uint8_t>(i * 30), 0, 0, 255})));
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
    Scene s = import_gltf(q.b.model, "slots.gltf");
    const SceneMaterial& sm = s.materials[0];
    const SceneTexture* slots[7] = {&sm.textures[TEXTURE_SLOT_BASE_COLOR],  &sm.textures[TEXTURE_SLOT_METALLIC_ROUGHNESS], &sm.textures[TEXTURE_SLOT_EMISSIVE],
                                    &sm.textures[TEXTURE_SLOT_NORMAL],      &sm.textures[TEXTURE_SLOT_SPECULAR],           &sm.textures[TEXTURE_SLOT_SPECULAR_COLOR],
                                    &sm.textures[TEXTURE_SLOT_TRANSMISSION]};
    const int sets[7] = {1, 0, 0, 0, 1, 0, 0};
    ASSERT_EQ(s.images.size(), 7u);
    for (int i = 0; i < 7; ++i) {
        ASSERT_TRUE(slots[i]->present()) << "slot " << i;
        EXPECT_EQ(s.images[static_cast<std::size_t>(slots[i]->image)].rgba8[0], i * 30) << "slot " << i;
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
    q.mat().pbrMetallicRoughness.baseColorTexture.index = white_texture(q.b, q.b.add_sampler(kNearest, kClamp, kMirror));
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

TEST(GltfTextures, VertexColorsInEveryAllowedForm)
{
    // COLOR_0 as VEC3 float, VEC4 normalized u8 and u16, VEC3 normalized u8 (alpha
    // ignored); a primitive without COLOR_0 in the same scene is white. Broken variant
    // seen to fail: u16 colours divided by 255.
    GltfBuilder b;
    int mat = b.add_material(glm::vec3(1.0f));
    auto add = [&](int color_accessor, float x) {
        int pos = b.add_positions({{x, 0, 0}, {x + 1, 0, 0}, {x, 1, 0}});
        int mesh = b.add_mesh(pos, -1, mat);
        if (color_accessor >= 0)
            b.set_attribute(mesh, "COLOR_0", color_accessor);
        b.add_root(b.add_node(mesh));
    };
    auto normalized = [&](int accessor) {
        b.model.accessors[static_cast<std::size_t>(accessor)].normalized = true;
        return accessor;
    };
    add(b.add_positions({{0.25f, 0.5f, 1.0f}, {0, 0, 0}, {1, 1, 1}}), 0.0f);
    const std::uint8_t u8v4[12] = {255, 0, 51, 7, 0, 0, 0, 0, 0, 0, 0, 0};
    add(normalized(b.add_accessor(b.add_view(u8v4, 12), kU8, TINYGLTF_TYPE_VEC4, 3)), 2.0f);
    const std::uint16_t u16v4[12] = {65535, 0, 13107, 1, 0, 0, 0, 0, 0, 0, 0, 0};
    add(normalized(b.add_accessor(b.add_view(u16v4, 24), kU16, TINYGLTF_TYPE_VEC4, 3)), 4.0f);
    const std::uint8_t u8v3[12] = {0, 255, 102, 0, 0, 0, 0, 0, 0, 0, 0, 0};
    add(normalized(b.add_accessor(b.add_view(u8v3, 12), kU8, TINYGLTF_TYPE_VEC3, 3)), 6.0f);
    add(-1, 8.0f);
    Scene s = import_gltf(b.model, "colors.gltf");
    ASSERT_EQ(s.colors.size(), 5u);
    EXPECT_TRUE(kernel_features(s, RenderOptions{}).has(FEATURE_VERTEX_COLORS));
    auto first_color = [&](float x) {
        for (std::size_t i = 0; i < s.triangles.size(); ++i)
            if (std::fabs(s.triangles[i].v[0].x + static_cast<float>(s.render_origin.x) - x) < 1e-4f)
                return s.colors[i][0];
        ADD_FAILURE() << "no triangle at x = " << x;
        return glm::vec3(-1.0f);
    };
    auto near = [](glm::vec3 a, glm::vec3 e) { return glm::length(a - e) < 1e-6f; };
    EXPECT_TRUE(near(first_color(0.0f), {0.25f, 0.5f, 1.0f}));
    EXPECT_TRUE(near(first_color(2.0f), {1.0f, 0.0f, 0.2f}));
    EXPECT_TRUE(near(first_color(4.0f), {1.0f, 0.0f, 0.2f}));
    EXPECT_TRUE(near(first_color(6.0f), {0.0f, 1.0f, 0.4f}));
    EXPECT_TRUE(near(first_color(8.0f), {1.0f, 1.0f, 1.0f}));
}

// ---------------------------------------------------------------------------------------
// Tangents

// A material with a normal texture on the quad.
Quad normal_mapped_quad()
{
    Quad q = quad(false);
    q.mat().normalTexture.index = white_texture(q.b);
    return q;
}

TEST(GltfTangents, FileTangentsFollowTheNodeAndFlipUnderAMirror)
{
    // TANGENT (1, 0, 0, +1): rotated 90 degrees about +z it becomes (0, 1, 0, +1); under
    // the mirror scale (-1, 1, 1) it becomes (-1, 0, 0) with handedness -1. Broken
    // variant seen to fail: handedness kept under the mirror.
    for (bool mirror : {false, true}) {
        Quad q = normal_mapped_quad();
        glm::vec4 t(1, 0, 0, 1);
        q.b.set_attribute(q.mesh, "TANGENT", q.b.add_tangents({t, t, t, t}));
        tinygltf::Node& node = q.b.model.nodes[0];
        if (mirror)
            node.scale = {-1.0, 1.0, 1.0};
        else
            node.rotation = {0.0, 0.0, std::sin(std::numbers::pi / 4.0), std::cos(std::numbers::pi / 4.0)};
        Scene s = import_gltf(q.b.model, "tangents.gltf");
        ASSERT_EQ(s.tangents.size(), 2u);
        glm::vec4 expected = mirror ? glm::vec4(-1, 0, 0, -1) : glm::vec4(0, 1, 0, 1);
        for (const TriangleTangent& tri : s.tangents)
            for (const glm::vec4& got : tri)
                EXPECT_LT(glm::length(got - expected), 1e-6f) << (mirror ? "mirrored" : "rotated");
    }
}

TEST(GltfTangents, ComputedTangentsAreOrthonormalAndRightHanded)
{
    // A bent strip (normals not equal to face normals, non-uniform UV density). At every
    // corner: |t| = 1, t . n = 0, t along +dP/du, and w cross(n, t) along -dP/dv (the
    // image's "up"), for the upright layout (w = +1) and the mirrored one (u -> 1 - u,
    // w = -1). Broken variants seen to fail: no Gram-Schmidt (t . n != 0 on the bend);
    // handedness from +dP/dv.
    for (bool mirrored : {false, true}) {
        std::vector<glm::dvec3> p, n;
        std::vector<glm::dvec2> uv;
        for (int i = 0; i <= 4; ++i) {
            double a = 0.3 * i, x = std::sin(a), z = 1.0 - std::cos(a);
            for (int j = 0; j <= 1; ++j) {
                p.push_back({x, j * 1.5, z});
                n.push_back(glm::normalize(glm::dvec3(-std::sin(a), 0.0, std::cos(a))));
                double u = 0.2 * i * i / 4.0 + 0.1 * i; // non-uniform
                uv.push_back({mirrored ? 1.0 - u : u, 1.0 - 0.8 * j});
            }
        }
        std::vector<std::uint32_t> tris;
        for (std::uint32_t i = 0; i < 4; ++i) {
            std::uint32_t a = 2 * i, b2 = 2 * i + 2, c = 2 * i + 3, d = 2 * i + 1;
            tris.insert(tris.end(), {a, b2, c, a, c, d});
        }
        std::vector<glm::dvec4> t = compute_tangents(p, n, uv, tris);
        ASSERT_EQ(t.size(), tris.size());
        for (std::size_t c = 0; c < tris.size(); ++c) {
            const glm::dvec3& nn = n[tris[c]];
            glm::dvec3 tt(t[c]);
            EXPECT_NEAR(glm::length(tt), 1.0, 1e-12);
            EXPECT_NEAR(glm::dot(tt, nn), 0.0, 1e-12);
            // dP/du points along the strip's length (+x side) when u grows with i.
            glm::dvec3 along = glm::normalize(glm::dvec3(std::cos(0.3 * (tris[c] / 2)), 0.0, std::sin(0.3 * (tris[c] / 2))));
            EXPECT_GT(glm::dot(tt, along) * (mirrored ? -1.0 : 1.0), 0.9);
            // v decreases with +y (v = 1 - 0.8 j), so "up" in the image is +y.
            glm::dvec3 bitangent = t[c].w * glm::cross(nn, tt);
            EXPECT_GT(bitangent.y, 0.99);
            EXPECT_EQ(t[c].w, mirrored ? -1.0 : 1.0);
        }
    }
}

TEST(GltfTangents, FlatShadingGetsOneFramePerFace)
{
    // Without NORMAL each triangle gets a tangent orthogonal to its own face normal.
    // Broken variant seen to fail: every face framed around the first face's normal.
    std::vector<glm::dvec3> p = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 0, 0}, {1, 1, 1}, {0, 1, 0}};
    std::vector<glm::dvec2> uv = {{0, 1}, {1, 1}, {0, 0}, {1, 1}, {1, 0}, {0, 0}};
    std::vector<std::uint32_t> tris = {0, 1, 2, 3, 4, 5};
    std::vector<glm::dvec4> t = compute_tangents(p, {}, uv, tris);
    for (int f = 0; f < 2; ++f) {
        glm::dvec3 fn = glm::normalize(glm::cross(p[tris[3 * f + 1]] - p[tris[3 * f]], p[tris[3 * f + 2]] - p[tris[3 * f]]));
        for (int k = 0; k < 3; ++k) {
            EXPECT_NEAR(glm::dot(glm::dvec3(t[static_cast<std::size_t>(3 * f + k)]), fn), 0.0, 1e-12) << "face " << f;
            EXPECT_EQ(t[static_cast<std::size_t>(3 * f + k)], t[static_cast<std::size_t>(3 * f)]);
        }
    }
}

TEST(GltfTangents, LoaderComputesTangentsWhenTheFileHasNone)
{
    // The quad (u = x, v = 1 - y): tangent +x, handedness +1, through the loader. Broken
    // variant seen to fail: handedness from +dP/dv.
    Quad q = normal_mapped_quad();
    Scene s = import_gltf(q.b.model, "computed.gltf");
    ASSERT_EQ(s.tangents.size(), 2u);
    for (const TriangleTangent& tri : s.tangents)
        for (const glm::vec4& t : tri)
            EXPECT_LT(glm::length(t - glm::vec4(1, 0, 0, 1)), 1e-6f);
}

// ---------------------------------------------------------------------------------------
// Image decoding

SceneImage decoded(const std::vector<unsigned char>& png) { return decode_image(png.data(), png.size(), "test"); }

TEST(GltfImages, PngAlphaStaysUnassociated)
{
    // Broken variant seen to fail: opening without oiio:UnassociatedAlpha (OpenImageIO
    // premultiplies: (200, 100, 50) at alpha 128 comes back as (100, 50, 25)).
    SceneImage img = decoded(kPngRgba8);
    ASSERT_EQ(img.bits, 8);
    ASSERT_EQ(img.width, 2u);
    EXPECT_EQ(img.rgba8, (std::vector<std::uint8_t>{200, 100, 50, 128, 10, 20, 30, 0}));
}

TEST(GltfImages, SixteenBitPngKeepsSixteenBits)
{
    // Broken variant seen to fail: no oiio:UnassociatedAlpha (its alpha 300 premultiplies).
    SceneImage img = decoded(kPngRgba16);
    ASSERT_EQ(img.bits, 16);
    EXPECT_EQ(img.rgba16, (std::vector<std::uint16_t>{1000, 20000, 40000, 65535, 65535, 1, 32768, 300}));
}

TEST(GltfImages, GreyImagesExpandToRgba)
{
    // Broken variant seen to fail: no oiio:UnassociatedAlpha (the grey-alpha texel).
    EXPECT_EQ(decoded(kPngGrey8).rgba8, (std::vector<std::uint8_t>{7, 7, 7, 255, 250, 250, 250, 255}));
    EXPECT_EQ(decoded(kPngGreyAlpha8).rgba8, (std::vector<std::uint8_t>{90, 90, 90, 33}));
}

TEST(GltfImages, JpegDecodes)
{
    // A flat 8 x 8 JPEG (lossy, so only near its colour). Broken variant seen to fail:
    // the format sniffed from the PNG signature only.
    std::vector<unsigned char> bytes;
    OIIO::Filesystem::IOVecOutput proxy(bytes);
    auto out = OIIO::ImageOutput::create("jpeg");
    OIIO::ImageSpec spec(8, 8, 3, OIIO::TypeDesc::UINT8);
    std::vector<std::uint8_t> pixels(8 * 8 * 3);
    for (std::size_t i = 0; i < pixels.size(); i += 3) {
        pixels[i] = 180;
        pixels[i + 1] = 90;
        pixels[i + 2] = 30;
    }
    ASSERT_TRUE(out && out->set_ioproxy(&proxy) && out->open("x.jpg", spec) &&
                out->write_image(OIIO::TypeDesc::UINT8, pixels.data()) && out->close());
    SceneImage img = decode_image(bytes.data(), bytes.size(), "jpeg");
    ASSERT_EQ(img.width, 8u);
    ASSERT_EQ(img.bits, 8);
    EXPECT_NEAR(img.rgba8[0], 180, 3);
    EXPECT_NEAR(img.rgba8[1], 90, 3);
    EXPECT_NEAR(img.rgba8[2], 30, 3);
    EXPECT_EQ(img.rgba8[3], 255);
}

// A directory removed at the end of the test.
class TempDir {
public:
    TempDir()
    {
        const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
        root_ = fs::temp_directory_path() / ("pathcl-tex-" + std::to_string(::getpid()) + "-" + info->name());
        fs::remove_all(root_);
        fs::create_directories(root_);
    }
    ~TempDir() { fs::remove_all(root_); }
    const fs::path& path() const { return root_; }

private:
    fs::path root_;
};

// Writes `b`'s model as a .gltf (buffers embedded as data: URIs; images keep their uri,
// nothing is written for them) and loads it with load_gltf.
Scene write_and_load(const GltfBuilder& b, const fs::path& file, bool binary = false)
{
    tinygltf::TinyGLTF writer;
    writer.SetImageWriter(
        [](const std::string*, const std::string*, const tinygltf::Image*, bool, std::string*, void*) { return false; },
        nullptr);
    if (!writer.WriteGltfSceneToFile(&b.model, file.string(), false, true, false, binary))
        throw std::runtime_error("cannot write " + file.string());
    return load_gltf(file.string());
}

void write_bytes(const fs::path& p, const std::vector<unsigned char>& bytes)
{
    std::ofstream out(p, std::ios::binary);
    out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
}

// The quad with its base colour read from image `image` (set up by the caller).
Quad quad_with_image(const tinygltf::Image& image)
{
    Quad q = quad(false);
    q.b.model.images.push_back(image);
    q.mat().pbrMetallicRoughness.baseColorTexture.index = q.b.add_texture(static_cast<int>(q.b.model.images.size()) - 1);
    return q;
}

TEST(GltfImages, FileUrisResolveAgainstTheGltfFilesDirectory)
{
    // The scene sits in a subdirectory and names "tex/a.png"; the working directory is
    // elsewhere. Also a data: URI. Broken variant seen to fail: the URI check rejecting
    // every path with a directory part.
    TempDir dir;
    fs::create_directories(dir.path() / "scene" / "tex");
    write_bytes(dir.path() / "scene" / "tex" / "a.png", kPngRgba8);
    tinygltf::Image file_image;
    file_image.uri = "tex/a.png";
    Scene s = write_and_load(quad_with_image(file_image).b, dir.path() / "scene" / "file.gltf");
    ASSERT_EQ(s.images.size(), 1u);
    EXPECT_EQ(s.images[0].rgba8[0], 200);

    tinygltf::Image data_image;
    const char* b64 = "data:image/png;base64,";
    std::string uri = b64;
    {
        static const char* t = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
        const std::vector<unsigned char>& in = kPngGrey8;
        for (std::size_t i = 0; i < in.size(); i += 3) {
            unsigned v = in[i] << 16 | (i + 1 < in.size() ? in[i + 1] << 8 : 0) | (i + 2 < in.size() ? in[i + 2] : 0);
            uri += t[v >> 18 & 63];
            uri += t[v >> 12 & 63];
            uri += i + 1 < in.size() ? t[v >> 6 & 63] : '=';
            uri += i + 2 < in.size() ? t[v & 63] : '=';
        }
    }
    data_image.uri = uri;
    Scene d = write_and_load(quad_with_image(data_image).b, dir.path() / "data.gltf");
    ASSERT_EQ(d.images.size(), 1u);
    EXPECT_EQ(d.images[0].rgba8[4], 250);
}

TEST(GltfImages, GlbBufferViewImages)
{
    // A .glb written by tinygltf, the PNG in a bufferView of its binary chunk. Broken
    // variant seen to fail: the view's byteOffset ignored.
    TempDir dir;
    Quad q = quad(false);
    q.mat().pbrMetallicRoughness.baseColorTexture.index =
        q.b.add_texture(q.b.add_image_bytes(kPngRgba16, "image/png"));
    Scene s = write_and_load(q.b, dir.path() / "scene.glb", true);
    ASSERT_EQ(s.images.size(), 1u);
    EXPECT_EQ(s.images[0].rgba16[1], 20000);
}

// ---------------------------------------------------------------------------------------
// Bad input: one line naming the file and what is wrong

struct BadCase {
    const char* name;
    std::function<void(Quad&)> breakit;
    const char* expected; // part of the message
};

void PrintTo(const BadCase& c, std::ostream* os) { *os << c.name; }

class GltfBrokenTextures : public ::testing::TestWithParam<BadCase> {};

// Broken variant seen to fail (TexcoordTheMeshLacks): the loader without its texCoord check.
TEST_P(GltfBrokenTextures, ThrowsOneLineNamingTheFile)
{
    Quad q = quad(false);
    q.mat().pbrMetallicRoughness.baseColorTexture.index = white_texture(q.b);
    ASSERT_NO_THROW(import_gltf(q.b.model, "broken.gltf")); // valid before breaking it
    GetParam().breakit(q);
    std::string msg = error_of([&] { import_gltf(q.b.model, "broken.gltf"); });
    EXPECT_EQ(msg.rfind("broken.gltf: ", 0), 0u) << msg;
    EXPECT_TRUE(contains(msg, GetParam().expected)) << msg;
    EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
}

INSTANTIATE_TEST_SUITE_P(
    GltfBrokenData, GltfBrokenTextures,
    ::testing::Values(
        BadCase{"TextureIndexOutOfRange", [](Quad& q) { q.mat().pbrMetallicRoughness.baseColorTexture.index = 7; },
                "texture index 7 does not exist"},
        BadCase{"ImageIndexOutOfRange", [](Quad& q) { q.b.model.textures[0].source = 3; },
                "image index 3 does not exist"},
        BadCase{"TextureWithoutSource", [](Quad& q) { q.b.model.textures[0].source = -1; }, "has no PNG or JPEG source"},
        BadCase{"SamplerIndexOutOfRange", [](Quad& q) { q.b.model.textures[0].sampler = 2; },
                "sampler index 2 does not exist"},
        BadCase{"UnknownWrapMode",
                [](Quad& q) { q.b.model.textures[0].sampler = q.b.add_sampler(kLinear, 12345, kRepeat); },
                "unknown wrap mode 12345"},
        BadCase{"TexcoordTheMeshLacks",
                [](Quad& q) { q.mat().pbrMetallicRoughness.baseColorTexture.texCoord = 1; },
                "baseColorTexture reads TEXCOORD_1, which the primitive does not have"},
        BadCase{"TexcoordOutOfRange", [](Quad& q) { q.mat().pbrMetallicRoughness.baseColorTexture.texCoord = 100000; },
                "texCoord 100000 is out of range"},
        BadCase{"NotPngOrJpeg",
                [](Quad& q) {
                    // A BMP header: a real image format, but not one glTF allows.
                    q.b.model.images[0].bufferView = q.b.add_view("BM\x3a\0\0\0\0\0\0\0\x36\0\0\0", 14);
                },
                "not a PNG or JPEG image"},
        BadCase{"CorruptPng",
                [](Quad& q) {
                    std::vector<unsigned char> bytes(kPngRgba8.begin(), kPngRgba8.begin() + 40);
                    q.b.model.images[0].bufferView = q.b.add_view(bytes.data(), bytes.size());
                },
                "cannot decode the png image"},
        BadCase{"ImageBufferViewOutsideBuffer",
                [](Quad& q) {
                    auto& view = q.b.model.bufferViews[static_cast<std::size_t>(q.b.model.images[0].bufferView)];
                    view.byteLength = 1 << 20;
                },
                "its bufferView lies outside its buffer"},
        BadCase{"MalformedTextureTransform",
                [](Quad& q) {
                    tinygltf::Value::Object transform;
                    transform["offset"] = tinygltf::Value(1.0);
                    q.mat().pbrMetallicRoughness.baseColorTexture.extensions["KHR_texture_transform"] =
                        tinygltf::Value(transform);
                },
                "\"offset\" must be an array of two finite numbers"},
        BadCase{"NonNormalizedIntegerTexcoords",
                [](Quad& q) {
                    const std::uint8_t uv[8] = {0, 0, 1, 0, 1, 1, 0, 1};
                    int acc = q.b.add_accessor(q.b.add_view(uv, 8), kU8, TINYGLTF_TYPE_VEC2, 4);
                    q.prim().attributes["TEXCOORD_0"] = acc;
                },
                "integer components must be normalized"},
        BadCase{"ColourOutsideUnitRange",
                [](Quad& q) {
                    q.prim().attributes["COLOR_0"] = q.b.add_positions({{0, 0, 0}, {2, 0, 0}, {0, 0, 0}, {0, 0, 0}});
                },
                "colour component outside [0, 1]"}),
    [](const ::testing::TestParamInfo<BadCase>& i) { return std::string(i.param.name); });

// Image URIs through load_gltf: missing file, absolute path, other schemes.
struct UriCase {
    const char* name;
    std::string uri;
    const char* expected;
};

void PrintTo(const UriCase& c, std::ostream* os) { *os << c.name; }

class GltfBadImageUri : public ::testing::TestWithParam<UriCase> {};

// Broken variant seen to fail (the three scheme cases): the URI-scheme check removed.
TEST_P(GltfBadImageUri, ThrowsOneLineNamingTheFile)
{
    TempDir dir;
    write_bytes(dir.path() / "a.png", kPngRgba8);
    tinygltf::Image image;
    image.uri = GetParam().uri == "ABSOLUTE" ? (dir.path() / "a.png").string() : GetParam().uri;
    fs::path file = dir.path() / "bad-uri.gltf";
    std::string msg = error_of([&] { write_and_load(quad_with_image(image).b, file); });
    EXPECT_EQ(msg.rfind(file.string() + ": ", 0), 0u) << msg;
    EXPECT_TRUE(contains(msg, GetParam().expected)) << msg;
    EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
}

INSTANTIATE_TEST_SUITE_P(
    GltfBrokenData, GltfBadImageUri,
    ::testing::Values(UriCase{"MissingFile", "missing.png", "cannot read the file"},
                      UriCase{"AbsolutePath", "ABSOLUTE", "is absolute"},
                      UriCase{"HttpScheme", "http://example.com/a.png", "the URI scheme 'http:' is not read"},
                      UriCase{"FileScheme", "file:///tmp/a.png", "the URI scheme 'file:' is not read"},
                      UriCase{"UnsupportedDataUri", "data:image/webp;base64,AAAA", "a data: URI with a media type"}),
    [](const ::testing::TestParamInfo<UriCase>& i) { return std::string(i.param.name); });

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
        mean.push_back(texture_mean_over_triangle(s.images[0], s.materials[0].textures[TEXTURE_SLOT_EMISSIVE], true, s.texcoords[0][t]).x);
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
} // namespace pathcl
