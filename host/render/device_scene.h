// The scene as the kernels read it: BVH nodes, triangles in leaf order with their shading
// data and optional vertex attributes, materials and their textures, lights with their
// alias table, and the camera; built once on the host.
#pragma once

#include <cstdint>
#include <vector>

#include "bvh/bvh_builder.h"
#include "render/environment.h"
#include "render/textures.h"
#include "scene/scene.h"
#include "shared_types.h"

namespace pathcl {

struct DeviceScene {
    std::vector<BvhNode> nodes;
    std::vector<Triangle> triangles;
    std::vector<TriangleShading> shading;
    std::vector<Material> materials;
    DeviceTextures textures;                 // empty unless a material has a texture
    std::vector<TriangleTangents> tangents;  // leaf order; empty unless there are normal maps
    std::vector<TriangleColors> colors;      // leaf order; empty unless there are vertex colours
    std::vector<Light> lights; // spheres, emissive triangles, punctual; selection by power
    std::size_t sphere_count = 0; // lights[0 .. sphere_count) are sphere lights
    EnvironmentMap environment;   // empty unless the scene has one
    std::vector<float> layer_albedo; // LAYER_* tables; empty unless a material is glossy
    int environment_light = -1;   // its index in `lights`
    SceneFeatures features;
    Bvh bvh_stats; // depth and leaf figures (nodes moved into `nodes`)
    double bvh_build_seconds = 0.0;
};

DeviceScene make_device_scene(const Scene& scene);

// Fills the alias-table fields and pmf (radiance.w) of `lights` from their powers.
void build_light_alias_table(std::vector<Light>& lights, const std::vector<double>& power);

// Camera for an image of the given size: yfov (orthographic: ymag) is kept; the
// horizontal extent follows the image's aspect ratio.
Camera make_device_camera(const SceneCamera& cam, std::uint32_t width, std::uint32_t height);

} // namespace pathcl
