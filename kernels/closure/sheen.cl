/* The sheen (KHR_materials_sheen): the "Charlie" lobe of closure/sheen.h on the shading
 * normal, added over the base it scales, its samples, and what a delta sample of the base
 * keeps under it. The model is in closure/bsdf.cl. */
#include "closure/bsdf_params.cl"
#include "closure/layer_albedo.cl"
#include "closure/sheen.h"
#include "features.h"
#include "geom/ray_offset.cl"
#include "util/math.cl"
#include "util/sincos.cl"

#ifdef PATHCL_HAS_SHEEN

/* Uniform hemisphere density: the sheen's sampling (sheen_sample). */
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

/* A sample of the sheen: uniform over the hemisphere of the shading normal, as Cycles
 * samples its velvet lobe. The Charlie distribution peaks at fibres lying in the surface,
 * whose mirror directions are mostly below it, so sampling D itself would waste most
 * samples; cosine-weighted sampling would weight grazing wi by 1 / cos_i. Returns true
 * when *s is a direction to be weighed by every lobe (bsdf_sample.cl), false when there
 * is none. */
static inline bool sheen_sample(const SurfacePoint* sp, float2 u, BsdfSample* s)
{
    *s = no_bsdf_sample();
    float z = u.x;
    float r = sqrt(fmax(0.0f, 1.0f - z * z));
    float cos_phi, sin_phi = sin_cos_turns(u.y, &cos_phi);
    float3 t, b;
    make_basis(sp->ns, &t, &b);
    s->wi = to_world((float3)(r * cos_phi, r * sin_phi, z), t, b, sp->ns);
    return z > 0.0f && above_surface(sp, dot(s->wi, sp->ng));
}

/* What a delta sample of the base keeps under the sheen. */
static inline float sheen_delta_scale(const BsdfParams* p, const SurfacePoint* sp, float3 wi)
{
    return p->sheen_max > 0.0f ? sheen_base_scale(p, sheen_albedo(p, fabs(dot(wi, sp->ns)))) : 1.0f;
}

#endif /* PATHCL_HAS_SHEEN */
