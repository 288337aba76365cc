// Device-scene construction: the light alias table selects each light with exactly its
// stored pmf (power-proportional), and the camera keeps yfov while the image sets the
// aspect ratio.
#include <cmath>

#include <gtest/gtest.h>

#include "render/device_scene.h"

namespace pathcl {
namespace {

// Probability that light_pick() in kernels/lights.cl returns each light, from the table.
std::vector<double> implied_probabilities(const std::vector<Light>& lights)
{
    std::vector<double> p(lights.size(), 0.0);
    double n = static_cast<double>(lights.size());
    for (std::size_t i = 0; i < lights.size(); ++i) {
        double keep = std::min(1.0, static_cast<double>(lights[i].alias_threshold));
        p[i] += keep / n;
        p[static_cast<std::size_t>(lights[i].alias)] += (1.0 - keep) / n;
    }
    return p;
}

TEST(LightAliasTable, SelectsEachLightWithItsPowerFraction)
{
    std::vector<double> power = {1.0, 1e-6, 250.0, 3.0, 3.0, 0.5, 1e3, 7.0};
    std::vector<Light> lights(power.size());
    build_light_alias_table(lights, power);
    double total = 0.0;
    for (double p : power)
        total += p;
    std::vector<double> implied = implied_probabilities(lights);
    for (std::size_t i = 0; i < power.size(); ++i) {
        EXPECT_NEAR(lights[i].radiance.w, power[i] / total, 1e-7 * power[i] / total + 1e-12) << "pmf of light " << i;
        EXPECT_NEAR(implied[i], power[i] / total, 1e-6 * power[i] / total + 1e-9) << "selection of light " << i;
    }
}

TEST(LightAliasTable, SingleLightIsAlwaysPicked)
{
    std::vector<Light> lights(1);
    build_light_alias_table(lights, {42.0});
    EXPECT_EQ(lights[0].radiance.w, 1.0f);
    EXPECT_DOUBLE_EQ(implied_probabilities(lights)[0], 1.0);
}

TEST(DeviceCamera, ImageAspectWinsAndYfovIsKept)
{
    SceneCamera cam;
    cam.yfov = 0.5;
    Camera c = make_device_camera(cam, 400, 200);
    EXPECT_NEAR(std::hypot(c.up.x, c.up.y, c.up.z), std::tan(0.25), 1e-6);
    EXPECT_NEAR(std::hypot(c.right.x, c.right.y, c.right.z), 2.0 * std::tan(0.25), 1e-6);
    EXPECT_FLOAT_EQ(c.forward.z, -1.0f);
}

TEST(DeviceScene, EmissiveTrianglesBecomeLightsInLeafOrder)
{
    Scene s;
    s.materials.resize(2);
    s.materials[1].emission = glm::vec3(2.0f);
    for (int i = 0; i < 10; ++i) {
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
    DeviceScene ds = make_device_scene(s);
    ASSERT_EQ(ds.lights.size(), 4u);
    EXPECT_TRUE(ds.features.area_lights);
    for (std::size_t i = 0; i < ds.triangles.size(); ++i) {
        int e = ds.shading[i].emitter;
        if (ds.shading[i].material == 1) {
            ASSERT_GE(e, 0);
            // The light holds the same triangle the BVH leaf holds.
            EXPECT_EQ(ds.lights[static_cast<std::size_t>(e)].p0.x, ds.triangles[i].v0.x);
            EXPECT_NEAR(ds.lights[static_cast<std::size_t>(e)].p0.w, 0.5f, 1e-6f); // area
        } else {
            EXPECT_EQ(e, -1);
        }
    }
}

} // namespace
} // namespace pathcl
