// The textured material at a hit through the kernels' own code
// (tests/kernels/texture_test_kernels.cl), on a quad imported from glTF and compiled for the
// device: factors x texels x vertex colour, normal mapping with file and computed tangents,
// normal scale and back faces, and normals bent back above the surface.
// Next to each test: the deliberately broken variant of the kernel that was seen to fail it.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <functional>
#include <numbers>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "compile/device_arrays.h"
#include "compile/texture_lookup.h"
#include "scene/gltf_loader.h"
#include "support/compiled_scene.h"
#include "support/device_fixture.h"
#include "support/gltf_builder.h"
#include "support/texture_kernels.h"

namespace pathcl::test_material_inputs {
namespace {

using test::read_back;
using test::texture_program;
using test::upload;

struct QuadOptions {
    bool mirrored_uv = false;   // u runs along -x instead of +x
    bool file_tangents = false; // TANGENT attribute instead of computed tangents
    bool double_sided = false;
    std::vector<std::uint8_t> normal_texel = {128, 128, 255, 255};
    double normal_scale = 1.0;
    // Edits the material last (after every texture above is set).
    std::function<void(test::GltfBuilder&, tinygltf::Material&)> edit;
};

// A unit quad in the z = 0 plane facing +z with smooth normals (+z), texture coordinates
// u = x (or 1 - x), v = 1 - y (the image upright), a constant 1 x 1 texture in every
// core slot, and COLOR_0 (0.5, 1, 1) at every vertex.
Scene textured_quad(const QuadOptions& o)
{
    test::GltfBuilder b;
    std::vector<glm::vec3> p = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    int pos = b.add_positions(p);
    int nrm = b.add_normals({{0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {0, 0, 1}});
    int idx = b.add_indices({0, 1, 2, 0, 2, 3}, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT);
    test::GltfBuilder::Pbr pbr;
    pbr.base_color = glm::vec3(0.8f, 0.6f, 0.4f);
    pbr.metallic = 0.5;
    pbr.roughness = 0.8;
    pbr.double_sided = o.double_sided;
    int mat = b.add_pbr_material(pbr);
    int mesh = b.add_mesh(pos, idx, mat, 4, nrm);
    std::vector<glm::vec2> uv;
    for (const glm::vec3& v : p)
        uv.push_back({o.mirrored_uv ? 1.0f - v.x : v.x, 1.0f - v.y});
    b.set_attribute(mesh, "TEXCOORD_0", b.add_texcoords(uv));
    if (o.file_tangents) {
        glm::vec4 t = o.mirrored_uv ? glm::vec4(-1, 0, 0, -1) : glm::vec4(1, 0, 0, 1);
        b.set_attribute(mesh, "TANGENT", b.add_tangents({t, t, t, t}));
    }
    std::vector<glm::vec3> colors(4, glm::vec3(0.5f, 1.0f, 1.0f));
    b.set_attribute(mesh, "COLOR_0", b.add_positions(colors));
    tinygltf::Material& m = b.model.materials.back();
    m.pbrMetallicRoughness.baseColorTexture.index = b.add_texture(b.add_png_image(1, 1, {188, 128, 64, 255}));
    m.pbrMetallicRoughness.metallicRoughnessTexture.index = b.add_texture(b.add_png_image(1, 1, {0, 102, 204, 255}));
    m.emissiveFactor = {2.0, 2.0, 2.0};
    m.emissiveTexture.index = b.add_texture(b.add_png_image(1, 1, {255, 128, 0, 255}));
    m.normalTexture.index = b.add_texture(b.add_png_image(1, 1, o.normal_texel));
    m.normalTexture.scale = o.normal_scale;
    // KHR_materials_specular and _transmission textures (factors 0.8, (1, 0.5, 1), 0.6).
    tinygltf::Value::Object spec, trans;
    spec["specularFactor"] = tinygltf::Value(0.8);
    spec["specularColorFactor"] = test::json_numbers({1.0, 0.5, 1.0});
    spec["specularTexture"] = test::texture_info(b.add_texture(b.add_png_image(1, 1, {10, 20, 30, 153})));
    spec["specularColorTexture"] = test::texture_info(b.add_texture(b.add_png_image(1, 1, {255, 188, 64, 255})));
    m.extensions["KHR_materials_specular"] = tinygltf::Value(spec);
    trans["transmissionFactor"] = tinygltf::Value(0.6);
    trans["transmissionTexture"] = test::texture_info(b.add_texture(b.add_png_image(1, 1, {51, 200, 200, 255})));
    m.extensions["KHR_materials_transmission"] = tinygltf::Value(trans);
    // KHR_materials_clearcoat textures (factors 0.9 and 0.5).
    tinygltf::Value::Object coat;
    coat["clearcoatFactor"] = tinygltf::Value(0.9);
    coat["clearcoatRoughnessFactor"] = tinygltf::Value(0.5);
    coat["clearcoatTexture"] = test::texture_info(b.add_texture(b.add_png_image(1, 1, {102, 0, 0, 255})));
    coat["clearcoatRoughnessTexture"] = test::texture_info(b.add_texture(b.add_png_image(1, 1, {0, 204, 0, 255})));
    m.extensions["KHR_materials_clearcoat"] = tinygltf::Value(coat);
    // KHR_materials_sheen textures (factors (0.5, 1, 0.25) and 0.8): roughness from A.
    tinygltf::Value::Object sheen;
    sheen["sheenColorFactor"] = test::json_numbers({0.5, 1.0, 0.25});
    sheen["sheenRoughnessFactor"] = tinygltf::Value(0.8);
    sheen["sheenColorTexture"] = test::texture_info(b.add_texture(b.add_png_image(1, 1, {200, 100, 50, 255})));
    sheen["sheenRoughnessTexture"] = test::texture_info(b.add_texture(b.add_png_image(1, 1, {10, 20, 30, 102})));
    m.extensions["KHR_materials_sheen"] = tinygltf::Value(sheen);
    if (o.edit)
        o.edit(b, m);
    b.add_root(b.add_node(mesh));
    return import_gltf(b.model, "quad.gltf");
}

struct MaterialProbe {
    std::vector<pcl_float4> normal, base_color, emission, specular_color, params, coat, coat_normal, sheen, anisotropy;
};

// test_material_inputs at barycentrics (b1, b2) of scene triangle 0, seen along -wo.
MaterialProbe probe(const Scene& scene, const std::vector<glm::vec2>& bary, const std::vector<glm::vec3>& wo)
{
    CompiledScene cs = test::compile_default(scene);
    auto order = cs.bvh.triangle_order;
    int leaf = static_cast<int>(std::find(order.begin(), order.end(), 0u) - order.begin());
    float leaf_bits;
    std::memcpy(&leaf_bits, &leaf, 4);
    std::vector<pcl_float4> hits, wos;
    for (std::size_t i = 0; i < bary.size(); ++i) {
        hits.push_back({bary[i].x, bary[i].y, leaf_bits, 0.0f});
        glm::vec3 w = glm::normalize(wo[i]);
        wos.push_back({w.x, w.y, w.z, 0.0f});
    }
    cl::Kernel k(texture_program(), "test_material_inputs");
    ClDevice& dev = test::test_device();
    DeviceArrays arrays = upload_arrays(dev, cs.arrays, 1);
    std::size_t n = hits.size();
    std::vector<cl::Buffer> outs;
    for (int i = 0; i < 9; ++i)
        outs.emplace_back(dev.context, CL_MEM_WRITE_ONLY, n * sizeof(pcl_float4));
    cl::Buffer hit_buffer = upload(hits), wo_buffer = upload(wos); // alive until the kernel has run
    bind_kernel(k, arrays, hit_buffer, wo_buffer, outs[0], outs[1], outs[2], outs[3], outs[4], outs[5], outs[6],
                outs[7], outs[8]);
    dev.queue.enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(n));
    return {read_back(outs[0], n), read_back(outs[1], n), read_back(outs[2], n),
            read_back(outs[3], n), read_back(outs[4], n), read_back(outs[5], n),
            read_back(outs[6], n), read_back(outs[7], n), read_back(outs[8], n)};
}

glm::vec3 v3(const pcl_float4& p)
{
    return {p.x, p.y, p.z};
}

TEST(MaterialInputs, TexturesMultiplyTheirFactorsAndVertexColourTheBaseColour)
{
    // base = factor x sRGB texel x COLOR_0; metallic = factor x B, roughness = factor x G;
    // emission = factor x sRGB texel; specular = factor x A, specular colour = factor x
    // sRGB texel, transmission = factor x R. Broken variants seen to fail: metallic from G
    // and roughness from B (swapped channels); emission texels read as linear; specular
    // from R instead of A.
    Scene scene = textured_quad({});
    MaterialProbe p = probe(scene, {{0.2f, 0.3f}}, {{0.0f, 0.0f, 1.0f}});
    glm::vec3 base(0.8f * srgb8_to_linear(188) * 0.5f, 0.6f * srgb8_to_linear(128), 0.4f * srgb8_to_linear(64));
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(v3(p.base_color[0])[c], base[c], 1e-6f) << "base colour channel " << c;
    EXPECT_NEAR(p.params[0].x, 0.5f * 204.0f / 255.0f, 1e-6f) << "metallic";
    EXPECT_NEAR(p.params[0].y, 0.8f * 102.0f / 255.0f, 1e-6f) << "roughness";
    glm::vec3 emission(2.0f * srgb8_to_linear(255), 2.0f * srgb8_to_linear(128), 0.0f);
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(v3(p.emission[0])[c], emission[c], 1e-6f) << "emission channel " << c;
    EXPECT_NEAR(p.params[0].z, 0.8f * 153.0f / 255.0f, 1e-6f) << "specular";
    glm::vec3 specular_color(srgb8_to_linear(255), 0.5f * srgb8_to_linear(188), srgb8_to_linear(64));
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(v3(p.specular_color[0])[c], specular_color[c], 1e-6f) << "specular colour channel " << c;
    EXPECT_NEAR(p.params[0].w, 0.6f * 51.0f / 255.0f, 1e-6f) << "transmission";
    EXPECT_NEAR(p.coat[0].x, 0.9f * 102.0f / 255.0f, 1e-6f) << "clearcoat";
    EXPECT_NEAR(p.coat[0].y, 0.5f * 204.0f / 255.0f, 1e-6f) << "clearcoat roughness";
    glm::vec3 sheen(0.5f * srgb8_to_linear(200), srgb8_to_linear(100), 0.25f * srgb8_to_linear(50));
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(v3(p.sheen[0])[c], sheen[c], 1e-6f) << "sheen colour channel " << c;
    EXPECT_NEAR(p.sheen[0].w, 0.8f * 102.0f / 255.0f, 1e-6f) << "sheen roughness";
}

TEST(MaterialInputs, TheBasesNormalMapDoesNotBendTheClearCoat)
{
    // KHR_materials_clearcoat: without clearcoatNormalTexture the coat keeps the
    // interpolated normal (+z here) while the base's normal map tilts the shading normal.
    // Broken variant seen to fail: the coat normal taken after the normal map.
    QuadOptions o;
    o.normal_texel = {200, 128, 200, 255};
    MaterialProbe p = probe(textured_quad(o), {{0.2f, 0.3f}}, {{0.0f, 0.0f, 1.0f}});
    EXPECT_LT(p.normal[0].w, 0.95f) << "the base's normal is tilted";
    EXPECT_FLOAT_EQ(p.coat[0].z, 1.0f) << "the coat's is not";
}

// Gives the quad's coat a clearcoatNormalTexture of one texel, with `scale`.
std::function<void(test::GltfBuilder&, tinygltf::Material&)> coat_normal_map(std::vector<std::uint8_t> texel,
                                                                             double scale)
{
    return [texel, scale](test::GltfBuilder& b, tinygltf::Material& m) {
        tinygltf::Value::Object coat = m.extensions["KHR_materials_clearcoat"].Get<tinygltf::Value::Object>();
        tinygltf::Value info = test::texture_info(b.add_texture(b.add_png_image(1, 1, texel)));
        info.Get<tinygltf::Value::Object>()["scale"] = tinygltf::Value(scale);
        coat["clearcoatNormalTexture"] = info;
        m.extensions["KHR_materials_clearcoat"] = tinygltf::Value(coat);
    };
}

TEST(MaterialInputs, TheClearcoatNormalMapBendsOnlyTheCoat)
{
    // clearcoatNormalTexture tilts the coat's normal in the tangent frame, with its own
    // scale, from the interpolated normal: not from the base's mapped one, which it leaves
    // as it is. Texel (255, 0, 255), scale 0.5: n_t = (0.5, -0.5, 1); the base's texel
    // (64, 128, 255) tilts the base towards -x. With mirrored UVs the tangent is -x. Without
    // a normalTexture the tangents follow the coat's texture coordinates (computed here).
    // Broken variants seen to fail: the coat map applied to the base's mapped normal; the
    // base's scale used for the coat; no tangents without a normalTexture.
    for (bool mirrored : {false, true})
        for (bool base_map : {true, false}) {
            SCOPED_TRACE(std::string(mirrored ? "mirrored UVs" : "upright UVs") +
                         (base_map ? ", with a base normal map" : ", no base normal map"));
            QuadOptions o;
            o.mirrored_uv = mirrored;
            o.normal_texel = {64, 128, 255, 255};
            auto coat_map = coat_normal_map({255, 0, 255, 255}, 0.5);
            o.edit = [&](test::GltfBuilder& b, tinygltf::Material& m) {
                coat_map(b, m);
                if (!base_map)
                    m.normalTexture = tinygltf::NormalTextureInfo{};
            };
            MaterialProbe p = probe(textured_quad(o), {{0.3f, 0.3f}}, {{0.0f, 0.0f, 1.0f}});
            glm::dvec3 coat = glm::normalize(glm::dvec3(mirrored ? -0.5 : 0.5, -0.5, 1.0));
            glm::dvec3 got(v3(p.coat_normal[0]));
            EXPECT_LT(glm::length(got - coat), 1e-5) << got.x << " " << got.y << " " << got.z;
            double bx = 2.0 * 64.0 / 255.0 - 1.0, by = 2.0 * 128.0 / 255.0 - 1.0;
            glm::dvec3 base = base_map ? glm::normalize(glm::dvec3(mirrored ? -bx : bx, by, 1.0)) : glm::dvec3(0, 0, 1);
            glm::dvec3 ns(v3(p.normal[0]));
            EXPECT_LT(glm::length(ns - base), 1e-5) << ns.x << " " << ns.y << " " << ns.z;
        }
}

TEST(MaterialInputs, SpecularGlossinessTexturesGiveDiffuseSpecularColourAndRoughness)
{
    // KHR_materials_pbrSpecularGlossiness on the textured quad: base = diffuseFactor x sRGB
    // diffuse texel x COLOR_0, metallic 0, specular colour = specularFactor x sRGB texel,
    // roughness = 1 - glossinessFactor x the texel's linear alpha; the quad's
    // metallic-roughness, specular and transmission textures are not read. Broken
    // variants seen to fail: glossiness read from G as a metallic-roughness texel; the
    // fallback metallic-roughness texture kept.
    QuadOptions o;
    o.edit = [](test::GltfBuilder& b, tinygltf::Material& m) {
        tinygltf::Value::Object sg;
        sg["diffuseFactor"] = test::json_numbers({0.8, 0.6, 0.4, 1.0});
        sg["diffuseTexture"] = test::texture_info(b.add_texture(b.add_png_image(1, 1, {128, 188, 255, 255})));
        sg["specularFactor"] = test::json_numbers({0.5, 0.4, 0.3});
        sg["glossinessFactor"] = tinygltf::Value(0.8);
        sg["specularGlossinessTexture"] = test::texture_info(b.add_texture(b.add_png_image(1, 1, {255, 188, 64, 102})));
        m.extensions["KHR_materials_pbrSpecularGlossiness"] = tinygltf::Value(sg);
    };
    MaterialProbe p = probe(textured_quad(o), {{0.2f, 0.3f}}, {{0.0f, 0.0f, 1.0f}});
    glm::vec3 base(0.8f * srgb8_to_linear(128) * 0.5f, 0.6f * srgb8_to_linear(188), 0.4f * srgb8_to_linear(255));
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(v3(p.base_color[0])[c], base[c], 1e-6f) << "base colour channel " << c;
    EXPECT_EQ(p.params[0].x, 0.0f) << "metallic";
    EXPECT_NEAR(p.params[0].y, 1.0f - 0.8f * 102.0f / 255.0f, 1e-6f) << "roughness";
    EXPECT_EQ(p.params[0].z, 1.0f) << "specular";
    glm::vec3 specular_color(0.5f * srgb8_to_linear(255), 0.4f * srgb8_to_linear(188), 0.3f * srgb8_to_linear(64));
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(v3(p.specular_color[0])[c], specular_color[c], 1e-6f) << "specular colour channel " << c;
    EXPECT_EQ(p.params[0].w, 0.0f) << "transmission";
}

TEST(MaterialInputs, NormalMapTiltsAlongTheTangentFrame)
{
    // Texel (192, 80, 255) is n_t = (129, -95, 255) / 255 / |.|: towards +u (the
    // tangent) and "down" in the image (against the bitangent, which points up the image,
    // along -v: +y here). For an upright UV layout the tangent is +x; for a mirrored one
    // (u along -x) it is -x, with the bitangent still +y (handedness w = -1). Computed
    // and file tangents agree. Broken variants seen to fail: the bitangent without the
    // handedness sign (mirrored layouts); computed handedness from +dP/dv (the loader's
    // tangents.cpp); the normal map not applied.
    for (bool mirrored : {false, true})
        for (bool file_tangents : {false, true}) {
            SCOPED_TRACE(std::string(mirrored ? "mirrored UVs" : "upright UVs") +
                         (file_tangents ? ", TANGENT from the file" : ", computed tangents"));
            QuadOptions o;
            o.mirrored_uv = mirrored;
            o.file_tangents = file_tangents;
            o.normal_texel = {192, 80, 255, 255};
            MaterialProbe p = probe(textured_quad(o), {{0.3f, 0.3f}}, {{0.0f, 0.0f, 1.0f}});
            double right = 2.0 * 192.0 / 255.0 - 1.0, up = 2.0 * 80.0 / 255.0 - 1.0;
            glm::dvec3 expected = glm::normalize(glm::dvec3(mirrored ? -right : right, up, 1.0));
            glm::dvec3 got(v3(p.normal[0]));
            EXPECT_LT(glm::length(got - expected), 1e-5) << got.x << " " << got.y << " " << got.z;
        }
}

TEST(MaterialInputs, AnisotropyTurnsFromTheTangentByItsRotationAndTexture)
{
    // KHR_materials_anisotropy: without a texture the direction is (cos r, sin r) in the
    // tangent, bitangent frame (upright UVs: +x, +y; mirrored: -x, +y); with one, its RG
    // direction (linear, [0, 1] to [-1, 1], normalized) turned by r, and its B scales the
    // strength. Seen from behind (double-sided) the direction is the same. The frame is
    // the quad's tangent (+x or -x) made orthogonal to the (default, 8-bit, so not quite
    // flat) mapped normal. Broken variants seen to fail: the rotation
    // turned the other way; the texture's direction not turned by r; the bitangent without
    // the handedness sign (mirrored UVs).
    const double r = 0.5;
    for (bool mirrored : {false, true})
        for (bool textured : {false, true}) {
            SCOPED_TRACE(std::string(mirrored ? "mirrored UVs" : "upright UVs") + (textured ? ", texture" : ""));
            QuadOptions o;
            o.mirrored_uv = mirrored;
            o.double_sided = true;
            o.edit = [&](test::GltfBuilder& b, tinygltf::Material& m) {
                tinygltf::Value::Object a;
                a["anisotropyStrength"] = tinygltf::Value(0.8);
                a["anisotropyRotation"] = tinygltf::Value(r);
                if (textured)
                    a["anisotropyTexture"] =
                        test::texture_info(b.add_texture(b.add_png_image(1, 1, {64, 220, 153, 255})));
                m.extensions["KHR_materials_anisotropy"] = tinygltf::Value(a);
            };
            MaterialProbe p = probe(textured_quad(o), {{0.3f, 0.3f}, {0.3f, 0.3f}}, {{0, 0, 1}, {0.1f, 0.2f, -1}});
            glm::dvec2 d(1.0, 0.0);
            if (textured)
                d = glm::normalize(glm::dvec2(2.0 * 64.0 / 255.0 - 1.0, 2.0 * 220.0 / 255.0 - 1.0));
            glm::dvec2 turned(std::cos(r) * d.x - std::sin(r) * d.y, std::sin(r) * d.x + std::cos(r) * d.y);
            for (int k = 0; k < 2; ++k) {
                glm::dvec3 n(v3(p.normal[static_cast<std::size_t>(k)]));
                n = k == 0 ? n : -n; // the front side's normal
                glm::dvec3 tangent(mirrored ? -1.0 : 1.0, 0.0, 0.0);
                tangent = glm::normalize(tangent - glm::dot(tangent, n) * n);
                glm::dvec3 bitangent = (mirrored ? -1.0 : 1.0) * glm::cross(n, tangent);
                glm::dvec3 expected = turned.x * tangent + turned.y * bitangent;
                glm::dvec3 got(v3(p.anisotropy[static_cast<std::size_t>(k)]));
                EXPECT_LT(glm::length(got - expected), 1e-5)
                    << (k ? "back " : "front ") << got.x << " " << got.y << " " << got.z;
                EXPECT_NEAR(p.anisotropy[static_cast<std::size_t>(k)].w, textured ? 0.8 * 153.0 / 255.0 : 0.8, 1e-6);
            }
        }
}

TEST(MaterialInputs, NormalScaleAndBackFaces)
{
    // scale 0.5 halves the tangential part before normalizing; seen from behind (a
    // double-sided material) the mapped normal is the front one turned to the back.
    // Broken variants seen to fail: the scale applied to z too; the front normal used
    // unturned on the back side.
    QuadOptions o;
    o.normal_texel = {255, 0, 255, 255}; // n_t = (1, -1, 1)
    o.normal_scale = 0.5;
    o.double_sided = true;
    MaterialProbe p = probe(textured_quad(o), {{0.3f, 0.3f}, {0.3f, 0.3f}}, {{0.2f, 0.1f, 1.0f}, {0.2f, 0.1f, -1.0f}});
    glm::dvec3 front = glm::normalize(glm::dvec3(0.5, -0.5, 1.0));
    EXPECT_LT(glm::length(glm::dvec3(v3(p.normal[0])) - front), 1e-5);
    EXPECT_LT(glm::length(glm::dvec3(v3(p.normal[1])) + front), 1e-5);
}

TEST(MaterialInputs, NormalsBelowTheSurfaceAreBentBackAboveIt)
{
    // A normal map pointing into the surface, sideways, or exactly backwards (scale 0
    // leaves n_t = (0, 0, -1)), seen from many directions: the shading normal stays a
    // finite unit vector above the geometric surface, on wo's side, and the mirror
    // direction of wo leaves above the surface at no less than min(0.9 cos, 0.01).
    // Broken variant seen to fail: no bending (the normal stays below the surface and
    // every reflected direction is rejected: black).
    struct Case {
        std::vector<std::uint8_t> texel;
        double scale;
    };
    for (const Case& c : {Case{{255, 128, 0, 255}, 1.0}, Case{{255, 128, 128, 255}, 1.0}, Case{{128, 128, 0, 255}, 0.0},
                          Case{{0, 255, 20, 255}, 3.0}, Case{{128, 128, 255, 255}, 1.0}}) {
        QuadOptions o;
        o.normal_texel = c.texel;
        o.normal_scale = c.scale;
        std::vector<glm::vec2> bary;
        std::vector<glm::vec3> wo;
        for (int i = 0; i < 16; ++i) {
            double phi = 2.0 * std::numbers::pi * i / 16.0;
            for (double cos_o : {1.0, 0.5, 0.05, 1e-3}) {
                double s = std::sqrt(1.0 - cos_o * cos_o);
                bary.push_back({0.25f, 0.25f});
                wo.push_back(glm::vec3(glm::dvec3(s * std::cos(phi), s * std::sin(phi), cos_o)));
            }
        }
        MaterialProbe p = probe(textured_quad(o), bary, wo);
        for (std::size_t i = 0; i < wo.size(); ++i) {
            glm::dvec3 n(v3(p.normal[i])), w = glm::normalize(glm::dvec3(wo[i]));
            SCOPED_TRACE("texel " + std::to_string(c.texel[0]) + "," + std::to_string(c.texel[1]) + "," +
                         std::to_string(c.texel[2]) + " wo " + std::to_string(w.x) + "," + std::to_string(w.y) + "," +
                         std::to_string(w.z));
            ASSERT_TRUE(std::isfinite(n.x) && std::isfinite(n.y) && std::isfinite(n.z));
            EXPECT_NEAR(glm::length(n), 1.0, 1e-5);
            EXPECT_GT(n.z, 0.0) << "above the geometric surface";
            EXPECT_GT(glm::dot(n, w), 0.0) << "on wo's side";
            glm::dvec3 r = 2.0 * glm::dot(n, w) * n - w;
            EXPECT_GE(r.z, std::min(0.9 * w.z, 0.01) - 2e-5) << "mirror direction above the surface";
        }
    }
}

} // namespace
} // namespace pathcl::test_material_inputs
