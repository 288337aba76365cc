/* BSDF evaluation: f cos theta_i and the pdf of sampling wi, summed over the non-delta
 * lobes. A direction is reflected only above both the shading and the geometric surface
 * (or from a lifted point, geom/ray_offset.cl), transmitted only below both. */
#include "closure/bsdf_params.cl"
#include "closure/fresnel_layer.cl"
#include "closure/layer_albedo.cl"
#include "closure/lobes.cl"
#include "closure/microfacet.cl"
#include "closure/sheen.h"
#include "features.h"
#include "geom/ray_offset.cl"
#include "util/compat.h"
#include "util/math.cl"

#ifdef PATHCL_FULL_BSDF

#ifdef PATHCL_HAS_ANISOTROPY

/* The specular reflection of an anisotropic material: the conductor's anisotropic lobe
 * (always rough) and the dielectric layer's lobe (anisotropic alike, or on a transmitting
 * solid isotropic, rough or a delta function), each with its own visible-normal density. */
static inline void bsdf_eval_anisotropic_reflection(const BsdfParams* p, float3 wo, float3 wi, BsdfEval* e)
{
    if (!(wo.z > 0.0f))
        return;
    float3 h = wo + wi;
    float len = length(h);
    if (!(len > 0.0f))
        return;
    h /= len;
    float cos_h = fabs(dot(wo, h));
    float3 fc = p->metallic * fresnel_schlick(p->base_color, cos_h);
    e->f_cos += fc * (conductor_ggx_d(p, h) * conductor_ggx_g1(p, wo) * conductor_ggx_g1(p, wi) / (4.0f * wo.z));
    e->pdf += p->lobes.conductor * conductor_visible_pdf(p, wo, h) / (4.0f * cos_h);
    if (interface_rough(p)) {
        float3 fd = fresnel_layer_reflection(p, fresnel_specular_layer(p, cos_h));
        e->f_cos += fd * (interface_dgg(p, h, wo, wi) / (4.0f * wo.z));
        e->pdf += p->lobes.interface * interface_split(p, cos_h) * interface_visible_pdf(p, wo, h) / (4.0f * cos_h);
    }
}

#endif /* PATHCL_HAS_ANISOTROPY */

/* Evaluation of the non-delta lobes in the frame of bsdf_frame; wo.z > 0 is not required (shading
 * normals), the rough lobes vanish where it fails. */
PATHCL_ALWAYS_INLINE static inline BsdfEval bsdf_eval_local(const BsdfParams* p, float3 wo, float3 wi, bool reflect)
{
    BsdfEval e;
    e.f_cos = (float3)(0.0f);
    e.pdf = 0.0f;
    bool rough = p->alpha >= ALPHA_DELTA;
    float a2 = p->alpha * p->alpha;
    if (reflect) {
        e.pdf = p->lobes.diffuse * wi.z * INV_PI; /* the diffuse and multiple-scattering lobes */
        if (!p->inside) {
            float3 k = (1.0f - p->layer_o) * (1.0f - layer_albedo_towards(p, wi));
            e.f_cos = p->diffuse_scale * k * wi.z;
        }
        if (conductor_rough(p) && p->metallic > 0.0f) {
            /* Kulla and Conty's multiple-scattering lobe: reciprocal, and with it a white
             * rough conductor reflects everything. Sampled with the diffuse lobe. */
            e.f_cos += p->ms_scale * ((1.0f - p->conductor_e_o) * (1.0f - conductor_albedo(p, wi)) * wi.z);
        }
#ifdef PATHCL_HAS_ANISOTROPY
        if (bsdf_anisotropic(p)) {
            bsdf_eval_anisotropic_reflection(p, wo, wi, &e);
            return e;
        }
#endif
        if (rough && wo.z > 0.0f && p->specular_lobes) {
            float3 h = wo + wi;
            float len = length(h);
            if (!(len > 0.0f))
                return e;
            h /= len;
            float cos_h = fabs(dot(wo, h));
            float3 fr = fresnel_reflection(p, cos_h, fresnel_specular_layer(p, cos_h));
            e.f_cos += fr * (ggx_d(h, a2) * ggx_g1(wo, a2) * ggx_g1(wi, a2) / (4.0f * wo.z));
            float select = p->lobes.conductor + p->lobes.interface * interface_split(p, cos_h);
            e.pdf += select * ggx_visible_pdf(wo, h, a2) / (4.0f * cos_h);
        }
        return e;
    }
    if (!interface_rough(p) || !(wo.z > 0.0f) || p->transmission <= 0.0f)
        return e;
    float3 wm;
    float dwm_dwi; /* Jacobian of the half vector map */
    float btdf;    /* f cos / (base colour x transmission weight) */
    if (p->thin) {
        /* Thin-walled: the reflection lobe mirrored through the surface. */
        float3 wr = (float3)(wi.x, wi.y, -wi.z);
        wm = normalize(wo + wr);
        float c = dot(wo, wm);
        if (!(c > 0.0f))
            return e;
        dwm_dwi = 1.0f / (4.0f * c);
        btdf = interface_dgg(p, wm, wo, wi) / (4.0f * wo.z);
    } else {
        /* Walter et al. 2007; radiance is divided by eta^2 as it crosses. */
        wm = normalize(wi * p->eta + wo);
        if (wm.z < 0.0f)
            wm = -wm;
        float dot_i = dot(wi, wm), dot_o = dot(wo, wm);
        if (!(dot_o > 0.0f) || !(dot_i < 0.0f))
            return e;
        float denom = dot_i + dot_o / p->eta;
        denom *= denom;
        dwm_dwi = -dot_i / denom;
        btdf = ggx_d(wm, a2) * ggx_g1(wo, a2) * ggx_g1(wi, a2) * fabs(dot_i * dot_o) / (wo.z * denom * p->eta * p->eta);
    }
    float c = dot(wo, wm);
    float3 f_layer = fresnel_specular_layer(p, c);
    float t = base_weight(p, f_layer) * p->transmission * p->glass_scale;
    e.f_cos = p->base_color * (t * btdf);
    e.pdf = p->lobes.interface * (1.0f - interface_split(p, c)) * interface_visible_pdf(p, wo, wm) * dwm_dwi;
    return e;
}

#endif /* PATHCL_FULL_BSDF */

#ifdef PATHCL_FULL_BSDF

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

#ifdef PATHCL_HAS_CLEARCOAT

/* The clear coat over the base's f_cos and pdf: the base scaled by what the coat passes
 * (coat_base_scale), plus the coat's own GGX reflection in its frame (rough coats; a
 * smooth coat is a delta lobe). The coat reflects only from outside a solid. */
static inline void coat_eval(const BsdfParams* p, const SurfacePoint* sp, float3 wo, float3 wi, BsdfEval* e)
{
    if (!(p->coat > 0.0f))
        return;
    e->f_cos *= coat_base_scale(p, wi);
    float3 t, b;
    make_basis(p->coat_n, &t, &b);
    float3 wo_c = to_local(wo, t, b, p->coat_n), wi_c = to_local(wi, t, b, p->coat_n);
    if (p->inside || p->coat_alpha < ALPHA_DELTA || !(wo_c.z > 0.0f) || !(wi_c.z > 0.0f) ||
        !above_surface(sp, dot(wi, sp->ng)))
        return;
    float3 h = wo_c + wi_c;
    float len = length(h);
    if (!(len > 0.0f))
        return;
    h /= len;
    float cos_h = dot(wo_c, h);
    float a2 = p->coat_alpha * p->coat_alpha;
    float fr = p->coat * fresnel_dielectric(cos_h, COAT_IOR);
    e->f_cos += (float3)(fr * ggx_d(h, a2) * ggx_g1(wo_c, a2) * ggx_g1(wi_c, a2) / (4.0f * wo_c.z));
    e->pdf += p->lobes.coat * ggx_visible_pdf(wo_c, h, a2) / (4.0f * cos_h);
}

#endif /* PATHCL_HAS_CLEARCOAT */

#ifdef PATHCL_HAS_SHEEN

/* Uniform hemisphere density: the sheen's sampling (closure/bsdf_sample.cl). */
#define SHEEN_SAMPLE_PDF (0.5f * INV_PI)

/* The sheen over the base's f_cos and pdf: the base scaled by what the sheen passes
 * (sheen_base_scale), plus the sheen's own lobe on the shading normal, divided by
 * max(1, E_s(cos_o), E_s(|cos_i|)): the lobe as the extension writes it reflects up to
 * eight times what it receives at grazing angles when sheenRoughness is below about 0.3,
 * and with the division it never reflects more than it receives, and stays reciprocal.
 * It reflects only from outside a solid. */
static inline void sheen_eval(const BsdfParams* p, const SurfacePoint* sp, float3 wo, float3 wi, BsdfEval* e)
{
    if (!(p->sheen_max > 0.0f))
        return;
    float cos_i = dot(wi, sp->ns);
    float e_i = sheen_albedo(p, fabs(cos_i));
    e->f_cos *= sheen_base_scale(p, e_i);
    if (p->inside || !(cos_i > 0.0f) || !(p->cos_o > 0.0f) || !above_surface(sp, dot(wi, sp->ng)))
        return;
    float3 t, b;
    make_basis(sp->ns, &t, &b);
    float f = sheen_f_cos(to_local(wo, t, b, sp->ns), to_local(wi, t, b, sp->ns), p->sheen_alpha);
    e->f_cos += p->sheen * (f / fmax(fmax(p->sheen_e_o, e_i), 1.0f));
    e->pdf += p->lobes.sheen * SHEEN_SAMPLE_PDF;
}

#endif /* PATHCL_HAS_SHEEN */

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
