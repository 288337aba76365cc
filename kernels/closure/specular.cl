/* The GGX reflection of the conductor and of the dielectric layer over the diffuse base.
 * Isotropic, the two lobes share one facet distribution (alpha), so they are evaluated as
 * one: D G once, times their Fresnel factors summed (fresnel_reflection), and the pdf of
 * picking either lobe and then its facet. Anisotropic, each has its own distribution. The
 * samples are each lobe's own (closure/conductor.cl, closure/dielectric.cl). */
#include "closure/bsdf_params.cl"
#include "closure/fresnel_layer.cl"
#include "closure/ggx.h"
#include "closure/lobes.cl"
#include "closure/microfacet.cl"
#include "features.h"
#include "util/math.cl"

#ifdef PATHCL_FULL_BSDF

/* The conductor's and the layer's reflection towards wi (in the frame of bsdf_frame), a2 =
 * alpha^2, added to e; none for delta lobes, from below, or without specular lobes. */
static inline void specular_reflection_eval(const BsdfParams* p, float3 wo, float3 wi, float a2, BsdfEval* e)
{
    bool rough = p->alpha >= ALPHA_DELTA;
    if (rough && wo.z > 0.0f && p->specular_lobes) {
        float3 h;
        if (!reflection_half_vector(wo, wi, &h))
            return;
        float cos_h = fabs(dot(wo, h));
        float3 fr = fresnel_reflection(p, cos_h, fresnel_specular_layer(p, cos_h));
        e->f_cos += fr * (ggx_d(h, a2) * ggx_g1(wo, a2) * ggx_g1(wi, a2) / (4.0f * wo.z));
        float select = p->lobes.conductor + p->lobes.interface * interface_split(p, cos_h);
        e->pdf += select * ggx_visible_pdf(wo, h, a2) / (4.0f * cos_h);
    }
}

#ifdef PATHCL_HAS_ANISOTROPY

/* The specular reflection of an anisotropic material: the conductor's anisotropic lobe
 * (always rough) and the dielectric layer's lobe (anisotropic alike, or on a transmitting
 * solid isotropic, rough or a delta function), each with its own visible-normal density. */
static inline void specular_reflection_eval_anisotropic(const BsdfParams* p, float3 wo, float3 wi, BsdfEval* e)
{
    if (!(wo.z > 0.0f))
        return;
    float3 h;
    if (!reflection_half_vector(wo, wi, &h))
        return;
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

#endif /* PATHCL_FULL_BSDF */
