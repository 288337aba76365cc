/* The environment at infinity: an equirectangular map (docs/gltf.md)
 *   theta = pi v (from +Y), phi = 2 pi u, d = (sin theta sin phi, cos theta, -sin theta cos phi)
 * rotated about +Y by the light's rotation, piecewise constant per texel, importance-
 * sampled from a 2D piecewise-constant distribution over the same texels (weights
 * luminance x sin theta, built by host/compile/environment.cpp). */
#include "features.h"
#include "kernel_data.cl"
#include "util/atan.cl"
#include "util/math.cl"
#include "util/sincos.cl"

#ifdef PATHCL_HAS_ENVIRONMENT

/* Continuous sample of a piecewise-constant 1D distribution from its n + 1 CDF values:
 * returns x in [0, 1), its cell index and the density p(x) = n (cdf[i+1] - cdf[i]). */
static inline float sample_cdf(__global const float* cdf, uint n, float u, uint* index, float* pdf)
{
    uint lo = 0u, hi = n; /* invariant: cdf[lo] <= u < cdf[hi] */
    while (lo + 1u < hi) {
        uint mid = (lo + hi) / 2u;
        if (cdf[mid] <= u)
            lo = mid;
        else
            hi = mid;
    }
    float c0 = cdf[lo], width = cdf[lo + 1u] - c0;
    *index = lo;
    *pdf = width * (float)n;
    float du = (width > 0.0f) ? clamp((u - c0) / width, 0.0f, 1.0f) : 0.5f;
    return fmin(((float)lo + du) / (float)n, 0x1.fffffep-1f);
}

/* World direction <-> map direction: the map is turned by the light's rotation about +Y. */
static inline float3 environment_to_world(const EnvironmentLight* env, float3 d)
{
    float c = env->cos_rotation, s = env->sin_rotation;
    return (float3)(c * d.x + s * d.z, d.y, -s * d.x + c * d.z);
}

static inline float3 environment_from_world(const EnvironmentLight* env, float3 d)
{
    float c = env->cos_rotation, s = env->sin_rotation;
    return (float3)(c * d.x - s * d.z, d.y, s * d.x + c * d.z);
}

/* The texel a world direction falls in: u = phi / 2 pi from atan2(x, -z), v = theta / pi
 * from atan2(sqrt(x^2 + z^2), y) (rather than acos(y): the same angle, one fast routine). */
static inline uint2 environment_texel(const EnvironmentLight* env, float3 world_dir)
{
    float3 d = environment_from_world(env, world_dir);
    uint w = env->width, h = env->height;
    float u = atan2_fast(d.x, -d.z) * (0.5f * INV_PI);
    if (u < 0.0f)
        u += 1.0f;
    float v = atan2_fast(sqrt(d.x * d.x + d.z * d.z), d.y) * INV_PI;
    return (uint2)(min((uint)(u * (float)w), w - 1u), min((uint)(v * (float)h), h - 1u));
}

/* The radiance of texel t. */
static inline float3 environment_radiance(const KernelData* kd, const EnvironmentLight* env, uint2 t)
{
    return kd->env_texels[t.y * env->width + t.x].xyz;
}

/* Solid-angle pdf of light_sample choosing world_dir, which falls in texel t, on the
 * environment, selection pmf included: pmf p(u, v) / (2 pi^2 sin theta). */
static inline float environment_pdf(const KernelData* kd, const EnvironmentLight* env, float pmf, uint2 t,
                                    float3 world_dir)
{
    uint w = env->width, h = env->height;
    float sin_theta = sqrt(fmax(0.0f, 1.0f - world_dir.y * world_dir.y));
    if (!(sin_theta > 0.0f))
        return 0.0f;
    __global const float* row = kd->env_conditional + t.y * (w + 1u);
    float p_uv =
        (kd->env_marginal[t.y + 1u] - kd->env_marginal[t.y]) * (float)h * (row[t.x + 1u] - row[t.x]) * (float)w;
    return pmf * p_uv / (2.0f * PI_F * PI_F * sin_theta);
}

/* Samples a world direction; returns its radiance, *pdf as environment_pdf (0: none). */
static inline float3 environment_sample(const KernelData* kd, const EnvironmentLight* env, float pmf, float2 u,
                                        float3* world_dir, float* pdf)
{
    uint w = env->width, h = env->height;
    uint row, col;
    float pdf_v, pdf_u;
    float v = sample_cdf(kd->env_marginal, h, u.y, &row, &pdf_v);
    float uu = sample_cdf(kd->env_conditional + row * (w + 1u), w, u.x, &col, &pdf_u);
    float cos_theta, sin_theta = sin_cos_turns(0.5f * v, &cos_theta); /* theta = pi v */
    float cos_phi, sin_phi = sin_cos_turns(uu, &cos_phi);             /* phi = 2 pi uu */
    *pdf = 0.0f;
    if (!(sin_theta > 0.0f) || !(pdf_u * pdf_v > 0.0f))
        return (float3)(0.0f);
    float3 d = (float3)(sin_theta * sin_phi, cos_theta, -sin_theta * cos_phi);
    *world_dir = environment_to_world(env, d);
    *pdf = pmf * pdf_u * pdf_v / (2.0f * PI_F * PI_F * sin_theta);
    return kd->env_texels[row * w + col].xyz;
}

#endif /* PATHCL_HAS_ENVIRONMENT */
