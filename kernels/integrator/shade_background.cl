/* What a path sees when it leaves the scene: the environment, weighted against light
 * sampling of it. Sphere lights, which live outside the BVH, are hit here too: they emit
 * outwards only and do not reflect, so the path ends on them. */
#include "features.h"
#include "integrator/absorption.cl"
#include "integrator/mis.cl"
#include "integrator/path_state.cl"
#include "kernel_data.cl"
#include "light/environment.cl"
#include "light/light_sample.cl"
#include "light/sphere.cl"

#ifdef PATHCL_HAS_SPHERE_LIGHTS
/* Whether the path's ray meets a sphere light before t_hit (the BVH's closest hit); adds
 * its emission, seen from outside, weighted against light sampling. The path ends there. */
static inline bool shade_sphere_lights(const KernelData* kd, const FrameParams* frame, PathState* ps, float t_hit)
{
    float t_sphere;
    bool sphere_from_outside;
    int sphere = closest_sphere_light(kd->lights, frame->sphere_count, ps->origin, ps->dir, t_hit, &t_sphere,
                                      &sphere_from_outside);
    if (sphere < 0)
        return false;
    if (sphere_from_outside) {
#ifdef PATHCL_HAS_VOLUME_ABSORPTION
        ps->beta *= medium_transmittance(kd, ps->medium, t_sphere);
#endif
        Light light = kd->lights[sphere];
#ifdef PATHCL_LIGHT_TREE
        float pmf = light_pick_pmf(kd, frame, ps->prev_ref, ps->prev_n, sphere);
#else
        float pmf = kd->light_distribution[sphere].pmf;
#endif
        float w = ps->prev_delta ? 1.0f
                                 : bsdf_hit_weight(frame->strategy, ps->prev_technique_bsdf, ps->prev_bsdf_pdf,
                                                   sphere_light_pdf(&light, pmf, ps->origin));
        ps->radiance += ps->beta * light.radiance.xyz * w;
    }
    return true;
}
#endif

/* The path escaped: the environment's radiance along its ray. */
static inline void shade_background(const KernelData* kd, const FrameParams* frame, PathState* ps)
{
#ifdef PATHCL_HAS_ENVIRONMENT
    if (frame->environment >= 0) {
        Light e = kd->lights[frame->environment];
#ifdef PATHCL_LIGHT_TREE
        float pmf = light_pick_pmf(kd, frame, ps->prev_ref, ps->prev_n, frame->environment);
#else
        float pmf = kd->light_distribution[frame->environment].pmf;
#endif
        uint2 texel = environment_texel(&e.data.environment, ps->dir);
        float w = ps->prev_delta ? 1.0f
                                 : bsdf_hit_weight(frame->strategy, ps->prev_technique_bsdf, ps->prev_bsdf_pdf,
                                                   environment_pdf(kd, &e.data.environment, pmf, texel, ps->dir));
        ps->radiance += ps->beta * environment_radiance(kd, &e.data.environment, texel) * w;
    }
#endif
}
