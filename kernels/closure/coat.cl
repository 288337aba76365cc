/* The clear coat (KHR_materials_clearcoat): its GGX reflection in its own frame, added
 * over the base it scales, and its samples. The model is in closure/bsdf.cl. */
#include "closure/bsdf_params.cl"
#include "closure/fresnel.h"
#include "closure/ggx.h"
#include "closure/layer_albedo.cl"
#include "closure/microfacet.cl"
#include "features.h"
#include "geom/ray_offset.cl"
#include "util/math.cl"

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
    float3 h;
    if (!reflection_half_vector(wo_c, wi_c, &h))
        return;
    float cos_h = dot(wo_c, h);
    float a2 = p->coat_alpha * p->coat_alpha;
    float fr = p->coat * fresnel_dielectric(cos_h, COAT_IOR);
    e->f_cos += (float3)(fr * ggx_d(h, a2) * ggx_g1(wo_c, a2) * ggx_g1(wi_c, a2) / (4.0f * wo_c.z));
    e->pdf += p->lobes.coat * ggx_visible_pdf(wo_c, h, a2) / (4.0f * cos_h);
}

/* A sample of the clear coat's reflection: a visible facet of the coat in its own frame
 * (the mirror direction when smooth). Returns true when *s is a direction to be weighed
 * by every lobe (bsdf_sample.cl); false when *s is final: the smooth coat's delta sample,
 * or none. */
static inline bool coat_sample(const BsdfParams* p, const SurfacePoint* sp, float3 wo, float2 u, BsdfSample* s)
{
    *s = no_bsdf_sample();
    float3 t, b;
    make_basis(p->coat_n, &t, &b);
    float3 wo_c = to_local(wo, t, b, p->coat_n);
    if (!(wo_c.z > 0.0f))
        return false;
    bool smooth = p->coat_alpha < ALPHA_DELTA;
    float3 wm = smooth ? (float3)(0.0f, 0.0f, 1.0f) : ggx_sample_visible(wo_c, p->coat_alpha, p->coat_alpha, u);
    float3 wi_c = 2.0f * dot(wo_c, wm) * wm - wo_c;
    s->wi = to_world(wi_c, t, b, p->coat_n);
    if (!(wi_c.z > 0.0f) || !above_surface(sp, dot(s->wi, sp->ng)))
        return false;
    if (smooth) {
        s->delta = true;
        s->pdf = p->lobes.coat;
        s->weight = (float3)(p->coat * fresnel_dielectric(wo_c.z, COAT_IOR) / s->pdf);
        return false;
    }
    return true;
}

#endif /* PATHCL_HAS_CLEARCOAT */
