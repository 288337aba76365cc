/* The path tracer: one camera ray per work-item, followed through up to max_bounces
 * scattering events, as one loop over the integrator's stages (Cycles'
 * integrator/megakernel.h). The estimator is the rendering equation unrolled: at each
 * vertex
 *   L += beta * Le(wo) * w_bsdf              emission found by the previous BSDF sample
 *   L += beta * f cos Le / p_light * w_light next event estimation (a shadow ray)
 *   beta *= f cos / p_bsdf                   continue the path by BSDF sampling
 * with the weights of the strategy (integrator/mis.cl). Emission seen by camera rays (or
 * after a delta BSDF) always has weight 1. Russian roulette from the fifth bounce on is unbiased.
 * Code for features a scene lacks is not compiled (features.h). */
#include "bvh/traversal.cl"
#include "features.h"
#include "film/film.cl"
#include "film/pixel.cl"
#include "integrator/absorption.cl"
#include "integrator/direct_light.cl"
#include "integrator/path_state.cl"
#include "integrator/shade_background.cl"
#include "integrator/shade_surface.cl"
#include "integrator/surface_bounce.cl"
#include "kernel_data.cl"
#include "sample/dimensions.h"
#include "sample/sampler.cl"

PATHCL_KERNEL void trace_paths(PATHCL_KERNEL_PARAMS FrameParams frame)
{
    PATHCL_KERNEL_DATA;
    uint2 xy;
    uint pixel;
    if (!frame_pixel(&frame, &xy, &pixel) || !pixel_active(&frame, kd.active, pixel))
        return;

    PathState ps = path_state_start(kd.rays[pixel]);
#ifdef PATHCL_DEFERRED_LIGHT_SAMPLE
    DeferredLightSample deferred;
    bool light_sample_deferred = false;
#endif
    const SamplerState path_sampler = frame_sampler(&frame, pixel, DIM_PATH_START);
    for (uint depth = 0;; ++depth) {
        /* The bounce's decisions start at its own sampler dimension, their numbers drawn
         * at once, before the ray is traced: they do not depend on the hit, and the
         * processor overlaps their chain of multiplies with the traversal. */
        uint dims = DIM_PATH_START + depth * DIMS_PER_BOUNCE;
        SamplerState sampler = sampler_bounce(&path_sampler, dims);
#ifdef PATHCL_HAS_LIGHTS
        LightChoice light_choice;
#if !defined(PATHCL_FULL_BSDF) && !defined(PATHCL_LIGHT_TREE)
        /* Lambertian surfaces only: every hit that scatters samples a light, so the pick
         * (the alias table's chain of integer divisions) is made before the traversal too.
         * Where delta lobes skip light sampling it waits for the hit (drawn early it ran
         * slower through glass and on the material spheres), as does the light tree, which
         * weighs the lights as seen from the hit. */
        if (frame_samples_lights(&frame)) {
            light_choice = direct_light_choose(&kd, &frame, dims, (float3)(0.0f), (float3)(0.0f), &sampler);
            light_record_warm(&kd, light_choice.light);
        }
#endif
#endif
        Hit hit = bvh_closest_hit(&kd, ps.origin, ps.dir, INFINITY);
#ifdef PATHCL_DEFERRED_LIGHT_SAMPLE
        if (light_sample_deferred)
            direct_light_deferred(&kd, &frame, &deferred, &ps);
        light_sample_deferred = false;
#endif
#ifdef PATHCL_HAS_SPHERE_LIGHTS
        if (shade_sphere_lights(&kd, &frame, &ps, hit.t))
            break;
#endif
#ifdef PATHCL_HAS_VOLUME_ABSORPTION
        ps.beta *= medium_transmittance(&kd, ps.medium, hit.t);
#endif
        if (hit.triangle < 0) {
            shade_background(&kd, &frame, &ps);
            break;
        }
        float3 wo = -ps.dir;
        ShadingPoint s = shade_surface_setup(&kd, hit, wo);
#ifdef PATHCL_HAS_UNLIT
        if (shade_unlit(&ps, &s))
            break;
#endif
        shade_surface_emission(&kd, &frame, &ps, &s, hit, wo);
        if (depth >= frame.max_bounces || !surface_scatters(&s))
            break;

        /* One-sample MIS's coin is drawn only by that strategy. */
        sampler.dimension = dims + DIM_TECHNIQUE;
        bool technique_light = frame.strategy == STRATEGY_ONE_SAMPLE && sampler_get_1d(&sampler) < 0.5f;
#ifdef PATHCL_HAS_LIGHTS
        if (direct_light_wanted(&frame, &s, technique_light)) {
#if defined(PATHCL_FULL_BSDF) || defined(PATHCL_LIGHT_TREE)
            light_choice = direct_light_choose(&kd, &frame, dims, light_sample_origin(&s.sp), s.sp.ns, &sampler);
#endif
#ifdef PATHCL_DEFERRED_LIGHT_SAMPLE
            direct_light_defer(&kd, &ps, &s, wo, technique_light, &light_choice, &deferred);
            light_sample_deferred = true;
#else
            direct_light(&kd, &frame, &ps, &s, wo, technique_light, &light_choice);
#endif
        }
#endif
        if (!surface_bounce(&ps, &s, wo, technique_light, dims, &sampler) ||
            !russian_roulette(&ps, depth, dims, &sampler))
            break;
    }
#ifdef PATHCL_DEFERRED_LIGHT_SAMPLE
    if (light_sample_deferred)
        direct_light_deferred(&kd, &frame, &deferred, &ps);
#endif
    film_add_sample(kd.film, kd.bad_samples, pixel, ps.radiance);
}
