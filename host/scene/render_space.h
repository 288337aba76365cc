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
void move_to_render_space(PendingGeometry& geometry, bool have_camera, Scene& scene);

} // namespace pathcl
