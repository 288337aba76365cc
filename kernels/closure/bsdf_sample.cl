/* BSDF sampling: a lobe by its estimated albedo, then a direction (cosine-weighted for the
 * diffuse base, a visible GGX facet for the specular lobes and the clear coat, uniform for
 * the sheen, reflection or refraction by the facet's own Fresnel split), with weight
 * f cos / pdf over every non-delta lobe. */
#include "closure/bsdf_eval.cl"
#include "closure/bsdf_params.cl"
#include "closure/fresnel_layer.cl"
#include "closure/layer_albedo.cl"
#include "closure/microfacet.cl"
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

#ifdef PATHCL_HAS_CLEARCOAT

/* A sample of the clear coat's reflection: a visible facet of the coat in its own frame
 * (the mirror direction when smooth). */
static inline BsdfSample coat_sample(const BsdfParams* p, const SurfacePoint* sp, float3 wo, float2 u)
{
    BsdfSample s = no_bsdf_sample();
    float3 t, b;
    make_basis(p->coat_n, &t, &b);
    float3 wo_c = to_local(wo, t, b, p->coat_n);
    if (!(wo_c.z > 0.0f))
        return s;
    bool smooth = p->coat_alpha < ALPHA_DELTA;
    float3 wm = smooth ? (float3)(0.0f, 0.0f, 1.0f) : ggx_sample_visible(wo_c, p->coat_alpha, p->coat_alpha, u);
    float3 wi_c = 2.0f * dot(wo_c, wm) * wm - wo_c;
    s.wi = to_world(wi_c, t, b, p->coat_n);
    if (!(wi_c.z > 0.0f) || !above_surface(sp, dot(s.wi, sp->ng)))
        return s;
    if (smooth) {
        s.delta = true;
        s.pdf = p->lobes.coat;
        s.weight = (float3)(p->coat * fresnel_dielectric(wo_c.z, COAT_IOR) / s.pdf);
        return s;
    }
    return weighed_by_every_lobe(p, sp, wo, s);
}

#endif /* PATHCL_HAS_CLEARCOAT */

#ifdef PATHCL_HAS_SHEEN

/* A sample of the sheen: uniform over the hemisphere of the shading normal, as Cycles
 * samples its velvet lobe. The Charlie distribution peaks at fibres lying in the surface,
 * whose mirror directions are mostly below it, so sampling D itself would waste most
 * samples; cosine-weighted sampling would weight grazing wi by 1 / cos_i. */
static inline BsdfSample sheen_sample(const BsdfParams* p, const SurfacePoint* sp, float3 wo, float2 u)
{
    BsdfSample s = no_bsdf_sample();
    float z = u.x;
    float r = sqrt(fmax(0.0f, 1.0f - z * z));
    float cos_phi, sin_phi = sin_cos_turns(u.y, &cos_phi);
    float3 t, b;
    make_basis(sp->ns, &t, &b);
    s.wi = to_world((float3)(r * cos_phi, r * sin_phi, z), t, b, sp->ns);
    if (!(z > 0.0f) || !above_surface(sp, dot(s.wi, sp->ng)))
        return s;
    return weighed_by_every_lobe(p, sp, wo, s);
}

/* What a delta sample of the base keeps under the sheen. */
static inline float sheen_delta_scale(const BsdfParams* p, const SurfacePoint* sp, float3 wi)
{
    return p->sheen_max > 0.0f ? sheen_base_scale(p, sheen_albedo(p, fabs(dot(wi, sp->ns)))) : 1.0f;
}

#endif /* PATHCL_HAS_SHEEN */

#ifdef PATHCL_FULL_BSDF

/* bsdf_sample_lobes where bsdf_lambertian holds: the diffuse lobe's sample as the lobe
 * choice there takes it (u_lobe < 1 always picks it) and weighs it (bsdf_eval_local's
 * f cos / pdf), the same values (tested bit for bit). */
static inline BsdfSample bsdf_sample_lambertian(const BsdfParams* p, const SurfacePoint* sp, float2 u)
{
    BsdfSample s = no_bsdf_sample();
    float3 t, b;
    bsdf_frame(p, sp, &t, &b);
    float3 wi = sample_cosine_hemisphere(u);
    s.wi = to_world(wi, t, b, sp->ns);
    if (!(wi.z > 0.0f) || !above_surface(sp, dot(s.wi, sp->ng)))
        return s;
    float pdf = wi.z * INV_PI;
    if (!(pdf > 0.0f))
        return s;
    s.pdf = pdf;
    s.weight = (p->diffuse_scale * wi.z) / pdf;
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
        return coat_sample(p, sp, wo, u);
#endif
#ifdef PATHCL_HAS_SHEEN
#ifdef PATHCL_HAS_CLEARCOAT
    float sheen_end = 1.0f - lobes.coat;
#else
    float sheen_end = 1.0f;
#endif
    if (lobes.sheen > 0.0f && u_lobe >= sheen_end - lobes.sheen)
        return sheen_sample(p, sp, wo, u);
#endif
    bool rough = interface_rough(p);
    float3 wi;
    bool reflect = true;
    if (u_lobe < lobes.diffuse) {
        wi = sample_cosine_hemisphere(u);
    } else if (u_lobe < lobes.diffuse + lobes.conductor) {
        if (!conductor_rough(p)) {
            /* Ideal mirror: weight F / (selection probability). */
            wi = (float3)(-wo_l.x, -wo_l.y, wo_l.z);
            s.wi = to_world(wi, t, b, sp->ns);
            if (!(wi.z > 0.0f) || !above_surface(sp, dot(s.wi, sp->ng)))
                return s;
            s.delta = true;
            s.pdf = lobes.conductor;
            s.weight = p->metallic * fresnel_schlick(p->base_color, p->cos_o) / lobes.conductor;
#ifdef PATHCL_HAS_SHEEN
            s.weight *= sheen_delta_scale(p, sp, s.wi);
#endif
#ifdef PATHCL_HAS_CLEARCOAT
            if (p->coat > 0.0f)
                s.weight *= coat_base_scale(p, s.wi);
#endif
            return s;
        }
        if (!(wo_l.z > 0.0f))
            return s;
        float3 wm = conductor_sample_visible(p, wo_l, u);
        wi = 2.0f * dot(wo_l, wm) * wm - wo_l;
    } else {
        /* The interface: a visible facet, then reflection or refraction by its own split;
         * the rest of u_lobe's interval is the uniform number for that choice. */
        if (!(wo_l.z > 0.0f) || !(lobes.interface > 0.0f))
            return s;
        float3 wm = rough ? interface_sample_visible(p, wo_l, u) : (float3)(0.0f, 0.0f, 1.0f);
        float c = dot(wo_l, wm);
        float split = interface_split(p, c);
        float u_split = (u_lobe - lobes.diffuse - lobes.conductor) / lobes.interface;
        reflect = u_split < split;
        if (reflect) {
            wi = 2.0f * c * wm - wo_l;
        } else if (p->thin) {
            wi = 2.0f * c * wm - wo_l;
            wi.z = -wi.z;
        } else if (!refract_dir(wo_l, wm, p->eta, &wi)) {
            return s; /* not reached: total internal reflection makes the split 1 */
        }
        if (!rough) {
            /* Ideal coat, glass or thin sheet: weight (F or T) / (selection probability);
             * radiance is scaled by 1/eta^2 when it crosses into a solid. */
            s.wi = to_world(wi, t, b, sp->ns);
            float cos_ig = dot(s.wi, sp->ng);
            if (reflect ? (!(wi.z > 0.0f) || !above_surface(sp, cos_ig)) : (!(wi.z < 0.0f) || !(cos_ig < 0.0f)))
                return s;
            float3 f_layer = fresnel_specular_layer(p, c);
            s.delta = true;
            if (reflect) {
                s.pdf = lobes.interface * split;
                s.weight = (1.0f - p->metallic) * f_layer / s.pdf;
            } else {
                float tw = base_weight(p, f_layer) * p->transmission;
                if (!p->thin) {
                    s.eta2 = p->eta * p->eta;
                    tw /= s.eta2;
                }
                s.pdf = lobes.interface * (1.0f - split);
                s.weight = p->base_color * (tw / s.pdf);
            }
#ifdef PATHCL_HAS_SHEEN
            s.weight *= sheen_delta_scale(p, sp, s.wi);
#endif
#ifdef PATHCL_HAS_CLEARCOAT
            if (p->coat > 0.0f)
                s.weight *= coat_base_scale(p, s.wi);
#endif
            return s;
        }
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
