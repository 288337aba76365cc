/* Shadow rays: the fraction of light that reaches a light sample from a shading point (the
 * BVH's visibility traversal, and the sphere lights outside it): 0 when something opaque
 * blocks the segment, 1 when nothing does, in between behind alpha-blended surfaces. */
#include "bvh/traversal.cl"
#include "features.h"
#include "kernel_data.cl"
#include "light/sphere.cl"

static inline float shadow_ray_visibility(const KernelData* kd, const FrameParams* frame, float3 from, float3 dir,
                                          float t_max)
{
    float visibility = bvh_visibility(kd, from, dir, t_max);
#ifdef PATHCL_HAS_SPHERE_LIGHTS
    float t_sphere_shadow;
    bool unused_side;
    if (visibility > 0.0f &&
        closest_sphere_light(kd->lights, frame->sphere_count, from, dir, t_max, &t_sphere_shadow, &unused_side) >= 0)
        visibility = 0.0f;
#endif
    return visibility;
}
