/* An instance's affine maps (types.h Instance) applied to points, directions and normals,
 * with pbrt's bound on the rounding error of a transformed point. Compiled only for
 * scenes with instanced meshes (PATHCL_HAS_INSTANCES). */
#include "features.h"
#include "types.h"
#include "util/math.cl"

#ifdef PATHCL_HAS_INSTANCES

/* The map's rows applied to a point (with the translation) and to a direction (without). */
static inline float3 affine_point(const float4* rows, float3 p)
{
    return (float3)(dot(rows[0].xyz, p) + rows[0].w, dot(rows[1].xyz, p) + rows[1].w, dot(rows[2].xyz, p) + rows[2].w);
}

static inline float3 affine_direction(const float4* rows, float3 v)
{
    return (float3)(dot(rows[0].xyz, v), dot(rows[1].xyz, v), dot(rows[2].xyz, v));
}

/* A bound on |affine_point(rows, p) - exact|: gamma(3) (|row.xyz| . |p| + |row.w|) per row
 * (pbrt-v4's Transform of a point). */
static inline float3 affine_point_error(const float4* rows, float3 p)
{
    float3 a = fabs(p);
    return FLOAT_GAMMA(3) * (float3)(dot(fabs(rows[0].xyz), a) + fabs(rows[0].w),
                                     dot(fabs(rows[1].xyz), a) + fabs(rows[1].w),
                                     dot(fabs(rows[2].xyz), a) + fabs(rows[2].w));
}

/* A normal of the instance's mesh in render space: the inverse transpose of to_render is
 * the transpose of to_object. Not normalized. */
static inline float3 instance_normal(const Instance* inst, float3 n)
{
    return n.x * inst->to_object[0].xyz + n.y * inst->to_object[1].xyz + n.z * inst->to_object[2].xyz;
}

#endif /* PATHCL_HAS_INSTANCES */
