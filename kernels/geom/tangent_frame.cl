/* The interpolated tangent frame at a hit, which normal maps and the anisotropy
 * direction are given in: the hit triangle's vertex tangents (an instance's mapped to
 * render space) and the frame T, B = w cross(N, T) around a normal N. Compiled only for
 * scenes that read it (normal textures or KHR_materials_anisotropy). */
#include "bvh/instance.cl"
#include "bvh/traversal.cl"
#include "features.h"
#include "kernel_data.cl"
#include "types.h"

#if defined(PATHCL_HAS_NORMAL_MAPS) || defined(PATHCL_HAS_ANISOTROPY)

/* The hit triangle's vertex tangents in render space: an instance's are mapped as
 * directions (and renormalized), their handedness flipped by a mirroring map. */
static inline TriangleTangents hit_tangents(const KernelData* kd, Hit hit)
{
    TriangleTangents t = kd->tangents[hit.triangle];
#ifdef PATHCL_HAS_INSTANCES
    Instance inst = kd->instances[hit.instance];
    if (!(inst.flags & INSTANCE_IDENTITY)) {
        float w = (inst.flags & INSTANCE_MIRRORED) ? -1.0f : 1.0f;
        t.t0 = (float4)(normalize(affine_direction(inst.to_render, t.t0.xyz)), w * t.t0.w);
        t.t1 = (float4)(normalize(affine_direction(inst.to_render, t.t1.xyz)), w * t.t1.w);
        t.t2 = (float4)(normalize(affine_direction(inst.to_render, t.t2.xyz)), w * t.t2.w);
    }
#endif
    return t;
}

/* The tangent T (the interpolated vertex tangent made orthogonal to the unit normal n)
 * and the bitangent B = w cross(n, T) at barycentrics (b1, b2). False where the tangent is
 * degenerate (zero, NaN, or along n). */
static inline bool tangent_frame(float3 n, TriangleTangents t, float b1, float b2, float3* tangent, float3* bitangent)
{
    float b0 = 1.0f - b1 - b2;
    float4 tw = b0 * t.t0 + b1 * t.t1 + b2 * t.t2;
    float3 tn = tw.xyz - dot(tw.xyz, n) * n;
    float len = length(tn);
    if (!(len > 1.0e-6f) || !isfinite(len))
        return false;
    *tangent = tn / len;
    *bitangent = (tw.w < 0.0f ? -1.0f : 1.0f) * cross(n, *tangent);
    return true;
}

#endif
