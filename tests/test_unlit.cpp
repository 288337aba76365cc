// KHR_materials_unlit on the device: the base colour is radiance the camera sees directly
// and through delta bounces; it lights nothing, scatters nothing and still blocks light.
// Next to each test: a broken variant seen to fail it.
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "compile/kernel_features.h"
#include "render/renderer.h"
#include "scene/gltf_loader.h"
#include "support/floor_probe.h"
#include "support/gltf_builder.h"
#include "support/render_checks.h"
#include "support/test_options.h"

namespace pathcl::test_unlit {
namespace {

constexpr double kPi = std::numbers::pi;
const glm::vec3 kUnlitColour(0.3f, 0.6f, 0.9f);

// An unlit quad at height `y` over x, z in [-1, 1], facing +Y (or -Y); returns its material.
int add_unlit_quad(test::GltfBuilder& b, float y, bool facing_down)
{
    std::vector<glm::vec3> up = {{-1, y, -1}, {-1, y, 1}, {1, y, 1}, {1, y, -1}};
    std::vector<glm::vec3> down = {{-1, y, -1}, {1, y, -1}, {1, y, 1}, {-1, y, 1}};
    int mat = b.add_material(kUnlitColour);
    tinygltf::Material& m = b.material(mat);
    m.extensions["KHR_materials_unlit"] = tinygltf::Value(tinygltf::Value::Object{});
    m.emissiveFactor = {5.0, 5.0, 5.0}; // ignored: an unlit material is no light
    int mesh = b.add_quad_mesh(facing_down ? down : up, mat);
    b.add_root(b.add_node(mesh));
    return mat;
}

void expect_radiance(const test::ChannelMean& m, double expected, const std::string& what)
{
    EXPECT_EQ(m.bad, 0u) << what;
    EXPECT_NEAR(m.mean, expected, 1e-4 * expected + 1e-7 + 5.0 * m.stderr_) << what;
}

TEST(Unlit, SeenAsItsBaseColourAndCastsAShadow)
{
    // The floor probe (tests/support/floor_probe.h) under a directional light at 45 degrees
    // towards +X: at x = 0 the camera sees the unlit quad (height 1): exactly its green 0.6,
    // whatever the light; at 1.5 the floor in its shadow; at -1.5 the lit floor. Broken
    // variants seen to fail: the quad shaded as a lit diffuse surface; its emissiveFactor
    // kept.
    test::GltfBuilder b;
    b.add_light_node(b.add_light("directional", glm::vec3(1.0f), 1.0), {0.0, 5.0, 0.0}, test::slanted_down(kPi / 4));
    add_unlit_quad(b, 1.0f, false);
    expect_radiance(test::floor_radiance_at(b, 0.0, 0.3), kUnlitColour.y, "the quad");
    expect_radiance(test::floor_radiance_at(b, 1.5, 0.3), 0.0, "its shadow");
    expect_radiance(test::floor_radiance_at(b, -1.5, 0.3), test::kFloorAlbedo * std::cos(kPi / 4) / kPi, "lit floor");
    Scene s = import_gltf(b.model, "unlit.gltf");
    EXPECT_TRUE(kernel_features(s, RenderOptions{}).has(FEATURE_UNLIT));
    EXPECT_FALSE(kernel_features(s, RenderOptions{}).has(FEATURE_AREA_LIGHTS));
}

// The camera at height 3 looks straight down at a floor (y = 0) of material `floor`; the
// unlit quad hangs at height 5 facing down, behind the camera; no lights.
test::ChannelMean floor_under_unlit_quad(const test::GltfBuilder::Pbr& floor)
{
    test::GltfBuilder b;
    add_unlit_quad(b, 5.0f, true);
    std::vector<glm::vec3> quad = {{-50, 0, -50}, {-50, 0, 50}, {50, 0, 50}, {50, 0, -50}};
    int mesh = b.add_quad_mesh(quad, b.add_pbr_material(floor));
    b.add_root(b.add_node(mesh));
    b.add_camera_node(b.add_perspective_camera(1e-3), {0.0, 3.0, 0.0}, test::kLookDown);
    RenderOptions o = test::independent_options();
    o.width = o.height = 8;
    o.spp = 16;
    o.max_bounces = 6;
    return test::channel_mean(render(import_gltf(b.model, "unlit-mirror.gltf"), o), 1);
}

TEST(Unlit, SeenInAMirrorButLightsNothing)
{
    // A smooth white metal floor mirrors the quad: its green exactly. A white Lambertian
    // or rough metal floor gets nothing from it (no light in the scene): 0. Broken
    // variants seen to fail: unlit seen only by camera rays (the mirror is black); unlit
    // seen by every ray (the diffuse floor is lit).
    test::GltfBuilder::Pbr mirror;
    mirror.metallic = 1.0;
    mirror.roughness = 0.0;
    expect_radiance(floor_under_unlit_quad(mirror), kUnlitColour.y, "mirror");
    test::GltfBuilder::Pbr diffuse;
    diffuse.roughness = 1.0;
    diffuse.specular = 0.0;
    expect_radiance(floor_under_unlit_quad(diffuse), 0.0, "diffuse floor");
    test::GltfBuilder::Pbr rough_metal = mirror;
    rough_metal.roughness = 0.5;
    expect_radiance(floor_under_unlit_quad(rough_metal), 0.0, "rough metal floor");
}

} // namespace
} // namespace pathcl::test_unlit
