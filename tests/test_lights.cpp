// Punctual lights against their analytic values. A camera with a 1e-3 rad field of view
// looks straight down at one point of a Lambertian plane (albedo rho) and so measures the
// radiance there, rho / pi * E, with E the irradiance the light gives that point. With
// delta lights and one bounce the estimate is nearly noise-free, so tolerances are tight.
#include <cmath>
#include <numbers>

#include <glm/gtc/quaternion.hpp>
#include <gtest/gtest.h>

#include "render/renderer.h"
#include "scene/gltf_loader.h"
#include "support/floor_probe.h"
#include "support/gltf_builder.h"
#include "support/test_options.h"
#include "types.h"

namespace pathcl::test_lights {
namespace {

constexpr double kRho = test::kFloorAlbedo;
constexpr double kPi = std::numbers::pi;
using test::kLookDown;
using test::slanted_down;
using Measurement = test::ChannelMean;

Measurement radiance_at(const test::GltfBuilder& b, double x, double z, double height_scale,
                        Strategy strategy = Strategy::Mis, std::uint32_t spp = 4)
{
    return test::floor_radiance_at(b, x, z, height_scale, strategy, spp);
}

void expect_radiance(const Measurement& m, double expected, const std::string& what)
{
    EXPECT_EQ(m.bad, 0u) << what;
    // Float rounding and the patch's 1e-3 rad extent: 1e-4 relative; plus Monte Carlo.
    EXPECT_NEAR(m.mean, expected, 1e-4 * expected + 5.0 * m.stderr_) << what;
}

TEST(PointLight, InverseSquareLawAtHeights1em2To100)
{
    for (double h : {1e-2, 1.0, 100.0}) {
        test::GltfBuilder b;
        b.add_light_node(b.add_light("point", glm::vec3(1.0f), 3.0), {0.0, h, 0.0});
        expect_radiance(radiance_at(b, 0.0, 0.0, h), kRho / kPi * 3.0 / (h * h), "height " + std::to_string(h));
    }
}

TEST(PointLight, OffAxisPointFollowsCosineOverDistanceSquared)
{
    test::GltfBuilder b;
    b.add_light_node(b.add_light("point", glm::vec3(1.0f), 2.0), {0.0, 1.0, 0.0});
    double x = 0.75, d2 = x * x + 1.0, cos_theta = 1.0 / std::sqrt(d2);
    expect_radiance(radiance_at(b, x, 0.0, 1.0), kRho / kPi * 2.0 * cos_theta / d2, "off axis");
}

TEST(PointLight, OneTenThousandthAboveTheSurfaceStaysFinite)
{
    test::GltfBuilder b;
    b.add_light_node(b.add_light("point", glm::vec3(1.0f), 1.0), {0.0, 1e-4, 0.0});
    Measurement m = radiance_at(b, 0.0, 0.0, 1e-4); // camera and patch scaled with the height
    EXPECT_EQ(m.bad, 0u);
    EXPECT_TRUE(std::isfinite(m.mean));
    EXPECT_NEAR(m.mean, kRho / kPi * 1e8, 1e-4 * kRho / kPi * 1e8);
}

TEST(PointLight, EveryStrategyButBsdfGivesTheSameValue)
{
    // bsdf cannot find a delta light (documented); one-sample picks the light technique
    // half the time and doubles it.
    test::GltfBuilder b;
    b.add_light_node(b.add_light("point", glm::vec3(1.0f), 1.0), {0.0, 1.0, 0.0});
    const double expected = kRho / kPi;
    expect_radiance(radiance_at(b, 0.0, 0.0, 1.0, Strategy::Nee), expected, "nee");
    expect_radiance(radiance_at(b, 0.0, 0.0, 1.0, Strategy::OneSample, 1024), expected, "one-sample");
    EXPECT_EQ(radiance_at(b, 0.0, 0.0, 1.0, Strategy::Bsdf).mean, 0.0);
}

TEST(SpotLight, ConeFalloffInsideBetweenAndOutside)
{
    // Spot pointing down from height 1: inner 20 deg, outer 30 deg. A plane point at
    // distance x from the axis sees the light at angle atan(x) off the axis.
    const double inner = 20.0 * kPi / 180.0, outer = 30.0 * kPi / 180.0, intensity = 4.0;
    for (double angle_deg : {0.0, 10.0, 22.0, 25.0, 28.0, 31.0, 45.0}) {
        test::GltfBuilder b;
        b.add_light_node(b.add_light("spot", glm::vec3(1.0f), intensity, inner, outer), {0.0, 1.0, 0.0}, kLookDown);
        double a = angle_deg * kPi / 180.0, x = std::tan(a), d2 = 1.0 + x * x, c = std::cos(a);
        double t = std::clamp((c - std::cos(outer)) / std::max(0.001, std::cos(inner) - std::cos(outer)), 0.0, 1.0);
        double expected = kRho / kPi * intensity * t * t * c / d2;
        Measurement m = radiance_at(b, x, 0.0, 1.0);
        if (expected == 0.0)
            EXPECT_EQ(m.mean, 0.0) << "outside the cone at " << angle_deg << " deg";
        else
            expect_radiance(m, expected, "angle " + std::to_string(angle_deg));
    }
}

TEST(SpotLight, RectangularFrustumHasHardEdges)
{
    // hfov 40 deg (along node +X = world +X), vfov 20 deg (node +Y = world -Z here).
    tinygltf::Value::Object extras;
    extras["hfov"] = tinygltf::Value(40.0);
    extras["vfov"] = tinygltf::Value(20.0);
    const double intensity = 2.0;
    const double th = std::tan(20.0 * kPi / 180.0), tv = std::tan(10.0 * kPi / 180.0);
    struct Case {
        double x, z;
        bool lit;
    };
    for (Case k : {Case{0.0, 0.0, true}, Case{0.95 * th, 0.0, true}, Case{1.05 * th, 0.0, false},
                   Case{0.0, 0.95 * tv, true}, Case{0.0, -1.05 * tv, false}, Case{0.9 * th, 0.9 * tv, true}}) {
        test::GltfBuilder b;
        b.add_light_node(b.add_light("spot", glm::vec3(1.0f), intensity, 0.0, 0.5, tinygltf::Value(extras)),
                         {0.0, 1.0, 0.0}, kLookDown);
        double d2 = 1.0 + k.x * k.x + k.z * k.z, c = 1.0 / std::sqrt(d2);
        Measurement m = radiance_at(b, k.x, k.z, 1.0);
        std::string what = "at x " + std::to_string(k.x) + " z " + std::to_string(k.z);
        if (k.lit)
            expect_radiance(m, kRho / kPi * intensity * c / d2, what);
        else
            EXPECT_EQ(m.mean, 0.0) << what;
    }
}

// A point light with extras.radius: a sphere of radius r.
int add_sphere_light(test::GltfBuilder& b, double intensity, double radius, const std::vector<double>& at)
{
    tinygltf::Value::Object extras;
    extras["radius"] = tinygltf::Value(radius);
    return b.add_light_node(b.add_light("point", glm::vec3(1.0f), intensity, 0.0, 0.5, tinygltf::Value(extras)), at);
}

TEST(SphereLight, IrradianceEqualsThePointLightsForEveryStrategy)
{
    // A uniformly radiant sphere wholly above the horizon gives E = I cos(theta) / d^2,
    // exactly a point light's, whatever its radius. It hangs beside the camera's view.
    // bsdf finds it by chance: more samples.
    const double d2 = 0.6 * 0.6 + 1.0, expected = kRho / kPi * 2.0 / d2 / std::sqrt(d2);
    for (Strategy strategy : {Strategy::Bsdf, Strategy::Nee, Strategy::OneSample, Strategy::Mis}) {
        test::GltfBuilder b;
        add_sphere_light(b, 2.0, 0.2, {0.6, 1.0, 0.0});
        Measurement m = radiance_at(b, 0.0, 0.0, 1.0, strategy, strategy == Strategy::Bsdf ? 4096 : 256);
        EXPECT_GT(m.stderr_, 0.0);
        EXPECT_LT(m.stderr_, 0.02 * expected) << "too noisy to test, strategy " << strategy_name(strategy);
        expect_radiance(m, expected, "strategy " + std::string(strategy_name(strategy)));
    }
}

TEST(SphereLight, SeenDirectlyItHasRadianceIntensityOverPiRSquared)
{
    test::GltfBuilder b;
    add_sphere_light(b, 3.0, 0.5, {0.0, 0.0, -4.0});
    b.add_camera_node(b.add_perspective_camera(0.05), {0.0, 0.0, 0.0});
    RenderOptions o = test::independent_options();
    o.width = o.height = 4;
    o.spp = 4;
    RenderResult r = render(import_gltf(b.model, "sphere-view"), o);
    for (float v : r.image.rgb)
        EXPECT_NEAR(v, 3.0 / (kPi * 0.25), 1e-5);
}

TEST(SphereLight, CameraInsideAndSphereTouchingASurfaceStayFinite)
{
    { // the camera inside the sphere sees its back side: black, finite
        test::GltfBuilder b;
        add_sphere_light(b, 1.0, 2.0, {0.0, 0.0, 0.0});
        b.add_camera_node(b.add_perspective_camera(1.0), {0.0, 0.0, 0.0});
        RenderOptions o = test::independent_options();
        o.width = o.height = 8;
        o.spp = 4;
        RenderResult r = render(import_gltf(b.model, "inside-sphere"), o);
        EXPECT_EQ(r.stats.bad_samples, 0u);
        for (float v : r.image.rgb)
            EXPECT_EQ(v, 0.0f);
    }
    { // a sphere resting on the plane: the contact point and its surroundings
        test::GltfBuilder b;
        add_sphere_light(b, 1.0, 0.25, {0.0, 0.25, 0.0});
        for (double x : {0.0, 1e-4, 0.3}) {
            Measurement m = radiance_at(b, x, 0.0, 1.0, Strategy::Mis, 16);
            EXPECT_EQ(m.bad, 0u) << "x " << x;
            EXPECT_TRUE(std::isfinite(m.mean)) << "x " << x;
        }
    }
}

TEST(DirectionalLight, IrradianceIsIntensityTimesCosine)
{
    const double a = 60.0 * kPi / 180.0;
    test::GltfBuilder b;
    b.add_light_node(b.add_light("directional", glm::vec3(1.0f), 1.5), {0.0, 5.0, 0.0}, slanted_down(a));
    expect_radiance(radiance_at(b, 0.3, -0.2, 1.0), kRho / kPi * 1.5 * std::cos(a), "directional");
}

TEST(DirectionalLight, AnOccluderOutOfViewCastsAShadow)
{
    // Light at 45 deg towards +X; a square at height 1 around x = -1 shadows the plane
    // around x = 0 (the camera, straight above, does not see the square).
    auto scene_with_blocker = [] {
        test::GltfBuilder b;
        b.add_light_node(b.add_light("directional", glm::vec3(1.0f), 1.0), {0.0, 5.0, 0.0}, slanted_down(kPi / 4));
        std::vector<glm::vec3> sq = {{-1.1f, 1, -0.1f}, {-0.9f, 1, -0.1f}, {-0.9f, 1, 0.1f}, {-1.1f, 1, 0.1f}};
        int mat = b.add_material(glm::vec3(0.5f), glm::vec3(0.0f), true);
        b.add_root(b.add_node(b.add_quad_mesh(sq, mat)));
        return b;
    };
    EXPECT_EQ(radiance_at(scene_with_blocker(), 0.0, 0.0, 1.0).mean, 0.0) << "in the shadow";
    expect_radiance(radiance_at(scene_with_blocker(), 0.5, 0.0, 1.0), kRho / kPi * std::cos(kPi / 4), "beside it");
}

} // namespace
} // namespace pathcl::test_lights
