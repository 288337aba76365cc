// Renders with each light sampler (--light-sampler): with the light tree, every strategy
// matches the Cornell box's committed reference (MIS weighs a hit on a light by the tree's
// pmf at the vertex the ray left, so a wrong pmf there biases the image; shown to fail),
// and renders the power table's image of a scene with every light type at once and of a
// room lit by many small lamps of varied power, partly hidden; the uniform sampler
// matches the reference too; the tree's light samples deferred past the next traversal
// give the image of samples taken at once, bit for bit.
#include <cmath>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "image/image_compare.h"
#include "image/image_io.h"
#include "render/renderer.h"
#include "scene/gltf_loader.h"
#include "support/gltf_builder.h"
#include "support/same_image.h"
#include "support/test_options.h"

namespace pathcl::test_render_light_samplers {
namespace {

const std::string kSource = PATHCL_SOURCE_DIR;

// The settings of tests/references/cornell-box-64.exr, another seed.
RenderOptions reference_options(LightSampler sampler)
{
    RenderOptions o = test::independent_options();
    o.width = o.height = 64;
    o.spp = 256;
    o.max_bounces = 8;
    o.seed = 5;
    o.light_sampler = sampler;
    return o;
}

CompareReport against_reference(const std::string& name, const RenderOptions& o)
{
    Scene scene = load_gltf(kSource + "/scenes/" + name + ".gltf");
    RenderResult r = render(scene, o);
    EXPECT_EQ(r.stats.bad_samples, 0u) << name;
    CompareOptions co;
    co.pooled_variance = false; // another estimator than the reference's
    co.judge_pixels = o.strategy != Strategy::Bsdf;
    return compare_images(r.image, read_image(kSource + "/tests/references/" + name + "-64.exr"), co);
}

TEST(LightSamplers, TreeWithEveryStrategyMatchesTheCornellBoxReference)
{
    for (Strategy strategy : {Strategy::Nee, Strategy::OneSample, Strategy::Mis}) {
        RenderOptions o = reference_options(LightSampler::Tree);
        o.strategy = strategy;
        CompareReport cmp = against_reference("cornell-box", o);
        std::cout << "strategy " << strategy_name(strategy) << "\n" << cmp.summary();
        EXPECT_TRUE(cmp.passed) << "strategy " << strategy_name(strategy) << "\n" << cmp.summary();
    }
}

TEST(LightSamplers, TreePmfOffAtTheHitsFailsTheComparison)
{
    // light_tree_pmf 0 where the pick has the light's, which only MIS at a BSDF ray's hit
    // on a light reads: those hits take full weight beside the light samples, and direct
    // light counts about twice.
    RenderOptions o = reference_options(LightSampler::Tree);
    o.kernel_patches = {{"light/light_tree.cl", "        p *= weight[lane] / total;\n        if (child[lane] < 0) {",
                         "        p *= weight[lane] / total;\n        p *= 0.0f;\n        if (child[lane] < 0) {"}};
    CompareReport cmp = against_reference("cornell-box", o);
    EXPECT_FALSE(cmp.passed) << cmp.summary();
}

// Every light type at once, so that the tree weighs them against each other: an open
// room (floor and two walls) with an emissive quad, a point, a spot, a sphere light, a
// directional light and a constant environment.
Scene mixed_lights()
{
    test::GltfBuilder b;
    const int grey = b.add_material(glm::vec3(0.6f), glm::vec3(0.0f), /*double_sided=*/true);
    b.add_root(b.add_node(b.add_quad_mesh({{-1, 0, -1}, {-1, 0, 1}, {1, 0, 1}, {1, 0, -1}}, grey)));   // floor
    b.add_root(b.add_node(b.add_quad_mesh({{-1, 0, -1}, {1, 0, -1}, {1, 2, -1}, {-1, 2, -1}}, grey))); // back
    b.add_root(b.add_node(b.add_quad_mesh({{-1, 0, 1}, {-1, 0, -1}, {-1, 2, -1}, {-1, 2, 1}}, grey))); // left
    const int lamp = b.add_material(glm::vec3(0.0f), glm::vec3(4.0f, 3.0f, 2.0f));
    b.add_root(b.add_node(
        b.add_quad_mesh({{0.6f, 0.2f, -0.9f}, {0.9f, 0.2f, -0.9f}, {0.9f, 0.5f, -0.9f}, {0.6f, 0.5f, -0.9f}}, lamp)));
    b.add_light_node(b.add_light("point", {1.0f, 0.9f, 0.8f}, 0.8), {-0.5, 1.0, -0.5});
    b.add_light_node(b.add_light("spot", {0.6f, 0.8f, 1.0f}, 3.0, 0.2, 0.5), {0.3, 1.5, 0.0},
                     {-0.7071068, 0.0, 0.0, 0.7071068}); // pointing down
    tinygltf::Value::Object radius;
    radius["radius"] = tinygltf::Value(0.1);
    b.add_light_node(b.add_light("point", {0.9f, 1.0f, 0.7f}, 0.5, 0.0, 0.7853981634, tinygltf::Value(radius)),
                     {0.5, 0.6, 0.4});
    b.add_light_node(b.add_light("directional", {1.0f, 0.95f, 0.9f}, 0.6), {0.0, 0.0, 0.0},
                     {-0.3826834, 0.0, 0.0, 0.9238795});
    b.add_camera_node(b.add_perspective_camera(1.0), {0.0, 0.9, 2.4});
    Scene scene = import_gltf(b.model, "mixed-lights");
    scene.environment.present = true;
    scene.environment.constant = glm::vec3(0.2f, 0.25f, 0.3f);
    return scene;
}

TEST(LightSamplers, TreeRendersEveryLightTypeTogetherAsThePowerTableDoes)
{
    Scene scene = mixed_lights();
    RenderOptions o = reference_options(LightSampler::Power);
    o.width = o.height = 32;
    o.spp = 512;
    o.max_bounces = 3;
    RenderResult power = render(scene, o);
    o.light_sampler = LightSampler::Tree;
    o.seed = 8;
    RenderResult tree = render(scene, o);
    EXPECT_EQ(tree.stats.bad_samples, 0u);
    EXPECT_EQ(tree.stats.lights, 7u)
        << "two lamp triangles, a point, a spot, a sphere, a directional light, the environment";
    CompareOptions co;
    co.pooled_variance = false;
    CompareReport cmp = compare_images(tree.image, power.image, co);
    std::cout << cmp.summary();
    EXPECT_TRUE(cmp.passed) << cmp.summary();
}

// The light tree's light samples taken at once, on any device: the megakernel defers them
// past the next traversal where the compiler can prefetch (kernels/integrator/
// direct_light.cl; PoCL on x86-64).
const KernelPatch kLightSamplesAtOnce = {"integrator/direct_light.cl",
                                         "#if defined(PATHCL_LIGHT_TREE) && defined(PATHCL_PREFETCH)", "#if 0"};

TEST(LightSamplers, DeferredLightSamplesGiveTheImmediateImageBitForBit)
{
    // The deferred sample is added right after the next traversal, before anything the
    // next vertex adds, with the throughput and medium of its own vertex, and once more
    // after the last vertex. Every light type with the tree, and the features box (a
    // solid that absorbs, alpha, clearcoat, textures); six bounces, so that roulette ends
    // paths with a sample waiting. Where the device does not defer, both renders take
    // their samples at once. Broken variants seen to fail on PoCL: the sample added after
    // the next vertex's emission; the last vertex's sample dropped; the throughput read
    // when the sample is added instead of at its vertex.
    const std::vector<std::pair<std::string, Scene>> scenes = {
        {"every light type", mixed_lights()},
        {"features box", load_gltf(kSource + "/scenes/cornell-box-features.gltf")}};
    for (const auto& [name, scene] : scenes) {
        RenderOptions o = reference_options(LightSampler::Tree);
        o.width = o.height = 32;
        o.spp = 64;
        o.max_bounces = 6;
        const RenderResult deferred = render(scene, o);
        o.kernel_patches = {kLightSamplesAtOnce};
        const RenderResult at_once = render(scene, o);
        test::expect_same_image(at_once.image, deferred.image, name);
        double sum = 0.0;
        for (float v : at_once.image.rgb)
            sum += v;
        EXPECT_GT(sum / static_cast<double>(at_once.image.rgb.size()), 0.01) << name << ": lit";
    }
}

TEST(LightSamplers, UniformMatchesTheCornellBoxReference)
{
    CompareReport cmp = against_reference("cornell-box", reference_options(LightSampler::Uniform));
    EXPECT_TRUE(cmp.passed) << cmp.summary();
}

// A closed room (1 x 1 x 1) with a dividing wall, lit by a grid of small lamps on the
// ceiling whose powers span three decades; the camera sees both halves.
Scene many_lamps_room()
{
    test::GltfBuilder b;
    const int grey = b.add_material(glm::vec3(0.6f), glm::vec3(0.0f), /*double_sided=*/true); // walls seen from inside
    b.add_root(b.add_node(b.add_box_mesh(glm::vec3(0.5f), grey)));
    b.add_root(b.add_node(
        b.add_quad_mesh({{0.1f, -0.5f, -0.5f}, {0.1f, -0.5f, 0.3f}, {0.1f, 0.3f, 0.3f}, {0.1f, 0.3f, -0.5f}}, grey)));
    for (int i = 0; i < 8; ++i) {
        for (int j = 0; j < 8; ++j) {
            const float power = std::pow(10.0f, static_cast<float>((i * 8 + j) % 7) / 2.0f);
            const int lamp = b.add_material(glm::vec3(0.0f), glm::vec3(power, 0.8f * power, 0.6f * power));
            const float x = -0.45f + 0.12f * static_cast<float>(i), z = -0.45f + 0.12f * static_cast<float>(j);
            // Facing down (counter-clockwise seen from below).
            b.add_root(b.add_node(b.add_quad_mesh(
                {{x, 0.49f, z}, {x + 0.02f, 0.49f, z}, {x + 0.02f, 0.49f, z + 0.02f}, {x, 0.49f, z + 0.02f}}, lamp)));
        }
    }
    b.add_camera_node(b.add_perspective_camera(1.2), {-0.3, 0.0, 0.45});
    return import_gltf(b.model, "many-lamps");
}

TEST(LightSamplers, TreeRendersTheManyLampRoomThePowerTableRenders)
{
    Scene room = many_lamps_room();
    RenderOptions o = reference_options(LightSampler::Power);
    o.width = o.height = 32;
    o.spp = 256;
    o.max_bounces = 4;
    RenderResult power = render(room, o);
    o.light_sampler = LightSampler::Tree;
    o.seed = 6;
    RenderResult tree = render(room, o);
    EXPECT_EQ(tree.stats.bad_samples, 0u);
    CompareOptions co;
    co.pooled_variance = false;
    CompareReport cmp = compare_images(tree.image, power.image, co);
    std::cout << cmp.summary();
    EXPECT_TRUE(cmp.passed) << cmp.summary();
    // Not vacuous: the room is lit.
    double red = 0.0;
    for (std::size_t i = 0; i < power.image.rgb.size(); i += 3)
        red += power.image.rgb[i];
    EXPECT_GT(red / static_cast<double>(power.image.rgb.size() / 3), 0.01);
}

} // namespace
} // namespace pathcl::test_render_light_samplers
