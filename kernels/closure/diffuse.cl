/* The diffuse base under the dielectric layer (Kelemen and Szirmay-Kalos's reciprocal
 * albedo scaling, closure/bsdf.cl), and the Lambertian shortcuts taken where a material
 * is exactly Lambertian (bsdf_lambertian). */
#include "closure/bsdf_params.cl"
#include "closure/layer_albedo.cl"
#include "features.h"
#include "geom/ray_offset.cl"
#include "sample/warp.cl"
#include "util/math.cl"

#ifdef PATHCL_FULL_BSDF

/* The diffuse lobe towards wi (reflected, in the frame of bsdf_frame): its pdf, which the
 * conductor's multiple-scattering lobe shares, and its f cos; none inside a solid. The
 * first lobe of bsdf_eval_local: it sets e. */
static inline void diffuse_eval(const BsdfParams* p, float3 wi, BsdfEval* e)
{
    e->pdf = p->lobes.diffuse * wi.z * INV_PI; /* the diffuse and multiple-scattering lobes */
    if (!p->inside) {
        float3 k = (1.0f - p->layer_o) * (1.0f - layer_albedo_towards(p, wi));
        e->f_cos = p->diffuse_scale * k * wi.z;
    }
}

/* bsdf_eval_lobes where bsdf_lambertian holds: bsdf_eval_local's diffuse lobe with its
 * factors of exactly 1 (the layer's albedos 0, the lobe's probability 1) left out, the
 * same values (tested bit for bit). */
static inline BsdfEval bsdf_eval_lambertian(const BsdfParams* p, const SurfacePoint* sp, float3 wi)
{
    BsdfEval e;
    e.f_cos = (float3)(0.0f);
    e.pdf = 0.0f;
    float cos_i = dot(wi, sp->ns);
    if (!(cos_i > 0.0f) || !above_surface(sp, dot(wi, sp->ng)))
        return e;
    e.f_cos = p->diffuse_scale * cos_i;
    e.pdf = cos_i * INV_PI;
    return e;
}

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

#endif /* PATHCL_FULL_BSDF */
