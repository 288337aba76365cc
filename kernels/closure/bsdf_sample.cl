/* BSDF sampling: a lobe by its estimated albedo, then a direction by that lobe's own code
 * (closure/diffuse.cl: cosine-weighted; conductor.cl and dielectric.cl: a visible GGX
 * facet, the interface then reflecting or refracting by the facet's own Fresnel split;
 * coat.cl: a visible facet of the coat; sheen.cl: uniform), with weight f cos / pdf over
 * every non-delta lobe. */
#include "closure/bsdf_eval.cl"
#include "closure/bsdf_params.cl"
#include "closure/coat.cl"
#include "closure/conductor.cl"
#include "closure/dielectric.cl"
#include "closure/diffuse.cl"
#include "closure/layer_albedo.cl"
#include "closure/sheen.cl"
#include "features.h"
#include "geom/ray_offset.cl"
#include "sample/warp.cl"
#include "util/math.cl"

#if defined(PATHCL_HAS_CLEARCOAT) || defined(PATHCL_HAS_SHEEN)

/* A sampled direction s.wi of a lobe sampled in a frame of its own, with its pdf and weight
 * f cos / pdf over every non-delta lobe (bsdf_eval); no sample where that pdf is 0. */
static inline BsdfSample weighed_by_every_lobe(const BsdfParams* p, const SurfacePoint* sp, float3 wo, BsdfSample s)
{
    BsdfEval e = bsdf_eval(p, sp, wo, s.wi);
    if (!(e.pdf > 0.0f))
        return s;
    s.pdf = e.pdf;
    s.weight = e.f_cos / e.pdf;
    return s;
}

#endif

#ifdef PATHCL_FULL_BSDF

/* A delta sample of the base as it leaves under the sheen and the clear coat: scaled by
 * what each passes towards s.wi. */
static inline BsdfSample delta_under_layers(const BsdfParams* p, const SurfacePoint* sp, BsdfSample s)
{
#ifdef PATHCL_HAS_SHEEN
    s.weight *= sheen_delta_scale(p, sp, s.wi);
#endif
#ifdef PATHCL_HAS_CLEARCOAT
    if (p->coat > 0.0f)
        s.weight *= coat_base_scale(p, s.wi);
#endif
    return s;
}

/* A sample through every lobe's code: u_lobe picks the lobe, u samples it. */
static inline BsdfSample bsdf_sample_lobes(const BsdfParams* p, const SurfacePoint* sp, float3 wo, float u_lobe,
                                           float2 u)
{
    BsdfSample s = no_bsdf_sample();
    float3 t, b;
    bsdf_frame(p, sp, &t, &b);
    float3 wo_l = to_local(wo, t, b, sp->ns);
    const LobeChoice lobes = p->lobes;
#ifdef PATHCL_HAS_CLEARCOAT
    if (lobes.coat > 0.0f && u_lobe >= 1.0f - lobes.coat)
        return coat_sample(p, sp, wo, u, &s) ? weighed_by_every_lobe(p, sp, wo, s) : s;
#endif
#ifdef PATHCL_HAS_SHEEN
#ifdef PATHCL_HAS_CLEARCOAT
    float sheen_end = 1.0f - lobes.coat;
#else
    float sheen_end = 1.0f;
#endif
    if (lobes.sheen > 0.0f && u_lobe >= sheen_end - lobes.sheen)
        return sheen_sample(sp, u, &s) ? weighed_by_every_lobe(p, sp, wo, s) : s;
#endif
    float3 wi;
    bool reflect = true;
    if (u_lobe < lobes.diffuse) {
        wi = sample_cosine_hemisphere(u);
    } else if (u_lobe < lobes.diffuse + lobes.conductor) {
        if (!conductor_sample(p, sp, wo_l, u, t, b, &wi, &s))
            return s.delta ? delta_under_layers(p, sp, s) : s;
    } else if (!interface_sample(p, sp, wo_l, u_lobe, u, t, b, &wi, &reflect, &s)) {
        return s.delta ? delta_under_layers(p, sp, s) : s;
    }
    s.wi = to_world(wi, t, b, sp->ns);
    float cos_ig = dot(s.wi, sp->ng);
    if (reflect ? (!(wi.z > 0.0f) || !above_surface(sp, cos_ig)) : (!(wi.z < 0.0f) || !(cos_ig < 0.0f)))
        return s;
    BsdfEval e = bsdf_eval_local(p, wo_l, wi, reflect);
#ifdef PATHCL_HAS_SHEEN
    sheen_eval(p, sp, wo, s.wi, &e); /* the sheen's lobe too, and its scale of the base */
#endif
#ifdef PATHCL_HAS_CLEARCOAT
    coat_eval(p, sp, wo, s.wi, &e); /* the coat's lobe too */
#endif
    if (!(e.pdf > 0.0f))
        return s;
    s.pdf = e.pdf;
    s.weight = e.f_cos / e.pdf;
    if (!reflect && !p->thin)
        s.eta2 = p->eta * p->eta;
    return s;
}

#endif /* PATHCL_FULL_BSDF */

/* u_lobe picks the lobe, u samples it. */
static inline BsdfSample bsdf_sample(const BsdfParams* p, const SurfacePoint* sp, float3 wo, float u_lobe, float2 u)
{
#ifndef PATHCL_FULL_BSDF
    BsdfSample s = no_bsdf_sample();
    float3 t, b;
    bsdf_frame(p, sp, &t, &b);
    float3 wi = sample_cosine_hemisphere(u);
    s.wi = to_world(wi, t, b, sp->ns);
    if (wi.z <= 0.0f || !above_surface(sp, dot(s.wi, sp->ng)))
        return s;
    s.pdf = wi.z * INV_PI;
    s.weight = p->base_color; /* (albedo / pi) cos / (cos / pi) */
    return s;
#else
    return bsdf_lambertian(p) ? bsdf_sample_lambertian(p, sp, u) : bsdf_sample_lobes(p, sp, wo, u_lobe, u);
#endif
}
