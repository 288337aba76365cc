// The scene compiled for the device: the light distribution selects each light with
// exactly its stored pmf (power-proportional), the camera keeps yfov while the image sets
// the aspect ratio, and emissive triangles become lights in leaf order, each naming its
// BVH leaf.
#include <cmath>
#include <cstdint>

#include <gtest/gtest.h>

#include "compile/light_distribution.h"
#include "light/light_pick.h"
#include "support/compiled_scene.h"

namespace pathcl::test_compile_scene {
namespace {

// Probability that light_pick() in kernels/light/light_pick.cl returns each light, from
// the table: every step k of the 2^24 grid, slot (k n) >> 24, counted directly.
std::vector<double> implied_probabilities(const std::vector<LightAliasEntry>& lights)
{
    std::size_t n = lights.size();
    std::vector<std::uint64_t> steps(n, 0);
    for (std::uint64_t k = 0; k < LIGHT_PICK_GRID; ++k)
        ++steps[(k * n) >> 24];
    std::vector<double> p(n, 0.0);
    for (std::size_t j = 0; j < n; ++j) {
        double slot = static_cast<double>(steps[j]) / LIGHT_PICK_GRID;
        double keep = static_cast<double>(lights[j].alias_threshold) / LIGHT_PICK_GRID;
        p[j] += slot * keep;
        p[static_cast<std::size_t>(lights[j].alias)] += slot * (1.0 - keep);
    }
    return p;
}

TEST(LightAliasTable, SelectsEachLightWithItsPowerFraction)
{
    // Broken variant seen failing: the pmf set to the power fraction rather than the
    // probability the grid realizes (the 1e-12 light is picked far more often than that).
    std::vector<double> power = {1.0, 1e-6, 250.0, 3.0, 3.0, 0.5, 1e3, 7.0, 1e-12};
    std::vector<LightAliasEntry> lights = build_light_distribution(power);
    double total = 0.0;
    for (double p : power)
        total += p;
    std::vector<double> implied = implied_probabilities(lights);
    for (std::size_t i = 0; i < power.size(); ++i) {
        // The pmf the estimator divides by is exactly how often the kernel picks the light.
        EXPECT_NEAR(lights[i].pmf, implied[i], 1e-7 * implied[i]) << "pmf of light " << i;
        // And it is the power fraction, to one step of the grid.
        EXPECT_NEAR(implied[i], power[i] / total, 1e-6 * power[i] / total + 1.0 / LIGHT_PICK_GRID)
            << "selection of light " << i;
        EXPECT_GT(implied[i], 0.0) << "every light stays pickable";
    }
}

TEST(LightAliasTable, PickProbabilitiesStayExactWithManyLights)
{
    // 3e5 slots on a 2^24 grid: slots get 55 or 56 steps (2 % apart); the pmf follows.
    std::vector<double> power(300000, 1.0);
    std::vector<LightAliasEntry> lights = build_light_distribution(power);
    std::vector<double> implied = implied_probabilities(lights);
    double sum = 0.0;
    for (std::size_t i = 0; i < lights.size(); ++i) {
        ASSERT_NEAR(lights[i].pmf, implied[i], 1e-7 * implied[i]) << "light " << i;
        sum += implied[i];
    }
    EXPECT_NEAR(sum, 1.0, 1e-9);
}

TEST(LightAliasTable, SingleLightIsAlwaysPicked)
{
    std::vector<LightAliasEntry> lights = build_light_distribution({42.0});
    EXPECT_EQ(lights[0].pmf, 1.0f);
    EXPECT_DOUBLE_EQ(implied_probabilities(lights)[0], 1.0);
}

TEST(DeviceCamera, ImageAspectWinsAndYfovIsKept)
{
    SceneCamera cam;
    cam.yfov = 0.5;
    Camera c = compile_camera(cam, 400, 200);
    EXPECT_NEAR(std::hypot(c.up.x, c.up.y, c.up.z), std::tan(0.25), 1e-6);
    EXPECT_NEAR(std::hypot(c.right.x, c.right.y, c.right.z), 2.0 * std::tan(0.25), 1e-6);
    EXPECT_FLOAT_EQ(c.forward.z, -1.0f);
}

TEST(CompileScene, EmissiveTrianglesBecomeLightsInLeafOrder)
{
    Scene s;
    s.materials.resize(2);
    s.materials[1].emission = glm::vec3(2.0f);
    for (int i = 0; i < 100; ++i) { // more leaves than a node holds: more than one node
        SceneTriangle t;
        float x = static_cast<float>(i);
        t.v[0] = {x, 0, 0};
        t.v[1] = {x + 1, 0, 0};
        t.v[2] = {x, 1, 0};
        for (auto& n : t.n)
            n = {0, 0, 1};
        t.material = (i % 3 == 0) ? 1 : 0;
        s.triangles.push_back(t);
    }
    CompiledScene cs = test::compile_default(s);
    const SceneArrays& a = cs.arrays;
    ASSERT_EQ(a.lights.size(), 34u);
    ASSERT_GT(a.nodes.size(), 1u);
    EXPECT_TRUE(cs.features.has(FEATURE_AREA_LIGHTS));
    for (std::size_t i = 0; i < a.triangles.size(); ++i) {
        int e = a.shading[i].emitter;
        if (a.shading[i].material == 1) {
            ASSERT_GE(e, 0);
            // The light holds the same triangle the BVH leaf holds.
            const TriangleLight& l = a.lights[static_cast<std::size_t>(e)].data.triangle;
            EXPECT_EQ(l.v0.x, a.triangles[i].v0.x);
            EXPECT_EQ(l.triangle, static_cast<pcl_int>(i));
            EXPECT_NEAR(l.area, 0.5f, 1e-6f);
            // And names the BVH leaf its shadow rays end in: a node whose slot names a
            // block that holds the triangle.
            const Light& light = a.lights[static_cast<std::size_t>(e)];
            ASSERT_GE(light.leaf_node, 0);
            ASSERT_LT(static_cast<std::size_t>(light.leaf_node), a.nodes.size());
            ASSERT_GE(light.leaf_block, 0);
            ASSERT_LT(static_cast<std::size_t>(light.leaf_block), a.triangle_blocks.size());
            bool named = false;
            for (int k = 0; k < BVH_WIDTH; ++k)
                named = named || (a.nodes[static_cast<std::size_t>(light.leaf_node)].count.s[k] > 0 &&
                                  a.nodes[static_cast<std::size_t>(light.leaf_node)].index.s[k] == light.leaf_block);
            EXPECT_TRUE(named) << "light " << e;
            bool held = false;
            for (pcl_int t : a.triangle_blocks[static_cast<std::size_t>(light.leaf_block)].triangle.s)
                held = held || t == static_cast<pcl_int>(i);
            EXPECT_TRUE(held) << "light " << e;
        } else {
            EXPECT_EQ(e, -1);
        }
    }
}

} // namespace
} // namespace pathcl::test_compile_scene
