// Render space: world space translated so that the camera (else the centre of the
// geometry) is the origin. This is the one place that picks that origin and moves the
// pending world-space geometry, the lights and the camera there, rounding positions to
// float only after the subtraction.
#pragma once

#include "scene/pending_geometry.h"
#include "scene/scene.h"

namespace pathcl {

// Moves `geometry` (left empty) into the scene's triangles and attributes, and moves the
// scene's lights and camera, into render space, setting scene.render_origin. The camera is
// the file's when `have_camera`, else replaced by one framing the scene. Zero-area
// triangles are dropped and unusable normals replaced, each counted on the scene. Rounding
// after the subtraction keeps a scene 1e5 from the world origin at full float precision.
// Throws pathcl::Error when the scene reaches further from the render-space origin than
// float arithmetic on it can go (1e18).
void move_to_render_space(PendingGeometry& geometry, bool have_camera, Scene& scene);

// A world-space point in the render space whose origin is `render_origin`
// (Scene::render_origin), and back: what everything after loading uses (camera
// overrides given in world space, the camera-ray log written in world space).
inline glm::dvec3 world_to_render(const glm::dvec3& render_origin, const glm::dvec3& world)
{
    return world - render_origin;
}

inline glm::dvec3 render_to_world(const glm::dvec3& render_origin, const glm::dvec3& render)
{
    return render + render_origin;
}

} // namespace pathcl
