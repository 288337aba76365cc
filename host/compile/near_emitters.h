// What --triangle-sampling auto decides from the scene: whether emissive triangles send
// enough of their light onto surfaces close enough that the kernels sample them by solid
// angle there (area over the squared distance to the centroid above
// TRIANGLE_SOLID_ANGLE_MIN, kernels/light/triangle_sampling.h), or onto one so close that
// area sampling's rare samples on its near part carry huge weights. Elsewhere solid-angle
// sampling would test every light sample and gain too little (3-6 % of the samples per
// second on the Cornell box and the textured scene, docs/accuracy.md), so auto compiles
// area sampling alone, bit for bit the same as --triangle-sampling area.
#pragma once

#include "render/render_options.h"
#include "scene/scene.h"

namespace pathcl {

// How much of the emissive triangles' light meets other surfaces near them, where the
// kernels would sample them by solid angle (within sqrt(area / TRIANGLE_SOLID_ANGLE_MIN)
// of an emitter's centroid, in front of it; sent from the centroid in 256 directions of
// density cos / pi), and how close the nearest such surface comes. Instanced copies of
// meshes are not looked at.
struct NearEmitters {
    double power_share = 0.0; // of the emitters' power (area x luminance of the emission)
    double closeness = 0.0;   // the largest area / d^2 of an emitter with a surface d in front of it
};
NearEmitters near_emitters(const Scene& scene);

// The triangle sampling a render uses: auto is area with the wavefront integrator (which
// has only area), solid-angle where near_emitters finds at least half the emitters' power
// meeting surfaces near them or a closeness of 10 or more, else area.
TriangleSampling resolve_triangle_sampling(const Scene& scene, const RenderOptions& options);

} // namespace pathcl
