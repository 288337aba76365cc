/* The watertight ray/triangle test of Woop, Benthin and Wald (JCGT 2013), with the ray's
 * shear set up once per ray, and pbrt-v3's conservative bound on t that keeps spawned
 * rays off their own surface.
 *
 * Watertightness needs each edge function computed identically by both triangles that
 * share the edge, so floating-point contraction (fma) is off for this file: an fma would
 * round the two orders of a shared edge differently and let rays slip between them. */
#include "types.h"
#include "util/math.cl"

#pragma OPENCL FP_CONTRACT OFF

#ifdef cl_khr_fp64
#pragma OPENCL EXTENSION cl_khr_fp64 : enable
#endif

typedef struct {
    float3 origin;
    float3 inv_dir;
    /* Woop's shear: the permutation making dir.z the largest axis, and shear constants. */
    uint4 permutation;
    float3 shear; /* (Sx, Sy, Sz) */
} RayTraversal;

static inline RayTraversal ray_traversal_setup(float3 origin, float3 dir)
{
    RayTraversal r;
    r.origin = origin;
    r.inv_dir = 1.0f / dir;
    float3 a = fabs(dir);
    uint kz = (a.x > a.y) ? ((a.x > a.z) ? 0u : 2u) : ((a.y > a.z) ? 1u : 2u);
    uint kx = (kz + 1u) % 3u;
    uint ky = (kx + 1u) % 3u;
    float4 d4 = (float4)(dir, 0.0f);
    float dz = (kz == 0u) ? dir.x : ((kz == 1u) ? dir.y : dir.z);
    if (dz < 0.0f) { /* keep the winding: swap x and y when the permuted z flips */
        uint t = kx;
        kx = ky;
        ky = t;
    }
    r.permutation = (uint4)(kx, ky, kz, 3u);
    float4 pd = shuffle(d4, r.permutation);
    r.shear = (float3)(pd.x / pd.z, pd.y / pd.z, 1.0f / pd.z);
    return r;
}

/* Watertight ray/triangle test. On a hit closer than *t_max, updates hit and *t_max. */
static inline bool ray_triangle(const RayTraversal* r, __global const Triangle* tri, float t_max, float* t_out,
                                float* b1_out, float* b2_out)
{
    float4 o = (float4)(r->origin, 0.0f);
    float4 a = shuffle(tri->v0 - o, r->permutation);
    float4 b = shuffle(tri->v1 - o, r->permutation);
    float4 c = shuffle(tri->v2 - o, r->permutation);
    float sx = r->shear.x, sy = r->shear.y, sz = r->shear.z;
    float ax = a.x - sx * a.z, ay = a.y - sy * a.z;
    float bx = b.x - sx * b.z, by = b.y - sy * b.z;
    float cx = c.x - sx * c.z, cy = c.y - sy * c.z;
    float u = cx * by - cy * bx;
    float v = ax * cy - ay * cx;
    float w = bx * ay - by * ax;
#ifdef cl_khr_fp64
    /* An edge function of exactly zero may be a rounding artefact: redo it in double. */
    if (u == 0.0f || v == 0.0f || w == 0.0f) {
        u = (float)((double)cx * (double)by - (double)cy * (double)bx);
        v = (float)((double)ax * (double)cy - (double)ay * (double)cx);
        w = (float)((double)bx * (double)ay - (double)by * (double)ax);
    }
#endif
    if ((u < 0.0f || v < 0.0f || w < 0.0f) && (u > 0.0f || v > 0.0f || w > 0.0f))
        return false;
    float det = u + v + w;
    if (det == 0.0f)
        return false;
    float az = sz * a.z, bz = sz * b.z, cz = sz * c.z;
    float t_scaled = u * az + v * bz + w * cz;
    /* Compare t with (0, t_max) without dividing: flip signs to make det positive. */
    float sign = (det < 0.0f) ? -1.0f : 1.0f;
    float det_abs = det * sign;
    float ts = t_scaled * sign;
    if (!(ts > 0.0f) || !(ts < t_max * det_abs)) /* NaN (a degenerate ray) never hits */
        return false;
    float inv_det = 1.0f / det;
    float t = t_scaled * inv_det;
    /* Conservative bound on the rounding error of t (pbrt-v3, section 3.9.6): a hit closer
     * than that may be the surface the ray starts on. Spawned origins are offset by the
     * hit point's error bound, but that bound is zero for a point exactly on a coordinate
     * plane (x = 0 walls), so this test is what stops those rays re-hitting the plane. */
    float max_zt = fmax(fabs(az), fmax(fabs(bz), fabs(cz)));
    float max_xt = fmax(fabs(ax), fmax(fabs(bx), fabs(cx)));
    float max_yt = fmax(fabs(ay), fmax(fabs(by), fabs(cy)));
    float delta_x = FLOAT_GAMMA(5) * (max_xt + max_zt);
    float delta_y = FLOAT_GAMMA(5) * (max_yt + max_zt);
    float delta_z = FLOAT_GAMMA(3) * max_zt;
    float delta_e = 2.0f * (FLOAT_GAMMA(2) * max_xt * max_yt + delta_y * max_xt + delta_x * max_yt);
    float max_e = fmax(fabs(u), fmax(fabs(v), fabs(w)));
    float delta_t = 3.0f * (FLOAT_GAMMA(3) * max_e * max_zt + delta_e * max_zt + delta_z * max_e) * fabs(inv_det);
    if (!(t > delta_t))
        return false;
    *t_out = t;
    *b1_out = v * inv_det;
    *b2_out = w * inv_det;
    return true;
}

#pragma OPENCL FP_CONTRACT ON
