/* GGX microfacet sampling: the density of visible normals, visible-normal sampling by
 * spherical caps (Dupuy and Benyoub 2023), and refraction through a facet. */
#include "closure/ggx.h"
#include "features.h"
#include "util/sincos.cl"

#ifdef PATHCL_FULL_BSDF

/* Density of visible normals wm as seen from wo (wo.z > 0). */
static inline float ggx_visible_pdf(float3 wo, float3 wm, float a2)
{
    float c = dot(wo, wm);
    if (!(c > 0.0f) || !(wm.z > 0.0f))
        return 0.0f;
    return ggx_g1(wo, a2) * c * ggx_d(wm, a2) / wo.z;
}

/* Visible-normal sampling by spherical caps (Dupuy and Benyoub 2023); wo.z > 0. */
static inline float3 ggx_sample_visible(float3 wo, float alpha, float2 u)
{
    float3 w = normalize((float3)(wo.x * alpha, wo.y * alpha, wo.z));
    float z = fma(1.0f - u.y, 1.0f + w.z, -w.z);
    float sin_theta = sqrt(clamp(1.0f - z * z, 0.0f, 1.0f));
    float cos_phi, sin_phi = sin_cos_turns(u.x, &cos_phi); /* phi = 2 pi u.x */
    float3 h = (float3)(sin_theta * cos_phi, sin_theta * sin_phi, z) + w;
    float3 wm = (float3)(h.x * alpha, h.y * alpha, fmax(h.z, 0.0f));
    float len = length(wm);
    return len > 0.0f ? wm / len : (float3)(0.0f, 0.0f, 1.0f);
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
