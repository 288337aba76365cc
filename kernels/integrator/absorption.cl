/* Beer-Lambert absorption inside solids (KHR_materials_volume attenuationColor and
 * attenuationDistance): a path that refracts into a solid transmissive material travels
 * inside it until it refracts out, and its throughput is multiplied by exp(-sigma t)
 * over each segment of length t there. The medium a path is in is the material of the
 * last solid it entered (PathState.medium); media do not nest (leaving any solid returns
 * to the outside), and cameras are outside every solid. Compiled only for scenes with an
 * absorbing solid (PATHCL_HAS_VOLUME_ABSORPTION). */
#include "features.h"
#include "integrator/path_state.cl"
#include "integrator/shade_surface.cl"
#include "kernel_data.cl"

#ifdef PATHCL_HAS_VOLUME_ABSORPTION

/* exp(-sigma t) in medium `medium` (-1: none, 1). t may be INFINITY (a ray that leaves
 * an unclosed solid): it gives 0 where sigma > 0 and 1 where sigma = 0. */
static inline float3 medium_transmittance(const KernelData* kd, int medium, float t)
{
    if (medium < 0)
        return (float3)(1.0f);
    float3 sigma = kd->materials[medium].absorption.xyz;
    return exp(-(sigma * fmin(t, FLT_MAX)));
}

/* The medium a ray leaving shading point s along wi travels in: a refraction through a
 * solid's surface enters it from the front face and leaves it from the back; anything
 * else stays where the path was. */
static inline int medium_after(int medium, const ShadingPoint* s, float3 wi)
{
    bool solid = s->material.transmission > 0.0f && !(s->material.flags & MATERIAL_THIN_WALLED);
    if (solid && dot(wi, s->sp.ng) < 0.0f)
        return s->sp.front_face ? s->sp.material : -1;
    return medium;
}

#endif /* PATHCL_HAS_VOLUME_ABSORPTION */
