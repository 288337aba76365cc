/* Next event estimation's light sample: pick one light (in proportion to its power, or by
 * the light tree with --light-sampler tree), then a point or direction on it as its type
 * says (the other files of light/). Only the light types a scene has are compiled
 * (PATHCL_HAS_*_LIGHTS). */
#include "features.h"
#include "kernel_data.cl"
#include "light/environment.cl"
#include "light/light_pick.cl"
#include "light/light_record_warm.cl"
#include "light/light_sample_record.cl"
#include "light/light_tree.cl"
#include "light/punctual.cl"
#include "light/sphere.cl"
#include "light/triangle.cl"
#include "sample/sampler.cl"
#include "util/hash.cl"

/* The light a sample is of: the light picked, the probability it was picked with, and the
 * numbers left for its point on it. */
typedef struct {
    int light; /* -1: none (the light tree found no light that can reach the point) */
    float pmf;
    float2 u; /* the point's numbers (power table: u.x rescaled within the picked slot) */
} LightChoice;

/* The probability that a light is picked for the shading point ref with normal n. */
static inline float light_pick_pmf(const KernelData* kd, const FrameParams* frame, float3 ref, float3 n, int light)
{
#ifdef PATHCL_LIGHT_TREE
    return light_tree_pmf(kd, frame, ref, n, light);
#else
    return kd->light_distribution[light].pmf;
#endif
}

/* Picks the light for the shading point ref with normal n, drawing a 1D decision (the
 * alias coin, or the tree's descent) and the point's 2D decision from the sampler. The
 * power table needs no point: the megakernel picks before it traces (ref, n unused). */
static inline LightChoice light_choose(const KernelData* kd, const FrameParams* frame, float3 ref, float3 n,
                                       SamplerState* sampler)
{
    LightChoice c;
#ifdef PATHCL_LIGHT_TREE
    uint fresh_key = hash_combine(sampler->sample_key, sampler->dimension);
    float u_tree = sampler_get_1d(sampler);
    c.u = sampler_get_2d(sampler);
    c.light = light_tree_pick(kd, frame, ref, n, u_tree, fresh_key, &c.pmf);
#else
    uint count = frame->light_count;
    float u_alias = sampler_get_1d(sampler);
    /* Independent of every sampler's numbers: the pair's own independent number, hashed
     * once more. With at most 16 lights a step is at most 2^-20 of the slot and its middle
     * serves (the hash cost the Cornell box 1 % of its samples per second). */
    float step_jitter = 0.5f;
    if (count > 16u)
        step_jitter = u32_to_unit_float(hash_combine(hash_combine(sampler->sample_key, sampler->dimension), 1u));
    float2 u = sampler_get_2d(sampler);
    float u_slot = u.x;
    c.light = light_pick(kd->light_distribution, count, &u_slot, u_alias, step_jitter);
    u.x = u_slot; /* rescaled within the slot: uniform again */
    c.u = u;
    c.pmf = kd->light_distribution[c.light].pmf;
#endif
    return c;
}

/* The chosen light's sample seen from ref. */
static inline LightSample light_sample_chosen(const KernelData* kd, const LightChoice* c, float3 ref)
{
    LightSample ls;
    ls.pdf = 0.0f;
    ls.delta = false;
    ls.at_infinity = false;
    ls.p_error = (float3)(0.0f);
    ls.radiance = (float3)(0.0f);
    ls.wi = ls.n = ls.p = (float3)(0.0f);
    if (c->light < 0)
        return ls;
    Light light = kd->lights[c->light];
    float pmf = c->pmf;
    float2 u = c->u;

#ifdef PATHCL_HAS_ENVIRONMENT
    if (light.type == LIGHT_ENVIRONMENT) {
        ls.at_infinity = true;
        ls.radiance = environment_sample(kd, &light.data.environment, pmf, u, &ls.wi, &ls.pdf);
        ls.p = ref; /* unused */
        ls.n = -ls.wi;
        return ls;
    }
#endif
#ifdef PATHCL_HAS_SPHERE_LIGHTS
    if (light.type == LIGHT_SPHERE) {
        sample_sphere_light(&light, pmf, ref, u, &ls);
        return ls;
    }
#endif
#ifdef PATHCL_HAS_DIRECTIONAL_LIGHTS
    if (light.type == LIGHT_DIRECTIONAL) {
        sample_directional_light(&light, pmf, ref, &ls);
        return ls;
    }
#endif
#if defined(PATHCL_HAS_POINT_LIGHTS) || defined(PATHCL_HAS_SPOT_LIGHTS)
    if (light.type == LIGHT_POINT || light.type == LIGHT_SPOT || light.type == LIGHT_RECT_SPOT) {
        sample_point_light(&light, pmf, ref, &ls);
        return ls;
    }
#endif
#ifdef PATHCL_HAS_AREA_LIGHTS
    sample_triangle_light(kd, &light, pmf, ref, u, &ls);
#endif
    return ls;
}

/* One light sample seen from ref (shading normal n), its numbers from the sampler. */
static inline LightSample light_sample(const KernelData* kd, const FrameParams* frame, float3 ref, float3 n,
                                       SamplerState* sampler)
{
    LightChoice c = light_choose(kd, frame, ref, n, sampler);
    return light_sample_chosen(kd, &c, ref);
}
