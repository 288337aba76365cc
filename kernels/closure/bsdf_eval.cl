/* BSDF evaluation: f cos theta_i and the pdf of sampling wi, summed over the non-delta
 * lobes, each lobe's own code in its file (diffuse, conductor, specular, dielectric,
 * sheen, coat). A direction is reflected only above both the shading and the geometric
 * surface (or from a lifted point, geom/ray_offset.cl), transmitted only below both. */
#include "closure/bsdf_params.cl"
#include "closure/coat.cl"
#include "closure/conductor.cl"
#include "closure/dielectric.cl"
#include "closure/diffuse.cl"
#include "closure/sheen.cl"
#include "closure/specular.cl"
#include "features.h"
#include "geom/ray_offset.cl"
#include "util/compat.h"
#include "util/math.cl"

#ifdef PATHCL_FULL_BSDF

/* Evaluation of the non-delta lobes in the frame of bsdf_frame; wo.z > 0 is not required (shading
 * normals), the rough lobes vanish where it fails. */
PATHCL_ALWAYS_INLINE static inline BsdfEval bsdf_eval_local(const BsdfParams* p, float3 wo, float3 wi, bool reflect)
{
    BsdfEval e;
    e.f_cos = (float3)(0.0f);
    e.pdf = 0.0f;
    float a2 = p->alpha * p->alpha;
    if (reflect) {
        diffuse_eval(p, wi, &e);
        conductor_ms_eval(p, wi, &e);
#ifdef PATHCL_HAS_ANISOTROPY
        if (bsdf_anisotropic(p)) {
            specular_reflection_eval_anisotropic(p, wo, wi, &e);
            return e;
        }
#endif
        specular_reflection_eval(p, wo, wi, a2, &e);
        return e;
    }
    dielectric_transmission_eval(p, wo, wi, a2, &e);
    return e;
}

/* The base material's lobes through every lobe's code. */
static inline BsdfEval bsdf_eval_lobes(const BsdfParams* p, const SurfacePoint* sp, float3 wo, float3 wi)
{
    BsdfEval e;
    e.f_cos = (float3)(0.0f);
    e.pdf = 0.0f;
    float cos_i = dot(wi, sp->ns), cos_ig = dot(wi, sp->ng);
    bool reflect = cos_i > 0.0f && above_surface(sp, cos_ig);
    bool transmit = cos_i < 0.0f && cos_ig < 0.0f;
    if (!reflect && !transmit)
        return e;
    float3 t, b;
    bsdf_frame(p, sp, &t, &b);
    return bsdf_eval_local(p, to_local(wo, t, b, sp->ns), to_local(wi, t, b, sp->ns), reflect);
}

#endif /* PATHCL_FULL_BSDF */

/* The base material's lobes (everything but the sheen and the clear coat). */
static inline BsdfEval bsdf_eval_base(const BsdfParams* p, const SurfacePoint* sp, float3 wo, float3 wi)
{
#ifndef PATHCL_FULL_BSDF
    /* Lambertian with albedo = base colour. */
    BsdfEval e;
    e.f_cos = (float3)(0.0f);
    e.pdf = 0.0f;
    float cos_i = dot(wi, sp->ns);
    if (cos_i <= 0.0f || !above_surface(sp, dot(wi, sp->ng)))
        return e;
    e.f_cos = p->base_color * (INV_PI * cos_i);
    e.pdf = cos_i * INV_PI;
    return e;
#else
    return bsdf_lambertian(p) ? bsdf_eval_lambertian(p, sp, wi) : bsdf_eval_lobes(p, sp, wo, wi);
#endif
}

/* f cos theta_i and the pdf of sampling wi, over every non-delta lobe. */
static inline BsdfEval bsdf_eval(const BsdfParams* p, const SurfacePoint* sp, float3 wo, float3 wi)
{
    BsdfEval e = bsdf_eval_base(p, sp, wo, wi);
#ifdef PATHCL_HAS_SHEEN
    sheen_eval(p, sp, wo, wi, &e);
#endif
#ifdef PATHCL_HAS_CLEARCOAT
    coat_eval(p, sp, wo, wi, &e);
#endif
    return e;
}
