/* Which lobe a BSDF sample takes: the lobe probabilities estimated once per shading
 * point from their albedos, and the per-facet split between reflection and refraction at
 * the dielectric interface. */
#include "closure/bsdf_params.cl"
#include "closure/fresnel_layer.cl"
#include "features.h"
#include "util/math.cl"

#ifdef PATHCL_FULL_BSDF

/* Lobe probabilities from each lobe's albedo as seen from wo at the macro normal. A rough
 * lobe that exists gets at least LOBE_ESTIMATE_FLOOR of its weight, since its facets can
 * reflect where the macro surface barely does (a black conductor at normal incidence).
 * Under a clear coat the base lobes' estimates are scaled by what the coat passes. */
static inline LobeChoice choose_lobes(const BsdfParams* p)
{
    bool rough = interface_rough(p);
    /* No specular lobes: specular 0 makes the layer's Fresnel factor exactly 0. */
    float3 f_layer = p->specular_lobes ? fresnel_specular_layer(p, p->cos_o) : (float3)(0.0f);
    LobeChoice c;
    c.diffuse =
        p->inside ? 0.0f : (1.0f - p->metallic) * (1.0f - p->transmission) * mean3(p->base_color * (1.0f - p->layer_o));
    c.diffuse += mean3(p->ms_albedo); /* the conductor's multiple scattering, sampled alike */
    c.conductor = p->metallic * mean3(fresnel_schlick(p->base_color, p->cos_o));
    /* The interface: the coat's reflection over the diffuse base, and the glass (whose
     * compensated albedo is reflection plus tinted refraction). */
    float coat = mean3(p->inside ? f_layer : p->layer_o);
    float glass = mean3(f_layer) + (1.0f - max3(f_layer)) * mean3(p->base_color);
    c.interface = (1.0f - p->metallic) * ((1.0f - p->transmission) * coat + p->transmission * glass);
    bool has_interface = (p->specular > 0.0f && p->eta != 1.0f) || p->transmission > 0.0f;
    if (conductor_rough(p))
        c.conductor = fmax(c.conductor, LOBE_ESTIMATE_FLOOR * p->metallic);
    if (rough && has_interface)
        c.interface = fmax(c.interface, LOBE_ESTIMATE_FLOOR * (1.0f - p->metallic));
    float sum = 0.0f;
#ifdef PATHCL_HAS_SHEEN
    /* The base lobes see what the sheen does not reflect; the sheen reflects from outside. */
    float e_sheen = fmin(p->sheen_e_o, 1.0f);
    float under_sheen = 1.0f - p->sheen_max * e_sheen;
    c.diffuse *= under_sheen;
    c.conductor *= under_sheen;
    c.interface *= under_sheen;
    c.sheen = p->inside ? 0.0f : mean3(p->sheen) * e_sheen;
    if (!p->inside)
        c.sheen = fmax(c.sheen, LOBE_ESTIMATE_FLOOR * p->sheen_max);
#endif
#ifdef PATHCL_HAS_CLEARCOAT
    /* The base lobes (and the sheen) see what the coat does not reflect; the coat reflects
     * from outside. */
    float base = 1.0f - p->coat_e_o;
    c.diffuse *= base;
    c.conductor *= base;
    c.interface *= base;
#ifdef PATHCL_HAS_SHEEN
    c.sheen *= base;
#endif
    c.coat = p->inside ? 0.0f : p->coat_e_o;
    if (!p->inside && p->coat_alpha >= ALPHA_DELTA)
        c.coat = fmax(c.coat, LOBE_ESTIMATE_FLOOR * p->coat);
    sum += c.coat;
#endif
#ifdef PATHCL_HAS_SHEEN
    sum += c.sheen;
#endif
    sum += c.diffuse + c.conductor + c.interface;
    if (sum > 0.0f) {
#ifdef PATHCL_HAS_CLEARCOAT
        c.coat /= sum;
#endif
#ifdef PATHCL_HAS_SHEEN
        c.sheen /= sum;
#endif
        c.diffuse /= sum;
        c.conductor /= sum;
        c.interface /= sum;
    }
    return c;
}

/* Probability that the interface reflects rather than refracts at a facet seen at cos c
 * from wo: its share of the facet's reflected and transmitted energy (pbrt's per-facet
 * choice; for a white dielectric this is the Fresnel factor itself). */
static inline float interface_split(const BsdfParams* p, float c)
{
    float3 f_layer = fresnel_specular_layer(p, c);
    float layer_scale = (1.0f - p->transmission) + p->transmission * p->glass_scale;
    float r = layer_scale * mean3(f_layer);
    float t = p->transmission * p->glass_scale * (1.0f - max3(f_layer)) * mean3(p->base_color);
    return r + t > 0.0f ? r / (r + t) : 1.0f;
}

#endif /* PATHCL_FULL_BSDF */
