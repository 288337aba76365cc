/* Next event estimation's light sample: pick one light in proportion to its power, then
 * a point or direction on it as its type says (the other files of light/). Only the light types a
 * scene has are compiled (PATHCL_HAS_*_LIGHTS). */
#include "features.h"
#include "kernel_data.cl"
#include "light/environment.cl"
#include "light/light_pick.cl"
#include "light/light_sample_record.cl"
#include "light/punctual.cl"
#include "light/sphere.cl"
#include "light/triangle.cl"
#include "sample/sampler.cl"
#include "util/hash.cl"

/* The part of a light sample that does not depend on the point it is seen from: the light
 * picked and the numbers left for its point on it. */
typedef struct {
    int light;
    float2 u; /* the point's numbers, u.x rescaled within the picked slot */
} LightChoice;

/* Picks the light, drawing the alias coin (a 1D decision) and the point (a 2D decision
 * whose first number also picks the slot) from the sampler. */
static inline LightChoice light_choose(const KernelData* kd, uint count, SamplerState* sampler)
{
    LightChoice c;
    float u_alias = sampler_get_1d(sampler);
    /* Independent of every sampler's numbers: the pair's own independent number, hashed
     * once more. With at most 16 lights a step is at most 2^-20 of the slot and its middle
     * serves (the hash cost the Cornell box 1 % of its samples per second). */
    float step_jitter = 0.5f;
    if (count > 16u)
        step_jitter = u32_to_unit_float(hash_combine(hash_combine(sampler->sample_key, sampler->dimension), 1u));
    float2 u = sampler_get_2d(sampler);
    float u_slot = u.x;
    int picked = light_pick(kd->light_distribution, count, &u_slot, u_alias, step_jitter);
    u.x = u_slot; /* rescaled within the slot: uniform again */
    c.light = picked;
    c.u = u;
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
    Light light = kd->lights[c->light];
    float pmf = kd->light_distribution[c->light].pmf;
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

/* One light sample seen from ref, its numbers from the sampler. */
static inline LightSample light_sample(const KernelData* kd, uint count, float3 ref, SamplerState* sampler)
{
    LightChoice c = light_choose(kd, count, sampler);
    return light_sample_chosen(kd, &c, ref);
}
