/* The conductor: Kulla and Conty's multiple-scattering lobe (its single-scattering GGX
 * reflection is evaluated with the dielectric layer's, closure/specular.cl) and its
 * samples: the ideal mirror, or a visible GGX facet. The model is in closure/bsdf.cl. */
#include "closure/bsdf_params.cl"
#include "closure/fresnel_layer.cl"
#include "closure/layer_albedo.cl"
#include "closure/microfacet.cl"
#include "features.h"
#include "geom/ray_offset.cl"
#include "util/math.cl"

#ifdef PATHCL_FULL_BSDF

/* Kulla and Conty's multiple-scattering lobe towards wi (reflected, in the frame of
 * bsdf_frame): reciprocal, and with it a white rough conductor reflects everything.
 * Sampled with the diffuse lobe. */
static inline void conductor_ms_eval(const BsdfParams* p, float3 wi, BsdfEval* e)
{
    if (conductor_rough(p) && p->metallic > 0.0f)
        e->f_cos += p->ms_scale * ((1.0f - p->conductor_e_o) * (1.0f - conductor_albedo(p, wi)) * wi.z);
}

/* A sample of the conductor from wo_l (in the frame t, b, ns of bsdf_frame). Returns true
 * with *wi the reflection off a visible facet, to be weighed by every lobe
 * (bsdf_sample.cl); false when *s is final: the ideal mirror's delta sample, weight
 * F / (selection probability), or none. */
static inline bool conductor_sample(const BsdfParams* p, const SurfacePoint* sp, float3 wo_l, float2 u, float3 t,
                                    float3 b, float3* wi, BsdfSample* s)
{
    if (!conductor_rough(p)) {
        *wi = (float3)(-wo_l.x, -wo_l.y, wo_l.z);
        s->wi = to_world(*wi, t, b, sp->ns);
        if (!(wi->z > 0.0f) || !above_surface(sp, dot(s->wi, sp->ng)))
            return false;
        s->delta = true;
        s->pdf = p->lobes.conductor;
        s->weight = p->metallic * fresnel_schlick(p->base_color, p->cos_o) / p->lobes.conductor;
        return false;
    }
    if (!(wo_l.z > 0.0f))
        return false;
    float3 wm = conductor_sample_visible(p, wo_l, u);
    *wi = 2.0f * dot(wo_l, wm) * wm - wo_l;
    return true;
}

#endif /* PATHCL_FULL_BSDF */
