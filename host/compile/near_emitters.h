// What --triangle-sampling auto decides from the scene: whether any surface lies in front
// of an emissive triangle close enough that the kernels would sample that triangle by
// solid angle there (its area over the squared distance to its centroid above
// TRIANGLE_SOLID_ANGLE_MIN, kernels/light/triangle_sampling.h). Where none does, solid-angle
// sampling would only test every light sample and gain nothing (3-6 % of the samples per
// second on the Cornell box and the textured scene, docs/accuracy.md), so auto compiles
// area sampling alone, bit for bit the same as --triangle-sampling area.
#pragma once

#include "render/render_options.h"
#include "scene/scene.h"

namespace pathcl {

// Whether some triangle of the scene other than the emitter itself has a point in front
// of an emissive triangle's plane (by more than the rounding of float coordinates) and
// within sqrt(area / TRIANGLE_SOLID_ANGLE_MIN) of its centroid. Instanced copies of
// meshes are not looked at.
bool surfaces_near_emitters(const Scene& scene);

// The triangle sampling a render uses: auto is area with the wavefront integrator (which
// has only area) and where no surface is near an emitter, else solid-angle.
TriangleSampling resolve_triangle_sampling(const Scene& scene, const RenderOptions& options);

} // namespace pathcl
