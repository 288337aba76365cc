// KHR_materials_volume attenuation: Beer-Lambert absorption inside solids, against the
// analytic transmittance of a slab (with its Fresnel inter-reflections) and of a sphere
// (along the chord of the very mesh rendered); a thin-walled sheet absorbs nothing; and a
// rough absorbing glass sphere renders the same by BSDF sampling alone and by MIS (light
// samples taken from inside the sphere leave it). Next to each test: the deliberately
// broken variant seen to fail it.
#include <algorithm>
#include <cmath>
#include <iostream>
#include <numbers>

#include <gtest/gtest.h>

#include "compile/kernel_features.h"
#include "image/image_compare.h"
#include "render/renderer.h"
#include "scene/gltf_loader.h"
#include "support/expect_error.h"
#include "support/gltf_builder.h"
#include "support/render_checks.h"
#include "support/test_options.h"
#include "types.h"
#include <tiny_gltf.h>

namespace pathcl::test_volume_absorption {
namespace {

constexpr int kU16 = TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;

// A smooth white glass (transmission 1) of the given ior, a solid unless thin, with
// attenuationColor `color` at attenuationDistance `distance`.
int add_absorbing_glass(test::GltfBuilder& b, double ior, glm::dvec3 color, double distance, bool thin = false,
                        double roughness = 0.0)
{
    test::GltfBuilder::Pbr glass;
    glass.transmission = 1.0;
    glass.ior = ior;
    glass.roughness = roughness;
    int mat = b.add_pbr_material(glass);
    tinygltf::Value::Object volume;
    volume["thicknessFactor"] = tinygltf::Value(thin ? 0.0 : 1.0);
    volume["attenuationColor"] = tinygltf::Value(
        tinygltf::Value::Array{tinygltf::Value(color.x), tinygltf::Value(color.y), tinygltf::Value(color.z)});
    volume["attenuationDistance"] = tinygltf::Value(distance);
    b.material(mat).extensions["KHR_materials_volume"] = tinygltf::Value(volume);
    return mat;
}

// An emissive panel of radiance 1 in the plane z = -3 facing +z, and a camera with a
// 1e-4 rad field of view at (x, 0, 5) looking along -z.
void add_panel_and_camera(test::GltfBuilder& b, double x)
{
    int mat = b.add_material(glm::vec3(0.0f), glm::vec3(1.0f));
    b.add_root(b.add_node(b.add_quad_mesh({{-20, -20, -3}, {20, -20, -3}, {20, 20, -3}, {-20, 20, -3}}, mat)));
    b.add_camera_node(b.add_perspective_camera(1e-4), {x, 0.0, 5.0});
}

struct Measurement {
    glm::dvec3 mean{0.0}, stderr_{0.0};
    std::uint64_t bad = 0;
};

Measurement measure(const Scene& scene, std::uint32_t spp)
{
    RenderOptions o = test::independent_options();
    o.width = o.height = 4;
    o.spp = spp;
    o.max_bounces = 32;
    RenderResult r = render(scene, o);
    Measurement m;
    for (int c = 0; c < 3; ++c) {
        test::ChannelMean channel = test::channel_mean(r, c);
        m.mean[c] = channel.mean;
        m.stderr_[c] = channel.stderr_;
        m.bad = channel.bad;
    }
    return m;
}

void expect_transmittance(const Measurement& m, glm::dvec3 expected, const std::string& what)
{
    EXPECT_EQ(m.bad, 0u) << what;
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(m.mean[c], expected[c], 1e-4 * expected[c] + 5.0 * m.stderr_[c]) << what << ", channel " << c;
}

TEST(VolumeAbsorption, SlabTransmitsTheBeerLambertFractionWithItsInterreflections)
{
    // A 0.5 thick glass slab (ior 1.5) at normal incidence between the camera and a panel
    // of radiance 1, attenuationColor c at attenuationDistance 0.5, so one crossing keeps
    // tau = c. Each face reflects R = 0.04; light bounces back and forth inside, so the
    // panel is seen at (1 - R)^2 tau / (1 - R^2 tau^2). Broken variants seen to fail: no
    // absorption (all channels); the medium kept after leaving the slab (the panel's
    // 3-unit segment absorbed too).
    const glm::dvec3 c(0.3, 0.6, 0.9);
    test::GltfBuilder b;
    int mat = add_absorbing_glass(b, 1.5, c, 0.5);
    b.add_root(b.add_node(b.add_box_mesh({4.0f, 4.0f, 0.25f}, mat)));
    add_panel_and_camera(b, 0.3);
    Scene scene = import_gltf(b.model, "slab.gltf");
    EXPECT_TRUE(kernel_features(scene, RenderOptions{}).has(FEATURE_VOLUME_ABSORPTION));
    const double r = 0.04;
    glm::dvec3 expected = (1.0 - r) * (1.0 - r) * c / (1.0 - r * r * c * c);
    expect_transmittance(measure(scene, 4096), expected, "slab");
}

// Where the ray origin + t dir enters and leaves the triangles of material `material`
// (double-precision Moller-Trumbore over the scene as rendered): the chord's length.
double chord_length(const Scene& scene, int material, glm::dvec3 origin, glm::dvec3 dir)
{
    double t_in = INFINITY, t_out = -INFINITY;
    for (const SceneTriangle& tri : scene.triangles) {
        if (tri.material != material)
            continue;
        glm::dvec3 v0(tri.v[0]), e1 = glm::dvec3(tri.v[1]) - v0, e2 = glm::dvec3(tri.v[2]) - v0;
        glm::dvec3 p = glm::cross(dir, e2);
        double det = glm::dot(e1, p);
        if (det == 0.0)
            continue;
        glm::dvec3 s = origin - v0;
        double u = glm::dot(s, p) / det;
        glm::dvec3 q = glm::cross(s, e1);
        double v = glm::dot(dir, q) / det;
        if (u < 0.0 || v < 0.0 || u + v > 1.0)
            continue;
        double t = glm::dot(e2, q) / det;
        t_in = std::min(t_in, t);
        t_out = std::max(t_out, t);
    }
    return t_out - t_in;
}

TEST(VolumeAbsorption, SphereTransmitsExpOfMinusSigmaTimesTheChord)
{
    // A solid sphere of radius 1 with ior 1 (no refraction, no reflection) seen against the
    // panel through its centre and at half its radius: exp(-sigma L), sigma = -ln c / D,
    // L the chord through the tessellated sphere. Broken variant seen to fail: no
    // absorption. A thin-walled sheet of the same material absorbs nothing (glTF: no
    // volume without thickness); broken variant seen to fail: absorption inside thin
    // materials.
    const glm::dvec3 c(0.2, 0.5, 0.8);
    const double distance = 1.5;
    for (bool thin : {false, true})
        for (double x : {0.0, 0.5}) {
            test::GltfBuilder b;
            int mat = add_absorbing_glass(b, 1.0, c, distance, thin);
            b.add_root(b.add_node(b.add_sphere_mesh(1.0, 48, 96, mat, false)));
            add_panel_and_camera(b, x);
            Scene scene = import_gltf(b.model, "sphere.gltf");
            EXPECT_EQ(kernel_features(scene, RenderOptions{}).has(FEATURE_VOLUME_ABSORPTION), !thin);
            double chord = chord_length(scene, mat, scene.camera.position, scene.camera.forward);
            ASSERT_GT(chord, 1.5);
            glm::dvec3 expected = thin ? glm::dvec3(1.0) : glm::exp(glm::log(c) / distance * chord);
            std::string what = std::string(thin ? "thin" : "solid") + " sphere at x = " + std::to_string(x);
            expect_transmittance(measure(scene, 64), expected, what);
        }
}

TEST(VolumeAbsorption, RoughAbsorbingSphereRendersTheSameByBsdfSamplingAndMis)
{
    // A rough (0.3) absorbing glass sphere on a floor under an area light. Light samples
    // taken at the sphere's inner surface leave it through its surface (rough refraction)
    // and must not be absorbed on the way out; BSDF sampling finds the light by rays that
    // really leave. Broken variant seen to fail: light samples absorbed along their whole
    // segment whenever the path is inside.
    test::GltfBuilder b;
    int floor_mat = b.add_material(glm::vec3(0.7f));
    b.add_root(b.add_node(b.add_quad_mesh({{-3, 0, 3}, {3, 0, 3}, {3, 0, -3}, {-3, 0, -3}}, floor_mat)));
    int light_mat = b.add_material(glm::vec3(0.0f), glm::vec3(1.0f), false, 4.0);
    b.add_root(b.add_node(b.add_quad_mesh({{-1, 2.5, 1}, {-1, 2.5, -1}, {1, 2.5, -1}, {1, 2.5, 1}}, light_mat)));
    int glass = add_absorbing_glass(b, 1.5, {0.3, 0.6, 0.9}, 1.0, false, 0.3);
    b.add_root(b.add_node(b.add_sphere_mesh(0.6, 24, 48, glass, false, true), {}, {0.0, 0.6, 0.0}));
    b.add_camera_node(b.add_perspective_camera(0.6), {0.0, 0.6, 2.5}); // the sphere fills most of the view
    Scene scene = import_gltf(b.model, "rough-absorbing-sphere.gltf");

    RenderOptions o = test::independent_options();
    o.width = o.height = 32;
    o.spp = 2048;
    o.seed = 3;
    o.max_bounces = 8;
    test::expect_same_image_by_strategies(scene, o, {Strategy::Mis}, 512, 1); // MIS at seed 4
}

TEST(VolumeAbsorption, BadAttenuationIsAOneLineError)
{
    auto error_with = [](double distance, double red) {
        test::GltfBuilder b;
        add_absorbing_glass(b, 1.5, {red, 0.5, 0.5}, distance);
        b.add_root(b.add_node(b.add_box_mesh({1.0f, 1.0f, 1.0f}, 0)));
        return test::error_of([&] { import_gltf(b.model, "volume.gltf"); });
    };
    std::string e = error_with(0.0, 0.5);
    EXPECT_TRUE(test::contains(e, "volume.gltf: material 0") && test::contains(e, "attenuationDistance must be > 0"))
        << e;
    e = error_with(1.0, 1.5);
    EXPECT_TRUE(test::contains(e, "attenuationColor must lie in [0, 1]")) << e;
}

} // namespace
} // namespace pathcl::test_volume_absorption
