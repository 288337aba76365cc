/* Normal mapping: the mapped shading normal in the interpolated tangent frame, and the
 * bend that keeps a mapped normal from reflecting below the geometric surface. Compiled
 * only for scenes with normal textures (PATHCL_HAS_NORMAL_MAPS). */
#include "features.h"
#include "geom/tangent_frame.cl"
#include "types.h"

#ifdef PATHCL_HAS_NORMAL_MAPS

/* The normal-mapped shading normal: n_t = normalize((texel * 2 - 1) * (scale, scale, 1))
 * in the frame T, B = w cross(N, T), N, where N is the interpolated normal and T the
 * interpolated tangent made orthogonal to it. Returns n unchanged where the tangent or the
 * mapped vector is degenerate (a zero or NaN tangent, a texel of (0.5, 0.5, 0.5)). */
static inline float3 normal_from_map(float3 n, TriangleTangents t, float b1, float b2, float3 texel, float scale)
{
    float3 tangent, bitangent;
    if (!tangent_frame(n, t, b1, b2, &tangent, &bitangent))
        return n;
    float3 nt = (2.0f * texel - 1.0f) * (float3)(scale, scale, 1.0f);
    float3 mapped = nt.x * tangent + nt.y * bitangent + nt.z * n;
    float mapped_len = length(mapped);
    if (!(mapped_len > 1.0e-6f) || !isfinite(mapped_len))
        return n;
    return mapped / mapped_len;
}

/* A shading normal that would mirror wo below the geometric surface (or that lies below
 * it) is turned towards ng, in the plane of ng and ns, just far enough that the mirror
 * direction of wo leaves at the height t = min(0.9 cos_o, 0.01) above the surface: the
 * rule of Cycles' ensure_valid_specular_reflection. ng is on wo's side. Solved as a half
 * vector rather than Cycles' quartic: in the frame (x, y, ng), x the part of ns
 * orthogonal to ng, the wanted mirror direction is r = (sqrt(ix^2 + iz^2 - t^2), -wo.y, t)
 * (r.z = t, and wo + r in the plane of x and ng), so the normal is normalize(wo + r) =
 * normalize((ix + sqrt(ix^2 + iz^2 - t^2)) x + (iz + t) ng), its x part computed without
 * cancellation. The result has n.ng > 0 and n.wo > 0: no direction is lost to a normal
 * pointing into the surface, and no NaN comes out of one pointing straight into it. */
static inline float3 keep_reflection_above_surface(float3 ng, float3 wo, float3 ns)
{
    float iz = dot(wo, ng);
    float t = fmin(0.9f * iz, 0.01f);
    float3 r = 2.0f * dot(ns, wo) * ns - wo;
    if (dot(ns, ng) > 0.0f && dot(r, ng) >= t)
        return ns;
    float3 x = ns - dot(ns, ng) * ng;
    float x_len = length(x);
    if (!(x_len > 1.0e-7f) || !(iz > 0.0f))
        return ng; /* ns along -ng (no plane to turn it in), or wo in the surface */
    x /= x_len;
    float ix = dot(wo, x);
    float s = sqrt(fmax(0.0f, ix * ix + (iz - t) * (iz + t)));
    float nx = ix >= 0.0f ? ix + s : (iz - t) * (iz + t) / (s - ix);
    return normalize(nx * x + (iz + t) * ng);
}

#endif /* PATHCL_HAS_NORMAL_MAPS */
