// A probe for direct lighting: a camera with a 1e-3 rad field of view looking straight
// down at one point of a large Lambertian floor, so the image's mean is the radiance
// there, rho / pi * E, with E the irradiance the lights give that point. The punctual
// light tests and the alpha tests add their lights (and occluders) to the scene.
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include <glm/gtc/quaternion.hpp>

#include "render/renderer.h"
#include "scene/gltf_loader.h"
#include "support/gltf_builder.h"
#include "support/render_checks.h"
#include "support/test_options.h"

namespace pathcl::test {

// The floor's albedo.
constexpr double kFloorAlbedo = 0.5;

// Rotation turning a node's -Z (where cameras look and lights shine) to world -Y.
inline const std::vector<double> kLookDown = {-std::sqrt(0.5), 0.0, 0.0, std::sqrt(0.5)};

// Node rotation that makes -Z point along (sin a, -cos a, 0): down and towards +X.
inline std::vector<double> slanted_down(double a)
{
    glm::dquat q =
        glm::angleAxis(a, glm::dvec3(0, 0, 1)) * glm::dquat(kLookDown[3], kLookDown[0], kLookDown[1], kLookDown[2]);
    return {q.x, q.y, q.z, q.w};
}

// Mean radiance (green channel) of a tiny patch of the floor y = 0 (100 x height_scale
// wide) around (x, 0, z), seen from height 3 x height_scale, with direct light only
// (max_bounces 1), lit by what the caller added to `b`.
inline ChannelMean floor_radiance_at(GltfBuilder b, double x, double z, double height_scale = 1.0,
                                     Strategy strategy = Strategy::Mis, std::uint32_t spp = 4)
{
    double s = 50.0 * height_scale;
    std::vector<glm::vec3> quad = {{-s, 0, -s}, {-s, 0, s}, {s, 0, s}, {s, 0, -s}}; // normal +Y
    int mat = b.add_material(glm::vec3(static_cast<float>(kFloorAlbedo)));
    int mesh = b.add_quad_mesh(quad, mat);
    b.add_root(b.add_node(mesh));
    b.add_camera_node(b.add_perspective_camera(1e-3), {x, 3.0 * height_scale, z}, kLookDown);
    RenderOptions o = independent_options();
    o.width = o.height = 8;
    o.spp = spp;
    o.max_bounces = 1;
    o.strategy = strategy;
    return channel_mean(render(import_gltf(b.model, "floor-probe.gltf"), o), 1);
}

} // namespace pathcl::test
