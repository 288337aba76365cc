/* The dielectric interface's transmission: Walter et al.'s rough refraction into a solid,
 * or the reflection lobe mirrored through a thin-walled sheet (its reflection is
 * evaluated with the conductor's, closure/specular.cl), and the interface's samples: a
 * visible facet, then reflection or refraction by that facet's own Fresnel split. The
 * model is in closure/bsdf.cl. */
#include "closure/bsdf_params.cl"
#include "closure/fresnel_layer.cl"
#include "closure/ggx.h"
#include "closure/lobes.cl"
#include "closure/microfacet.cl"
#include "features.h"
#include "geom/ray_offset.cl"
#include "util/math.cl"

#ifdef PATHCL_FULL_BSDF

/* The rough interface's transmission towards wi (below the surface, in the frame of
 * bsdf_frame), a2 = alpha^2: its f cos and pdf into e (the only lobe below). */
static inline void dielectric_transmission_eval(const BsdfParams* p, float3 wo, float3 wi, float a2, BsdfEval* e)
{
    if (!interface_rough(p) || !(wo.z > 0.0f) || p->transmission <= 0.0f)
        return;
    float3 wm;
    float dwm_dwi; /* Jacobian of the half vector map */
    float btdf;    /* f cos / (base colour x transmission weight) */
    if (p->thin) {
        /* Thin-walled: the reflection lobe mirrored through the surface. */
        float3 wr = (float3)(wi.x, wi.y, -wi.z);
        wm = normalize(wo + wr);
        float c = dot(wo, wm);
        if (!(c > 0.0f))
            return;
        dwm_dwi = 1.0f / (4.0f * c);
        btdf = interface_dgg(p, wm, wo, wi) / (4.0f * wo.z);
    } else {
        /* Walter et al. 2007; radiance is divided by eta^2 as it crosses. */
        wm = normalize(wi * p->eta + wo);
        if (wm.z < 0.0f)
            wm = -wm;
        float dot_i = dot(wi, wm), dot_o = dot(wo, wm);
        if (!(dot_o > 0.0f) || !(dot_i < 0.0f))
            return;
        float denom = dot_i + dot_o / p->eta;
        denom *= denom;
        dwm_dwi = -dot_i / denom;
        btdf = ggx_d(wm, a2) * ggx_g1(wo, a2) * ggx_g1(wi, a2) * fabs(dot_i * dot_o) / (wo.z * denom * p->eta * p->eta);
    }
    float c = dot(wo, wm);
    float3 f_layer = fresnel_specular_layer(p, c);
    float t = base_weight(p, f_layer) * p->transmission * p->glass_scale;
    e->f_cos = p->base_color * (t * btdf);
    e->pdf = p->lobes.interface * (1.0f - interface_split(p, c)) * interface_visible_pdf(p, wo, wm) * dwm_dwi;
}

/* A sample of the interface from wo_l (in the frame t, b, ns of bsdf_frame): a visible
 * facet, then reflection or refraction by its own split; u_lobe's part of the interval
 * beyond the diffuse and conductor lobes is the uniform number for that choice. Returns
 * true with *wi and *reflect a rough lobe's direction, to be weighed by every lobe
 * (bsdf_sample.cl); false when *s is final: the delta sample of an ideal coat, glass or
 * thin sheet, weight (F or T) / (selection probability), or none. */
static inline bool interface_sample(const BsdfParams* p, const SurfacePoint* sp, float3 wo_l, float u_lobe, float2 u,
                                    float3 t, float3 b, float3* wi, bool* reflect, BsdfSample* s)
{
    const LobeChoice lobes = p->lobes;
    bool rough = interface_rough(p);
    if (!(wo_l.z > 0.0f) || !(lobes.interface > 0.0f))
        return false;
    float3 wm = rough ? interface_sample_visible(p, wo_l, u) : (float3)(0.0f, 0.0f, 1.0f);
    float c = dot(wo_l, wm);
    float split = interface_split(p, c);
    float u_split = (u_lobe - lobes.diffuse - lobes.conductor) / lobes.interface;
    *reflect = u_split < split;
    if (*reflect) {
        *wi = 2.0f * c * wm - wo_l;
    } else if (p->thin) {
        *wi = 2.0f * c * wm - wo_l;
        wi->z = -wi->z;
    } else if (!refract_dir(wo_l, wm, p->eta, wi)) {
        return false; /* not reached: total internal reflection makes the split 1 */
    }
    if (rough)
        return true;
    /* Radiance is scaled by 1/eta^2 when it crosses into a solid. */
    s->wi = to_world(*wi, t, b, sp->ns);
    float cos_ig = dot(s->wi, sp->ng);
    if (*reflect ? (!(wi->z > 0.0f) || !above_surface(sp, cos_ig)) : (!(wi->z < 0.0f) || !(cos_ig < 0.0f)))
        return false;
    float3 f_layer = fresnel_specular_layer(p, c);
    s->delta = true;
    if (*reflect) {
        s->pdf = lobes.interface * split;
        s->weight = (1.0f - p->metallic) * f_layer / s->pdf;
    } else {
        float tw = base_weight(p, f_layer) * p->transmission;
        if (!p->thin) {
            s->eta2 = p->eta * p->eta;
            tw /= s->eta2;
        }
        s->pdf = lobes.interface * (1.0f - split);
        s->weight = p->base_color * (tw / s->pdf);
    }
    return false;
}

#endif /* PATHCL_FULL_BSDF */
