// What a loaded scene uses, counted for `pathcl info`: geometry, lights by type, materials
// by lobe, textures, the environment and the camera model.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "scene/scene.h"

namespace pathcl {

struct SceneSummary {
    std::size_t triangles = 0, dropped_degenerate = 0; // triangles drawn, instances included
    // Meshes stored once and drawn by instances, with their triangles (stored once each).
    std::size_t instances = 0, instanced_meshes = 0, stored_triangles = 0;
    std::size_t emissive_triangles = 0; // area lights
    std::size_t point_lights = 0, spot_lights = 0, rect_spot_lights = 0, directional_lights = 0, sphere_lights = 0;
    // Materials some triangle uses, by lobe (a material may count under several):
    // diffuse (base colour not fully metallic), metal, specular layer (a dielectric coat:
    // specular > 0 on the non-metallic part), transmission, emissive; and those with
    // textures or a normal map.
    std::size_t materials = 0, diffuse = 0, metal = 0, specular_layer = 0, transmission = 0, emissive = 0;
    std::size_t textured = 0, normal_mapped = 0;
    std::size_t images = 0, texels = 0;
    bool vertex_colors = false;
    std::string environment; // "none", "constant (r, g, b)" or "image W x H (file)"
    std::string camera;      // "perspective, vertical FOV 39.3 degrees, pinhole", ...
};

SceneSummary summarize_scene(const Scene& scene);

} // namespace pathcl
