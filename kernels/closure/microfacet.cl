/* GGX microfacet sampling: the density of visible normals, visible-normal sampling by
 * spherical caps (Dupuy and Benyoub 2023), and refraction through a facet. */
#include "closure/bsdf_params.cl"
#include "closure/ggx.h"
#include "features.h"
#include "util/compat.h"
#include "util/sincos.cl"

#ifdef PATHCL_FULL_BSDF

/* The facet normal that reflects wo into wi, in *h; false where they are opposite. */
static inline bool reflection_half_vector(float3 wo, float3 wi, float3* h)
{
    float3 sum = wo + wi;
    float len = length(sum);
    if (!(len > 0.0f))
        return false;
    *h = sum / len;
    return true;
}

/* Density of visible normals wm as seen from wo (wo.z > 0). */
static inline float ggx_visible_pdf(float3 wo, float3 wm, float a2)
{
    float c = dot(wo, wm);
    if (!(c > 0.0f) || !(wm.z > 0.0f))
        return 0.0f;
    return ggx_g1(wo, a2) * c * ggx_d(wm, a2) / wo.z;
}

/* Visible-normal sampling by spherical caps (Dupuy and Benyoub 2023) for alpha ax along x
 * and ay along y; wo.z > 0. */
PATHCL_ALWAYS_INLINE static inline float3 ggx_sample_visible(float3 wo, float ax, float ay, float2 u)
{
    float3 w = normalize((float3)(wo.x * ax, wo.y * ay, wo.z));
    float z = fma(1.0f - u.y, 1.0f + w.z, -w.z);
    float sin_theta = sqrt(clamp(1.0f - z * z, 0.0f, 1.0f));
    float cos_phi, sin_phi = sin_cos_turns(u.x, &cos_phi); /* phi = 2 pi u.x */
    float3 h = (float3)(sin_theta * cos_phi, sin_theta * sin_phi, z) + w;
    float3 wm = (float3)(h.x * ax, h.y * ay, fmax(h.z, 0.0f));
    float len = length(wm);
    return len > 0.0f ? wm / len : (float3)(0.0f, 0.0f, 1.0f);
}

#ifdef PATHCL_HAS_ANISOTROPY

/* The conductor's anisotropic GGX lobe (KHR_materials_anisotropy) in the frame of
 * bsdf_frame: alpha_t along x, alpha_b along y. */
static inline float conductor_ggx_d(const BsdfParams* p, float3 wm)
{
    return ggx_d_aniso(wm, p->alpha_t, p->alpha_b);
}

static inline float conductor_ggx_g1(const BsdfParams* p, float3 w)
{
    return ggx_g1_aniso(w, p->alpha_t, p->alpha_b);
}

/* Density of its visible normals wm as seen from wo (wo.z > 0). */
static inline float conductor_visible_pdf(const BsdfParams* p, float3 wo, float3 wm)
{
    float c = dot(wo, wm);
    if (!(c > 0.0f) || !(wm.z > 0.0f))
        return 0.0f;
    return conductor_ggx_g1(p, wo) * c * conductor_ggx_d(p, wm) / wo.z;
}

#endif /* PATHCL_HAS_ANISOTROPY */

/* A visible facet of the conductor's lobe (anisotropic or not); wo.z > 0. */
static inline float3 conductor_sample_visible(const BsdfParams* p, float3 wo, float2 u)
{
#ifdef PATHCL_HAS_ANISOTROPY
    return ggx_sample_visible(wo, p->alpha_t, p->alpha_b, u);
#else
    return ggx_sample_visible(wo, p->alpha, p->alpha, u);
#endif
}

/* A visible facet of the dielectric interface's lobe (anisotropic on layer_anisotropic
 * materials); wo.z > 0. */
static inline float3 interface_sample_visible(const BsdfParams* p, float3 wo, float2 u)
{
#ifdef PATHCL_HAS_ANISOTROPY
    if (layer_anisotropic(p))
        return ggx_sample_visible(wo, p->alpha_t, p->alpha_b, u);
#endif
    return ggx_sample_visible(wo, p->alpha, p->alpha, u);
}

/* The interface lobe's D G1(wo) G1(wi) and the density of its visible normal wm seen from
 * wo (times G1(wo) c D / wo.z), anisotropic or not; wo.z > 0. */
static inline float interface_dgg(const BsdfParams* p, float3 wm, float3 wo, float3 wi)
{
#ifdef PATHCL_HAS_ANISOTROPY
    if (layer_anisotropic(p))
        return conductor_ggx_d(p, wm) * conductor_ggx_g1(p, wo) * conductor_ggx_g1(p, wi);
#endif
    float a2 = p->alpha * p->alpha;
    return ggx_d(wm, a2) * ggx_g1(wo, a2) * ggx_g1(wi, a2);
}

static inline float interface_visible_pdf(const BsdfParams* p, float3 wo, float3 wm)
{
#ifdef PATHCL_HAS_ANISOTROPY
    if (layer_anisotropic(p))
        return conductor_visible_pdf(p, wo, wm);
#endif
    return ggx_visible_pdf(wo, wm, p->alpha * p->alpha);
}

/* Refraction of wo about n (wo on n's side), eta = far ior / near ior. False under TIR. */
static inline bool refract_dir(float3 wo, float3 n, float eta, float3* wt)
{
    float cos_i = dot(n, wo);
    float sin2_t = fmax(0.0f, 1.0f - cos_i * cos_i) / (eta * eta);
    if (sin2_t >= 1.0f)
        return false;
    float cos_t = sqrt(1.0f - sin2_t);
    *wt = -wo / eta + (cos_i / eta - cos_t) * n;
    return true;
}

#endif /* PATHCL_FULL_BSDF */
