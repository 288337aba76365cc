/* Continuing a path: sample the BSDF for the next direction, update the throughput, and
 * from bounce RR_START_BOUNCE on play Russian roulette on the energy the path carries. */
#include "closure/bsdf.cl"
#include "geom/ray_offset.cl"
#include "integrator/absorption.cl"
#include "integrator/path_state.cl"
#include "integrator/shade_surface.cl"
#include "sample/dimensions.h"
#include "sample/sampler.cl"
#include "util/math.cl"

/* Roulette from the fifth bounce on (Mitsuba 3's rr_depth default). Measured against a
 * 16384-spp reference (256x256, 64 spp, 7 bounces, 6 seeds), efficiency 1 / (error x
 * time) over starting at the third: Cornell box 1.07x (RMSE^2) and 1.25x (relMSE),
 * glass-and-mirror box 1.10x and 1.07x; starting at the fourth gained less, and no
 * roulette at all (up to 7 bounces) lost on the Cornell box's RMSE. */
#define RR_START_BOUNCE 5

/* Samples the next direction; false when the BSDF gives none (the path ends). */
static inline bool surface_bounce(PathState* ps, const ShadingPoint* s, float3 wo, bool technique_light, uint dims,
                                  SamplerState* sampler)
{
#ifdef PATHCL_FULL_BSDF
    sampler->dimension = dims + DIM_BSDF_LOBE;
    float u_lobe = sampler_get_1d(sampler);
#else
    float u_lobe = 0.0f; /* one lobe: nothing to pick (no sampler number spent on it) */
#endif
    sampler->dimension = dims + DIM_BSDF;
    BsdfSample bs = bsdf_sample(&s->bsdf, &s->sp, wo, u_lobe, sampler_get_2d(sampler));
    if (!(bs.pdf > 0.0f))
        return false;
    ps->beta *= bs.weight;
    ps->eta2_product *= bs.eta2;
    ps->prev_bsdf_pdf = bs.pdf;
    ps->prev_delta = bs.delta;
    ps->prev_technique_bsdf = !technique_light;
    ps->origin = spawn_ray_origin(&s->sp, bs.wi);
    ps->dir = bs.wi;
#ifdef PATHCL_HAS_VOLUME_ABSORPTION
    ps->medium = medium_after(ps->medium, s, bs.wi);
#endif
#ifdef PATHCL_HAS_UNLIT
    ps->specular_chain = ps->specular_chain && bs.delta;
#endif
#ifdef PATHCL_KEEPS_PREV_REF
    ps->prev_ref = light_sample_origin(&s->sp);
#endif
#ifdef PATHCL_LIGHT_TREE
    ps->prev_n = s->sp.ns;
#endif
    return true;
}

/* Russian roulette: survive with probability q, divide by q (unbiased). q follows the
 * energy the path carries, not its radiance: inside glass beta holds 1/eta^2, which
 * would otherwise kill paths that are about to leave it (as pbrt does). False: the path
 * ends. */
static inline bool russian_roulette(PathState* ps, uint depth, uint dims, SamplerState* sampler)
{
    if (depth + 1u < RR_START_BOUNCE)
        return true;
    sampler->dimension = dims + DIM_RR;
    float q = fmin(1.0f, max3(ps->beta) * ps->eta2_product);
    if (sampler_get_1d(sampler) >= q)
        return false;
    ps->beta /= q;
    return true;
}
