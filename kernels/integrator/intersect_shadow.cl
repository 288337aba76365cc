/* Shadow rays: whether anything blocks the segment from a shading point to a light
 * sample (the BVH's any-hit traversal, and the sphere lights outside it). */
#include "bvh/traversal.cl"
#include "features.h"
#include "kernel_data.cl"
#include "light/sphere.cl"

static inline bool shadow_ray_blocked(const KernelData* kd, const FrameParams* frame, float3 from, float3 dir,
                                      float t_max)
{
    bool blocked = bvh_trace(kd->nodes, kd->triangles, from, dir, t_max, true).triangle >= 0;
#ifdef PATHCL_HAS_SPHERE_LIGHTS
    float t_sphere_shadow;
    bool unused_side;
    blocked = blocked || closest_sphere_light(kd->lights, frame->sphere_count, from, dir, t_max, &t_sphere_shadow,
                                              &unused_side) >= 0;
#endif
    return blocked;
}
