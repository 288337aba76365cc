// Command-line changes to the scene's camera (--fov, --look-from/--look-at/--up,
// --aperture, --focus-distance), applied after the glTF camera (or the framing camera)
// was chosen. Positions are world space, as in the file.
#pragma once

#include <optional>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace pathcl {

struct CameraOverrides {
    std::optional<double> fov_degrees;    // full vertical field of view (perspective only)
    std::optional<glm::dvec3> look_from;  // world-space camera position
    std::optional<glm::dvec3> look_at;    // world-space point the camera looks at
    std::optional<glm::dvec3> up;         // world-space up hint (default: the camera's up)
    std::optional<double> aperture;       // thin-lens radius, world units (0: pinhole)
    std::optional<double> focus_distance; // plane of focus along the view direction
};

// Applies `o` to scene.camera; throws pathcl::Error naming the flag for values that make
// no camera (a field of view outside (0, 180), look-at equal to look-from, an up
// parallel to the view direction, a negative aperture, an aperture without any focus
// distance, --fov on an orthographic camera).
void apply_camera_overrides(Scene& scene, const CameraOverrides& o);

} // namespace pathcl
