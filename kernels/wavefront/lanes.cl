/* Paths in lanes: the wavefront's shading kernels run LANES paths per work-item, each value
 * a vector of LANES floats (a LaneF), one path per component, so that a CPU runs them as
 * SIMD instructions whatever its OpenCL compiler does. (PoCL 3.1 could in principle run
 * scalar code on LANES work-items per instruction, but it runs LLVM's SLP vectorizer over
 * each kernel before it makes the work-item loop, and the <2 x float> values SLP makes of
 * any two alike chains of arithmetic, which shading is full of, stop the loop vectorizer:
 * docs/architecture.md, "Paths in lanes".)
 *
 * Conventions: a mask is a LaneI, true where a comparison is (-1 in a vector, 1 as a
 * scalar); select(if_false, if_true, mask). A lane whose path is not taking part computes
 * on harmless inputs (index 0 for gathers) and its results are not stored. LANES is a
 * build option: 8 on CPUs, 1 (one path per work-item) elsewhere (host/render/wavefront.cpp). */
#include "util/compat.h"

#ifndef LANES
#define LANES 8
#endif

#if LANES == 8
typedef float8 LaneF;
typedef int8 LaneI;
#define LANE_ANY(mask) any(mask)
#define LANE_LOAD(p) vload8(0, p)
#define LANE_STORE(v, p) vstore8(v, 0, p)
#elif LANES == 1
/* One path per work-item, for devices that run work-items in lanes themselves (GPUs). A
 * scalar comparison gives 1, not -1, for true: masks are only combined with & | and !,
 * and read by select and LANE_ANY, which take either. */
typedef float LaneF;
typedef int LaneI;
#define LANE_ANY(mask) ((mask) != 0)
#define LANE_LOAD(p) (*(p))
#define LANE_STORE(v, p) (*(p) = (v))
#else
#error "wavefront/lanes.cl: LANES is 8 (CPUs) or 1"
#endif

PATHCL_ALWAYS_INLINE static inline LaneF lane_splat(float v)
{
    return (LaneF)(v);
}

PATHCL_ALWAYS_INLINE static inline LaneI lane_splat_i(int v)
{
    return (LaneI)(v);
}

/* Element i * stride of base per lane: a field of an array of structs (stride: the
 * struct's size in words) at the lanes' indices. OpenCL C has no gather: LANES loads. */
PATHCL_ALWAYS_INLINE static inline LaneF lane_gather(__global const float* base, LaneI i, int stride)
{
    i *= stride;
#if LANES == 8
    return (LaneF)(base[i.s0], base[i.s1], base[i.s2], base[i.s3], base[i.s4], base[i.s5], base[i.s6], base[i.s7]);
#else
    return base[i];
#endif
}

PATHCL_ALWAYS_INLINE static inline LaneI lane_gather_i(__global const int* base, LaneI i, int stride)
{
    i *= stride;
#if LANES == 8
    return (LaneI)(base[i.s0], base[i.s1], base[i.s2], base[i.s3], base[i.s4], base[i.s5], base[i.s6], base[i.s7]);
#else
    return base[i];
#endif
}

/* The words of a struct array's member, for lane_gather: its first word and the struct's
 * size in words. */
#define LANE_FIELD(array, member) ((__global const float*)&(array)[0].member)
#define LANE_FIELD_I(array, member) ((__global const int*)&(array)[0].member)
#define LANE_STRIDE(array) ((int)(sizeof((array)[0]) / 4u))

/* Three LaneFs: a point, direction or colour per lane. */
typedef struct {
    LaneF x, y, z;
} Lane3;

PATHCL_ALWAYS_INLINE static inline Lane3 lane3(LaneF x, LaneF y, LaneF z)
{
    Lane3 v;
    v.x = x;
    v.y = y;
    v.z = z;
    return v;
}

PATHCL_ALWAYS_INLINE static inline Lane3 lane3_splat(float s)
{
    return lane3(lane_splat(s), lane_splat(s), lane_splat(s));
}

/* The xyz of a float4 member of a struct array, per lane. */
PATHCL_ALWAYS_INLINE static inline Lane3 lane3_gather(__global const float* xyz, LaneI i, int stride)
{
    return lane3(lane_gather(xyz, i, stride), lane_gather(xyz + 1, i, stride), lane_gather(xyz + 2, i, stride));
}
#define LANE3_GATHER(array, member, i) lane3_gather(LANE_FIELD(array, member), i, LANE_STRIDE(array))

PATHCL_ALWAYS_INLINE static inline Lane3 lane3_add(Lane3 a, Lane3 b)
{
    return lane3(a.x + b.x, a.y + b.y, a.z + b.z);
}

PATHCL_ALWAYS_INLINE static inline Lane3 lane3_sub(Lane3 a, Lane3 b)
{
    return lane3(a.x - b.x, a.y - b.y, a.z - b.z);
}

PATHCL_ALWAYS_INLINE static inline Lane3 lane3_mul(Lane3 a, Lane3 b)
{
    return lane3(a.x * b.x, a.y * b.y, a.z * b.z);
}

PATHCL_ALWAYS_INLINE static inline Lane3 lane3_scale(Lane3 a, LaneF s)
{
    return lane3(a.x * s, a.y * s, a.z * s);
}

PATHCL_ALWAYS_INLINE static inline Lane3 lane3_div(Lane3 a, LaneF s)
{
    return lane3(a.x / s, a.y / s, a.z / s);
}

PATHCL_ALWAYS_INLINE static inline Lane3 lane3_neg(Lane3 a)
{
    return lane3(-a.x, -a.y, -a.z);
}

PATHCL_ALWAYS_INLINE static inline Lane3 lane3_fabs(Lane3 a)
{
    return lane3(fabs(a.x), fabs(a.y), fabs(a.z));
}

PATHCL_ALWAYS_INLINE static inline LaneF lane3_dot(Lane3 a, Lane3 b)
{
    return a.x * b.x + a.y * b.y + a.z * b.z;
}

PATHCL_ALWAYS_INLINE static inline Lane3 lane3_cross(Lane3 a, Lane3 b)
{
    return lane3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}

PATHCL_ALWAYS_INLINE static inline LaneF lane3_length(Lane3 a)
{
    return sqrt(lane3_dot(a, a));
}

PATHCL_ALWAYS_INLINE static inline LaneF lane3_max(Lane3 a)
{
    return fmax(a.x, fmax(a.y, a.z));
}

/* mask ? a : b per lane. */
PATHCL_ALWAYS_INLINE static inline Lane3 lane3_select(LaneI mask, Lane3 a, Lane3 b)
{
    return lane3(select(b.x, a.x, mask), select(b.y, a.y, mask), select(b.z, a.z, mask));
}

PATHCL_ALWAYS_INLINE static inline LaneI lane3_equal(Lane3 a, Lane3 b)
{
    return (a.x == b.x) & (a.y == b.y) & (a.z == b.z);
}
