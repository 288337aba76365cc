// Cameras on the host (no device): glTF orthographic cameras and --camera N, the thin lens
// from node extras, the command-line overrides (--fov, --look-from/--look-at/--up,
// --aperture, --focus-distance), the device camera's layout, and how each sampler rounds
// spp. The rays these cameras make are tested on the device (test_camera_render.cpp).
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "common/error.h"
#include "sampling/samplers.h"
#include "scene/camera_overrides.h"
#include "scene/gltf_loader.h"
#include "support/compiled_scene.h"
#include "support/gltf_builder.h"
#include "types.h"

namespace pathcl::test_camera {
namespace {

using test::GltfBuilder;

int add_orthographic_camera(GltfBuilder& b, double xmag, double ymag)
{
    tinygltf::Camera cam;
    cam.type = "orthographic";
    cam.orthographic.xmag = xmag;
    cam.orthographic.ymag = ymag;
    cam.orthographic.znear = 0.01;
    cam.orthographic.zfar = 100.0;
    b.model.cameras.push_back(cam);
    return static_cast<int>(b.model.cameras.size()) - 1;
}

tinygltf::Value object(const std::vector<std::pair<std::string, tinygltf::Value>>& members)
{
    tinygltf::Value::Object o;
    for (const auto& [k, v] : members)
        o[k] = v;
    return tinygltf::Value(o);
}

// A triangle and one camera node at (1, 2, 3) with the given extras, scaled by 2.
GltfBuilder one_camera(bool orthographic, const tinygltf::Value& extras = {})
{
    GltfBuilder b;
    b.add_root(b.add_node(
        b.add_mesh(b.add_positions({{0, 0, -1}, {1, 0, -1}, {0, 1, -1}}), -1, b.add_material(glm::vec3(0.5f)))));
    int cam = orthographic ? add_orthographic_camera(b, 4.0, 1.5) : b.add_perspective_camera(0.6);
    int node = b.add_node(-1, {}, {1.0, 2.0, 3.0}, {}, {2.0, 2.0, 2.0});
    b.model.nodes[static_cast<std::size_t>(node)].camera = cam;
    b.model.nodes[static_cast<std::size_t>(node)].extras = extras;
    b.add_root(node);
    return b;
}

TEST(CameraImport, OrthographicKeepsYmagAndTheNodeFrame)
{
    // Exact: ymag is the file's; node scale 2 changes neither ymag nor the frame.
    Scene s = import_gltf(one_camera(true).model, "ortho.gltf");
    EXPECT_TRUE(s.camera.orthographic);
    EXPECT_EQ(s.camera.ymag, 1.5);
    EXPECT_EQ(s.camera.forward, glm::dvec3(0, 0, -1));
    EXPECT_EQ(s.camera.up, glm::dvec3(0, 1, 0));
    EXPECT_EQ(s.camera.right, glm::dvec3(1, 0, 0));
    EXPECT_EQ(s.camera.position + s.render_origin, glm::dvec3(1, 2, 3));
    EXPECT_EQ(s.camera.aperture, 0.0);
}

TEST(CameraImport, OrthographicWithoutPositiveYmagIsAnError)
{
    GltfBuilder b = one_camera(true);
    b.model.cameras[0].orthographic.ymag = 0.0;
    EXPECT_THROW(import_gltf(b.model, "ortho.gltf"), Error);
    b.model.cameras[0].orthographic.ymag = -1.0;
    EXPECT_THROW(import_gltf(b.model, "ortho.gltf"), Error);
}

TEST(CameraImport, ThinLensFromNodeExtrasInWorldUnits)
{
    // Exact: the extras' values, not scaled by the node's scale 2 (docs/gltf.md).
    Scene s = import_gltf(
        one_camera(false, object({{"aperture", tinygltf::Value(0.05)}, {"focusDistance", tinygltf::Value(3.5)}})).model,
        "lens.gltf");
    EXPECT_EQ(s.camera.aperture, 0.05);
    EXPECT_EQ(s.camera.focus_distance, 3.5);
    EXPECT_TRUE(kernel_features(s, RenderOptions{}).has(FEATURE_THIN_LENS));
    // Aperture 0 is a pinhole: no lens code compiled.
    Scene p = import_gltf(
        one_camera(false, object({{"aperture", tinygltf::Value(0.0)}, {"focusDistance", tinygltf::Value(3.5)}})).model,
        "pinhole.gltf");
    EXPECT_FALSE(kernel_features(p, RenderOptions{}).has(FEATURE_THIN_LENS));
}

TEST(CameraImport, BadThinLensExtrasAreErrors)
{
    using V = tinygltf::Value;
    for (const tinygltf::Value& extras :
         {object({{"aperture", V(0.1)}}), object({{"aperture", V(-0.1)}, {"focusDistance", V(2.0)}}),
          object({{"aperture", V(0.1)}, {"focusDistance", V(0.0)}}),
          object({{"aperture", V(std::string("wide"))}, {"focusDistance", V(2.0)}})})
        EXPECT_THROW(import_gltf(one_camera(false, extras).model, "lens.gltf"), Error);
}

TEST(CameraImport, CameraIndexBeyondTheCameraNodesIsAnErrorNamingTheCount)
{
    try {
        import_gltf(one_camera(false).model, "one.gltf", "", {1, ""});
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("camera: there is no camera node 1: one.gltf has 1 camera node"),
                  std::string::npos)
            << e.what();
    }
    // No camera at all: --camera 0 is an error, the default frames the scene.
    GltfBuilder b;
    b.add_root(b.add_node(
        b.add_mesh(b.add_positions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}), -1, b.add_material(glm::vec3(0.5f)))));
    EXPECT_THROW(import_gltf(b.model, "none.gltf", "", {0, ""}), Error);
    EXPECT_FALSE(import_gltf(b.model, "none.gltf").camera.from_file);
}

// A scene whose render space is offset from world space, with a camera at world (0, 0, 5)
// looking down -Z.
Scene offset_scene()
{
    Scene s;
    s.render_origin = glm::dvec3(100.0, -50.0, 20.0);
    s.camera.position = glm::dvec3(0.0, 0.0, 5.0) - s.render_origin;
    return s;
}

TEST(CameraOverrides, LookFromLookAtUpBuildARightHandedFrameInWorldSpace)
{
    // Tolerance 1e-12. From world (1, 1, 1) towards world (1, 1, -4) with an up hint
    // leaning towards +X: forward -Z, up +X, right = forward x up = -Y (render space is
    // world space minus render_origin).
    Scene s = offset_scene();
    CameraOverrides o;
    o.look_from = glm::dvec3(1, 1, 1);
    o.look_at = glm::dvec3(1, 1, -4);
    o.up = glm::dvec3(2, 0, 0.5); // not orthogonal to forward: only a hint
    apply_camera_overrides(s, o);
    const SceneCamera& c = s.camera;
    EXPECT_LT(glm::length(c.position + s.render_origin - glm::dvec3(1, 1, 1)), 1e-12);
    EXPECT_LT(glm::length(c.forward - glm::dvec3(0, 0, -1)), 1e-12);
    EXPECT_LT(glm::length(c.up - glm::dvec3(1, 0, 0)), 1e-12);
    EXPECT_LT(glm::length(c.right - glm::cross(c.forward, c.up)), 1e-12);
    EXPECT_LT(std::abs(glm::length(c.right) - 1.0), 1e-12);
}

TEST(CameraOverrides, LookAtAloneKeepsThePositionAndFovIsDegrees)
{
    Scene s = offset_scene();
    CameraOverrides o;
    o.look_at = glm::dvec3(3, 0, 1); // from world (0, 0, 5): direction (3, 0, -4) / 5
    o.fov_degrees = 90.0;
    apply_camera_overrides(s, o);
    EXPECT_LT(glm::length(s.camera.position + s.render_origin - glm::dvec3(0, 0, 5)), 1e-12);
    EXPECT_LT(glm::length(s.camera.forward - glm::dvec3(0.6, 0, -0.8)), 1e-12);
    EXPECT_DOUBLE_EQ(s.camera.yfov, std::numbers::pi / 2.0);
}

TEST(CameraOverrides, InconsistentValuesAreErrorsNamingTheParameter)
{
    // The library names parameters (the CLI names them by their flags: Cli tests).
    auto error_of = [](Scene s, const CameraOverrides& o) {
        try {
            apply_camera_overrides(s, o);
        } catch (const ParameterError& e) {
            return e.parameter() + " | " + e.what();
        }
        return std::string();
    };
    auto starts = [](const std::string& s, const std::string& prefix) { return s.rfind(prefix, 0) == 0; };
    CameraOverrides same;
    same.look_from = same.look_at = glm::dvec3(1, 2, 3);
    EXPECT_TRUE(starts(error_of(offset_scene(), same), "look_at | look_at: must differ"));
    CameraOverrides parallel;
    parallel.look_at = glm::dvec3(0, 10, 5); // straight up from (0, 0, 5), camera up is +Y
    EXPECT_TRUE(starts(error_of(offset_scene(), parallel), "up | up: must not be parallel"));
    CameraOverrides fov;
    fov.fov_degrees = 180.0;
    EXPECT_TRUE(starts(error_of(offset_scene(), fov), "fov | fov: must be in (0, 180)"));
    Scene ortho = offset_scene();
    ortho.camera.orthographic = true;
    fov.fov_degrees = 40.0;
    EXPECT_TRUE(starts(error_of(ortho, fov), "fov | fov: the selected camera is orthographic"));
    CameraOverrides lens;
    lens.aperture = 0.1; // no focus distance anywhere
    EXPECT_TRUE(starts(error_of(offset_scene(), lens), "aperture | aperture: needs focus_distance"));
    lens.aperture = -0.1;
    lens.focus_distance = 2.0;
    EXPECT_TRUE(starts(error_of(offset_scene(), lens), "aperture | aperture: must be >= 0"));
    lens.aperture = 0.1;
    EXPECT_EQ(error_of(offset_scene(), lens), "");
}

TEST(DeviceCamera, OrthographicKeepsYmagAndTheImageSetsTheWidth)
{
    // Exact up to float rounding (1e-6): up carries ymag, right ymag * width / height.
    SceneCamera cam;
    cam.orthographic = true;
    cam.ymag = 1.5;
    Camera c = compile_camera(cam, 300, 100);
    EXPECT_EQ(c.type, CAMERA_ORTHOGRAPHIC);
    EXPECT_NEAR(std::hypot(c.up.x, c.up.y, c.up.z), 1.5, 1e-6);
    EXPECT_NEAR(std::hypot(c.right.x, c.right.y, c.right.z), 4.5, 1e-6);
    EXPECT_EQ(c.lens_radius, 0.0f);
}

TEST(DeviceCamera, ThinLensCarriesRadiusAndFocusDistance)
{
    SceneCamera cam;
    cam.aperture = 0.25;
    cam.focus_distance = 7.0;
    Camera c = compile_camera(cam, 64, 64);
    EXPECT_EQ(c.type, CAMERA_PERSPECTIVE);
    EXPECT_EQ(c.lens_radius, 0.25f);
    EXPECT_EQ(c.focus_distance, 7.0f);
}

TEST(SamplerSpp, RoundingAsDocumented)
{
    // Jittered and multi-jittered: the next square; Hammersley: the next power of two;
    // the others: as asked.
    for (SamplerType s : {SamplerType::Jittered, SamplerType::MultiJittered}) {
        EXPECT_EQ(sampler_spp(s, 1), 1u);
        EXPECT_EQ(sampler_spp(s, 2), 4u);
        EXPECT_EQ(sampler_spp(s, 50), 64u);
        EXPECT_EQ(sampler_spp(s, 64), 64u);
        EXPECT_EQ(sampler_spp(s, 65), 81u);
        EXPECT_EQ(sampler_spp(s, 1u << 30), 1u << 30);
        EXPECT_EQ(sampler_spp(s, (1u << 30) - 1), 1u << 30);
    }
    EXPECT_EQ(sampler_spp(SamplerType::Hammersley, 1), 1u);
    EXPECT_EQ(sampler_spp(SamplerType::Hammersley, 3), 4u);
    EXPECT_EQ(sampler_spp(SamplerType::Hammersley, 64), 64u);
    EXPECT_EQ(sampler_spp(SamplerType::Hammersley, 65), 128u);
    EXPECT_EQ(sampler_spp(SamplerType::Hammersley, (1u << 30) - 5), 1u << 30);
    for (SamplerType s : {SamplerType::Independent, SamplerType::NRooks, SamplerType::Sobol, SamplerType::Halton})
        EXPECT_EQ(sampler_spp(s, 50), 50u);
    EXPECT_THROW(sampler_spp(static_cast<SamplerType>(SAMPLER_COUNT), 4), Error);
    // The names --sampler takes, one per sampler.
    EXPECT_EQ(sampler_names().size(), static_cast<std::size_t>(SAMPLER_COUNT));
    for (std::uint32_t s = 0; s < SAMPLER_COUNT; ++s)
        EXPECT_EQ(sampler_names().at(sampler_name(static_cast<SamplerType>(s))), static_cast<SamplerType>(s));
}

} // namespace
} // namespace pathcl::test_camera
