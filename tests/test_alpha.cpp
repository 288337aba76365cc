// glTF alpha (alphaMode MASK and BLEND) as geometry. Host: what the loader reads and
// which triangles the kernels test. Device: a cut-out card seen and casting its cut-out
// shadow, a 50% BLEND sheet passing half the light, two stacked sheets with independent
// coverage, and an alpha-cut emitter behind a sheet that every light-sampling strategy
// renders the same. Next to each test: the deliberately broken variant seen to fail it.
#include <cmath>
#include <iostream>
#include <numbers>

#include <glm/gtc/quaternion.hpp>
#include <gtest/gtest.h>

#include "compile/kernel_features.h"
#include "image/image_compare.h"
#include "render/renderer.h"
#include "scene/alpha_cutouts.h"
#include "scene/gltf_loader.h"
#include "support/expect_error.h"
#include "support/floor_probe.h"
#include "support/gltf_builder.h"
#include "support/render_checks.h"
#include "support/test_options.h"
#include "types.h"
#include <tiny_gltf.h>

namespace pathcl::test_alpha {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kFloor = test::kFloorAlbedo, kCard = 0.8;
constexpr int kNearest = 9728, kClamp = 33071;
constexpr int kU16 = TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
using test::kLookDown;
using test::slanted_down;

// A double-sided Lambertian card over x, z in [-1, 1] at height y facing up, with
// TEXCOORD_0 u = (x + 1) / 2, v = (z + 1) / 2; returns its material index.
int add_card(test::GltfBuilder& b, float y, float albedo, int* mesh_out = nullptr)
{
    int mat = b.add_material(glm::vec3(albedo), glm::vec3(0.0f), true);
    int mesh = b.add_quad_mesh({{-1, y, -1}, {-1, y, 1}, {1, y, 1}, {1, y, -1}}, mat);
    b.set_attribute(mesh, "TEXCOORD_0", b.add_texcoords({{0, 0}, {0, 1}, {1, 1}, {1, 0}}));
    b.add_root(b.add_node(mesh));
    if (mesh_out)
        *mesh_out = mesh;
    return mat;
}

// A float VEC4 COLOR_0 for a mesh's four vertices.
void set_vertex_alpha(test::GltfBuilder& b, int mesh, const std::vector<float>& alpha)
{
    std::vector<float> rgba;
    for (float a : alpha)
        rgba.insert(rgba.end(), {1.0f, 1.0f, 1.0f, a});
    int view = b.add_view(rgba.data(), rgba.size() * sizeof(float));
    b.set_attribute(mesh, "COLOR_0",
                    b.add_accessor(view, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC4, alpha.size()));
}

// ---------------------------------------------------------------------------------------
// Host

TEST(Alpha, ModeCutoffAndFactorAreRead)
{
    test::GltfBuilder b;
    int opaque = add_card(b, 0.0f, 0.5f);
    int mask = add_card(b, 1.0f, 0.5f);
    int blend = add_card(b, 2.0f, 0.5f);
    b.material(mask).alphaMode = "MASK";
    b.material(mask).alphaCutoff = 0.25;
    b.material(mask).pbrMetallicRoughness.baseColorFactor[3] = 0.2;
    b.material(blend).alphaMode = "BLEND";
    b.material(blend).pbrMetallicRoughness.baseColorFactor[3] = 0.6;
    Scene s = import_gltf(b.model, "alpha.gltf");
    const SceneMaterial& o = s.materials[static_cast<std::size_t>(opaque)];
    const SceneMaterial& m = s.materials[static_cast<std::size_t>(mask)];
    const SceneMaterial& l = s.materials[static_cast<std::size_t>(blend)];
    EXPECT_EQ(o.alpha_mode, AlphaMode::Opaque);
    EXPECT_EQ(o.alpha_cutoff, 0.5f); // the glTF default
    EXPECT_EQ(m.alpha_mode, AlphaMode::Mask);
    EXPECT_EQ(m.alpha_cutoff, 0.25f);
    EXPECT_EQ(m.alpha, 0.2f);
    EXPECT_EQ(l.alpha_mode, AlphaMode::Blend);
    EXPECT_EQ(l.alpha, 0.6f);
}

TEST(Alpha, BadValuesAreOneLineErrors)
{
    auto error_with = [](const std::function<void(tinygltf::Material&)>& edit) {
        test::GltfBuilder b;
        edit(b.material(add_card(b, 0.0f, 0.5f)));
        return test::error_of([&] { import_gltf(b.model, "alpha.gltf"); });
    };
    std::string e = error_with([](tinygltf::Material& m) { m.alphaMode = "blend"; });
    EXPECT_TRUE(test::contains(e, "alpha.gltf: material 0") &&
                test::contains(e, "alphaMode must be OPAQUE, MASK or BLEND"))
        << e;
    e = error_with([](tinygltf::Material& m) { m.alphaCutoff = -0.5; });
    EXPECT_TRUE(test::contains(e, "alphaCutoff must be finite and >= 0")) << e;
    e = error_with([](tinygltf::Material& m) { m.pbrMetallicRoughness.baseColorFactor[3] = 1.5; });
    EXPECT_TRUE(test::contains(e, "baseColorFactor must lie in [0, 1]")) << e;
}

TEST(Alpha, OnlyTrianglesAlphaCanCutAreTested)
{
    // Exporters mark opaque materials BLEND: alpha that cannot fall short of opaque (factor
    // x least texel alpha x least vertex alpha) leaves the triangle opaque and the program
    // without alpha code. Broken variant seen to fail: every MASK or BLEND triangle tested.
    struct Case {
        const char* what;
        const char* mode;
        double factor, cutoff;
        int texel_alpha;    // of the texture's second texel; < 0: no texture
        float vertex_alpha; // of the second vertex; < 0: no COLOR_0
        bool tested;
    };
    const Case cases[] = {
        {"opaque with alpha 0", "OPAQUE", 0.0, 0.5, 0, -1.0f, false},
        {"blend, alpha 1", "BLEND", 1.0, 0.5, -1, -1.0f, false},
        {"blend, factor 0.5", "BLEND", 0.5, 0.5, -1, -1.0f, true},
        {"blend, opaque texture", "BLEND", 1.0, 0.5, 255, -1.0f, false},
        {"blend, texel alpha 254", "BLEND", 1.0, 0.5, 254, -1.0f, true},
        {"mask, factor above cutoff", "MASK", 0.6, 0.5, -1, -1.0f, false},
        {"mask, factor below cutoff", "MASK", 0.4, 0.5, -1, -1.0f, true},
        {"mask, texel alpha 0", "MASK", 1.0, 0.5, 0, -1.0f, true},
        {"mask, texel alpha 0, cutoff 0", "MASK", 1.0, 0.0, 0, -1.0f, false},
        {"mask, vertex alpha 0.6", "MASK", 1.0, 0.5, -1, 0.6f, false},
        {"mask, vertex alpha 0.4", "MASK", 1.0, 0.5, -1, 0.4f, true},
    };
    for (const Case& c : cases) {
        test::GltfBuilder b;
        int mesh = 0;
        tinygltf::Material& m = b.material(add_card(b, 0.0f, 0.5f, &mesh));
        m.alphaMode = c.mode;
        m.alphaCutoff = c.cutoff;
        m.pbrMetallicRoughness.baseColorFactor[3] = c.factor;
        if (c.texel_alpha >= 0)
            m.pbrMetallicRoughness.baseColorTexture.index = b.add_texture(
                b.add_png_image(2, 1, {255, 255, 255, 255, 255, 255, 255, static_cast<std::uint8_t>(c.texel_alpha)}));
        if (c.vertex_alpha >= 0.0f)
            set_vertex_alpha(b, mesh, {1.0f, c.vertex_alpha, 1.0f, 1.0f});
        Scene s = import_gltf(b.model, "alpha.gltf");
        std::vector<bool> tested = alpha_tested_triangles(s);
        bool expected = c.tested;
        ASSERT_EQ(tested.size(), 2u);
        // Vertex 1 belongs to the first triangle only.
        EXPECT_EQ(tested[0] || tested[1], expected) << c.what;
        EXPECT_EQ(kernel_features(s, RenderOptions{}).has(FEATURE_ALPHA), expected) << c.what;
        if (c.vertex_alpha >= 0.0f && expected) {
            EXPECT_NE(tested[0], tested[1]) << c.what << ": only the triangle with the low vertex";
        }
    }
}

// ---------------------------------------------------------------------------------------
// Device

using Measurement = test::ChannelMean;

// Mean radiance (green) of the floor probe (tests/support/floor_probe.h: a Lambertian floor
// of albedo kFloor at y = 0 seen straight down from height 3) at (x, z).
Measurement radiance_at(const test::GltfBuilder& b, double x, double z, std::uint32_t spp)
{
    return test::floor_radiance_at(b, x, z, 1.0, Strategy::Mis, spp);
}

void expect_radiance(const Measurement& m, double expected, const std::string& what)
{
    EXPECT_EQ(m.bad, 0u) << what;
    // Float rounding: 1e-4 relative (plus 1e-7 for an expected 0); plus Monte Carlo.
    EXPECT_NEAR(m.mean, expected, 1e-4 * expected + 1e-7 + 5.0 * m.stderr_) << what;
}

// The light: directional, irradiance 1, at 45 degrees towards +X, so a card at height 1
// shadows the floor 1 further along +X.
const double kLit = std::cos(kPi / 4) / kPi; // radiance per unit albedo of a lit horizontal surface

void add_sun(test::GltfBuilder& b)
{
    b.add_light_node(b.add_light("directional", glm::vec3(1.0f), 1.0), {0.0, 5.0, 0.0}, slanted_down(kPi / 4));
}

TEST(Alpha, MaskedCardIsSeenAndCastsItsShadowOnlyWhereItIsOpaque)
{
    // The card at height 1 is opaque for x < 0 and cut away for x > 0, by its base colour
    // texture's alpha (texel 0 alpha 255, texel 1 alpha 0, nearest) or by COLOR_0 alpha
    // (1 at x = -1, 0 at x = 1, interpolated). Looking down: at x = -0.5 the lit card; at
    // 0.5 the floor through the cut, in the opaque half's shadow; at 1.5 the floor, lit
    // through the cut half (an opaque card would shadow it); at 2.5 the floor beyond.
    // Broken variants seen to fail: the closest hit ignoring alpha (x = 0.5 sees the card);
    // shadow rays ignoring alpha (x = 1.5 is black).
    for (bool by_texture : {true, false}) {
        test::GltfBuilder b;
        add_sun(b);
        int mesh = 0;
        tinygltf::Material& m = b.material(add_card(b, 1.0f, static_cast<float>(kCard), &mesh));
        m.alphaMode = "MASK";
        if (by_texture)
            m.pbrMetallicRoughness.baseColorTexture.index = b.add_texture(
                b.add_png_image(2, 1, {255, 255, 255, 255, 255, 255, 255, 0}), b.add_sampler(kNearest, kClamp, kClamp));
        else
            set_vertex_alpha(b, mesh, {1.0f, 1.0f, 0.0f, 0.0f});
        std::string what = by_texture ? "texture alpha, x = " : "vertex alpha, x = ";
        expect_radiance(radiance_at(b, -0.5, 0.3, 4), kCard * kLit, what + "-0.5");
        expect_radiance(radiance_at(b, 0.5, 0.3, 4), 0.0, what + "0.5");
        expect_radiance(radiance_at(b, 1.5, 0.3, 4), kFloor * kLit, what + "1.5");
        expect_radiance(radiance_at(b, 2.5, 0.3, 4), kFloor * kLit, what + "2.5");
    }
}

TEST(Alpha, HalfCoverageSheetPassesHalfTheLight)
{
    // A BLEND card of alpha a over x in [-1, 1]: the floor at x = 1.5 is lit through it
    // (exactly 1 - a: shadow rays pass 1 - alpha; a = 0.5 halves the light); at x = -0.5 a
    // camera ray sees the card (probability a) or the lit floor; at 0.5 the card or the
    // floor in the card's partial shadow. Broken variants seen to fail: shadow rays blocked
    // by the sheet (x = 1.5 is 0); the coin keeping a hit with probability 1 - alpha
    // (a = 0.25, x = -0.5 and 0.5).
    for (double a : {0.5, 0.25}) {
        test::GltfBuilder b;
        add_sun(b);
        tinygltf::Material& m = b.material(add_card(b, 1.0f, static_cast<float>(kCard)));
        m.alphaMode = "BLEND";
        m.pbrMetallicRoughness.baseColorFactor[3] = a;
        std::string what = "alpha " + std::to_string(a) + ", x = ";
        expect_radiance(radiance_at(b, 1.5, 0.3, 4), (1.0 - a) * kFloor * kLit, what + "1.5");
        expect_radiance(radiance_at(b, -0.5, 0.3, 4096), (a * kCard + (1.0 - a) * kFloor) * kLit, what + "-0.5");
        expect_radiance(radiance_at(b, 0.5, 0.3, 4096), (a * kCard + (1.0 - a) * (1.0 - a) * kFloor) * kLit,
                        what + "0.5");
    }
}

TEST(Alpha, StackedSheetsCoverIndependently)
{
    // Two black BLEND sheets of alpha 0.5 at heights 1 and 1.5 under a light straight
    // down: the floor is seen with probability 1/4 and lit at 1/4, so the radiance is
    // 1/16 of the open floor's. Broken variant seen to fail: one coin per ray for every
    // surface on it (pbrt-v4's hash of the ray alone), which sees the floor half the time.
    test::GltfBuilder b;
    b.add_light_node(b.add_light("directional", glm::vec3(1.0f), 1.0), {0.0, 5.0, 0.0}, kLookDown);
    for (float y : {1.0f, 1.5f}) {
        tinygltf::Material& m = b.material(add_card(b, y, 0.0f));
        m.alphaMode = "BLEND";
        m.pbrMetallicRoughness.baseColorFactor[3] = 0.5;
    }
    expect_radiance(radiance_at(b, 0.2, 0.3, 8192), kFloor / kPi / 16.0, "under both sheets");
}

TEST(Alpha, CutEmitterBehindASheetRendersTheSameByEveryStrategy)
{
    // An emissive panel facing down, cut by a 4 x 4 MASK checker in its texture's alpha,
    // lights a floor through a BLEND sheet of alpha 0.4 that covers half of it. BSDF
    // sampling alone finds the light only by rays that pass the sheet's coin and hit the
    // panel where it is not cut; light sampling must weigh its samples by the panel's
    // coverage and the sheet's transmission to agree. Broken variants seen to fail: light
    // samples ignoring the emitter's cut-outs (nee, mis); shadow rays blocked by the sheet.
    test::GltfBuilder b;
    int floor_mat = b.add_material(glm::vec3(0.7f));
    b.add_root(b.add_node(b.add_quad_mesh({{-3, 0, 3}, {3, 0, 3}, {3, 0, -3}, {-3, 0, -3}}, floor_mat)));
    int light_mat = b.add_material(glm::vec3(0.0f), glm::vec3(1.0f), false, 4.0);
    int light = b.add_quad_mesh({{-1, 1.5, 1}, {-1, 1.5, -1}, {1, 1.5, -1}, {1, 1.5, 1}}, light_mat);
    b.set_attribute(light, "TEXCOORD_0", b.add_texcoords({{0, 0}, {0, 1}, {1, 1}, {1, 0}}));
    std::vector<std::uint8_t> checker;
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x)
            checker.insert(checker.end(), {255, 255, 255, static_cast<std::uint8_t>((x + y) % 2 == 0 ? 255 : 0)});
    b.material(light_mat).alphaMode = "MASK";
    b.material(light_mat).pbrMetallicRoughness.baseColorTexture.index =
        b.add_texture(b.add_png_image(4, 4, checker), b.add_sampler(kNearest, kClamp, kClamp));
    b.add_root(b.add_node(light));
    int sheet_mat = b.add_material(glm::vec3(0.5f), glm::vec3(0.0f), true);
    b.material(sheet_mat).alphaMode = "BLEND";
    b.material(sheet_mat).pbrMetallicRoughness.baseColorFactor[3] = 0.4;
    b.add_root(b.add_node(b.add_quad_mesh({{-2, 0.7f, 2}, {0, 0.7f, 2}, {0, 0.7f, -2}, {-2, 0.7f, -2}}, sheet_mat)));
    b.add_camera_node(b.add_perspective_camera(1.2), {0.0, 0.9, 3.0}, {-0.1305, 0.0, 0.0, 0.9914});
    Scene scene = import_gltf(b.model, "cut-emitter.gltf");

    RenderOptions o = test::independent_options();
    o.width = o.height = 32;
    o.spp = 1024;
    o.seed = 5;
    o.max_bounces = 3;
    test::expect_same_image_by_strategies(scene, o, {Strategy::Nee, Strategy::Mis}, 256, 30);
}

} // namespace
} // namespace pathcl::test_alpha
