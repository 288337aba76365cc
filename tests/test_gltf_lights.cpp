// KHR_lights_punctual import: types, the rectangular-spot extras, the node frame, render
// space, and clear errors for bad light data.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "common/error.h"
#include "scene/gltf_loader.h"
#include "support/gltf_builder.h"

namespace pathcl::test_gltf_lights {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(GltfLights, TypesIntensityAndNodeFrame)
{
    test::GltfBuilder b;
    b.add_light_node(b.add_light("point", glm::vec3(1.0f, 0.5f, 0.25f), 8.0), {1.0, 2.0, 3.0});
    b.add_light_node(b.add_light("spot", glm::vec3(1.0f), 2.0, 0.1, 0.4), {0.0, 0.0, 0.0},
                     {0.0, std::sqrt(0.5), 0.0, std::sqrt(0.5)}); // 90 deg about +Y: -Z -> -X
    b.add_light_node(b.add_light("directional", glm::vec3(1.0f), 3.0), {0.0, 0.0, 0.0});
    Scene s = import_gltf(b.model, "lights.gltf");
    ASSERT_EQ(s.lights.size(), 3u);
    const SceneLight& p = s.lights[0];
    EXPECT_EQ(p.type, SceneLight::Type::Point);
    EXPECT_EQ(p.intensity, glm::vec3(8.0f, 4.0f, 2.0f));
    glm::dvec3 world = p.position + s.render_origin;
    EXPECT_NEAR(glm::length(world - glm::dvec3(1, 2, 3)), 0.0, 1e-12);
    const SceneLight& spot = s.lights[1];
    EXPECT_EQ(spot.type, SceneLight::Type::Spot);
    EXPECT_NEAR(spot.cos_inner, std::cos(0.1), 1e-12);
    EXPECT_NEAR(spot.cos_outer, std::cos(0.4), 1e-12);
    EXPECT_NEAR(glm::length(spot.direction - glm::dvec3(-1, 0, 0)), 0.0, 1e-12);
    EXPECT_EQ(s.lights[2].type, SceneLight::Type::Directional);
    EXPECT_NEAR(glm::length(s.lights[2].direction - glm::dvec3(0, 0, -1)), 0.0, 1e-12);
}

TEST(GltfLights, SpotWithHfovVfovExtrasIsRectangular)
{
    test::GltfBuilder b;
    tinygltf::Value::Object extras;
    extras["hfov"] = tinygltf::Value(60.0);
    extras["vfov"] = tinygltf::Value(30.0);
    b.add_light_node(b.add_light("spot", glm::vec3(1.0f), 1.0, 0.0, 0.5, tinygltf::Value(extras)), {0, 0, 0});
    Scene s = import_gltf(b.model, "rect.gltf");
    ASSERT_EQ(s.lights.size(), 1u);
    EXPECT_EQ(s.lights[0].type, SceneLight::Type::RectSpot);
    EXPECT_NEAR(s.lights[0].tan_half_h, std::tan(30.0 * kPi / 180.0), 1e-12);
    EXPECT_NEAR(s.lights[0].tan_half_v, std::tan(15.0 * kPi / 180.0), 1e-12);
    EXPECT_NEAR(glm::length(s.lights[0].right - glm::dvec3(1, 0, 0)), 0.0, 1e-12);
}

TEST(GltfLights, PointWithRadiusIsASphereScaledWithItsNode)
{
    test::GltfBuilder b;
    tinygltf::Value::Object extras;
    extras["radius"] = tinygltf::Value(0.5);
    int light = b.add_light("point", glm::vec3(1.0f), 2.0, 0.0, 0.5, tinygltf::Value(extras));
    int node = b.add_light_node(light, {0, 0, 0});
    b.model.nodes[static_cast<std::size_t>(node)].scale = {3.0, 3.0, 3.0};
    Scene s = import_gltf(b.model, "sphere.gltf");
    ASSERT_EQ(s.lights.size(), 1u);
    EXPECT_EQ(s.lights[0].type, SceneLight::Type::Sphere);
    EXPECT_NEAR(s.lights[0].radius, 1.5, 1e-12);
}

TEST(GltfLights, BadLightDataIsAnErrorNamingTheFile)
{
    auto error_of = [](test::GltfBuilder b) {
        try {
            import_gltf(b.model, "bad-light.gltf");
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    {
        test::GltfBuilder b;
        b.add_light_node(7, {0, 0, 0}); // no such light
        EXPECT_NE(error_of(b).find("bad-light.gltf"), std::string::npos) << error_of(b);
    }
    {
        test::GltfBuilder b;
        b.add_light_node(b.add_light("laser", glm::vec3(1.0f), 1.0), {0, 0, 0});
        EXPECT_NE(error_of(b).find("unknown light type \"laser\""), std::string::npos) << error_of(b);
    }
    {
        test::GltfBuilder b;
        b.add_light_node(b.add_light("point", glm::vec3(1.0f), -2.0), {0, 0, 0});
        EXPECT_NE(error_of(b).find("non-negative"), std::string::npos) << error_of(b);
    }
    {
        test::GltfBuilder b;
        tinygltf::Value::Object extras;
        extras["radius"] = tinygltf::Value(-1.0);
        b.add_light_node(b.add_light("point", glm::vec3(1.0f), 1.0, 0.0, 0.5, tinygltf::Value(extras)), {0, 0, 0});
        EXPECT_NE(error_of(b).find("radius must be a positive number"), std::string::npos) << error_of(b);
    }
    {
        test::GltfBuilder b;
        b.add_light_node(b.add_light("spot", glm::vec3(1.0f), 1.0, 0.5, 0.3), {0, 0, 0}); // inner > outer
        EXPECT_NE(error_of(b).find("cone angles"), std::string::npos) << error_of(b);
    }
}

} // namespace
} // namespace pathcl::test_gltf_lights
