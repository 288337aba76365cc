/* The watertight ray/triangle test of Woop, Benthin and Wald (JCGT 2013), with the ray's
 * shear set up once per ray, and pbrt-v3's conservative bound on t that keeps spawned
 * rays off their own surface (asked again in double where float's bound rejects a hit).
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
    float3 shear;           /* (Sx, Sy, Sz) */
    float3 origin_permuted; /* the origin's coordinates in permuted order */
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
    r.origin_permuted = shuffle((float4)(origin, 0.0f), r.permutation).xyz;
    return r;
}

/* Bit k set where lane k of mask is set (mask lanes 0 or -1): one branch for "any lane". */
static inline uint lane_bits(int8 mask)
{
    int8 b = mask & (int8)(1, 2, 4, 8, 16, 32, 64, 128);
    int4 h = b.lo | b.hi;
    int2 q = h.lo | h.hi;
    return (uint)(q.x | q.y);
}

/* The traversal's leaf test is called from both traversals of the path kernel, which
 * makes it too large for LLVM's inliner to copy; a call costs its five vector results a
 * trip through memory. Clang-based OpenCL compilers take the attribute. */
#ifdef __clang__
#define PATHCL_HOT_INLINE static inline __attribute__((always_inline))
#else
#define PATHCL_HOT_INLINE static inline
#endif

/* pbrt-v3's conservative bound on the rounding error of a triangle hit's t (section
 * 3.9.6), from the largest magnitudes of the vertices' ray-space coordinates and of the
 * edge functions, for float or for double (GAMMA: FLOAT_GAMMA or DOUBLE_GAMMA): one
 * expression, so that the double re-test bounds exactly what the float test does. */
#define TRIANGLE_T_ERROR_BOUND(GAMMA, max_xt, max_yt, max_zt, max_e, inv_det)                                          \
    (3 *                                                                                                               \
     (GAMMA(3) * (max_e) * (max_zt) +                                                                                  \
      2 *                                                                                                              \
          (GAMMA(2) * (max_xt) * (max_yt) + GAMMA(5) * ((max_yt) + (max_zt)) * (max_xt) +                              \
           GAMMA(5) * ((max_xt) + (max_zt)) * (max_yt)) *                                                              \
          (max_zt) +                                                                                                   \
      GAMMA(3) * (max_zt) * (max_e)) *                                                                                 \
     fabs(inv_det))

#ifdef cl_khr_fp64
/* The edge function px qy - py qx of four lanes, in double. Four at a time, not eight: PoCL
 * on a CPU without AVX-512 warns at every build from source that a double8 passed to or
 * returned from its built-ins changes the ABI, and its compiler writes that to the
 * program's standard error. */
static inline float4 edge_function_double4(float4 px, float4 py, float4 qx, float4 qy)
{
    double4 dpx = convert_double4(px), dpy = convert_double4(py), dqx = convert_double4(qx), dqy = convert_double4(qy);
    return convert_float4(dpx * dqy - dpy * dqx);
}

#define DOUBLE_GAMMA(n) ((double)(n)*0x1.0p-53 / (1.0 - (double)(n)*0x1.0p-53))

/* Whether four lanes' hits lie beyond the rounding error of their t, with t and its
 * conservative bound (the float test's arithmetic, below) in double from the lanes'
 * vertices (a, b, c: x, y, z in the ray's permuted order) and the ray's origin and
 * shear. The vertices' differences from the origin are exact in double. */
static inline int4 t_beyond_error_double4(float4 pax, float4 pay, float4 paz, float4 pbx, float4 pby, float4 pbz,
                                          float4 pcx, float4 pcy, float4 pcz, float3 o, float3 shear)
{
    double sx = shear.x, sy = shear.y, sz = shear.z;
    double4 a_z = convert_double4(paz) - o.z, b_z = convert_double4(pbz) - o.z, c_z = convert_double4(pcz) - o.z;
    double4 ax = convert_double4(pax) - o.x - sx * a_z, ay = convert_double4(pay) - o.y - sy * a_z;
    double4 bx = convert_double4(pbx) - o.x - sx * b_z, by = convert_double4(pby) - o.y - sy * b_z;
    double4 cx = convert_double4(pcx) - o.x - sx * c_z, cy = convert_double4(pcy) - o.y - sy * c_z;
    double4 u = cx * by - cy * bx, v = ax * cy - ay * cx, w = bx * ay - by * ax;
    double4 inv_det = 1.0 / (u + v + w);
    double4 az = sz * a_z, bz = sz * b_z, cz = sz * c_z;
    double4 t = (u * az + v * bz + w * cz) * inv_det;
    double4 max_zt = fmax(fabs(az), fmax(fabs(bz), fabs(cz)));
    double4 max_xt = fmax(fabs(ax), fmax(fabs(bx), fabs(cx)));
    double4 max_yt = fmax(fabs(ay), fmax(fabs(by), fabs(cy)));
    double4 max_e = fmax(fabs(u), fmax(fabs(v), fabs(w)));
    return convert_int4(t > TRIANGLE_T_ERROR_BOUND(DOUBLE_GAMMA, max_xt, max_yt, max_zt, max_e, inv_det));
}
#endif

/* The watertight test of the up to eight triangles of a leaf's block (types.h
 * TriangleBlock) at once, one per lane; each lane's arithmetic is that of testing its
 * triangle alone, so a lane's t and barycentrics do not depend on its neighbours. The
 * ray's permutation picks the block's rows. Returns the lanes hit at t in (0, t_max) as
 * bits (lane_bits: bit k for lane k; the bits rather than the mask, so that a caller's
 * branch on them follows the early exit below without a second reduction), with t and
 * the barycentric weights of v1 and v2; *ts_out and *det_abs_out are the two sides of the
 * comparison with t_max (ts < t_max * det_abs), so that a caller can ask a lane again,
 * exactly as testing it later would, after a closer hit has lowered t_max. */
PATHCL_HOT_INLINE uint ray_triangle_block(const RayTraversal* r, __global const TriangleBlock* block, float t_max,
                                          float8* t_out, float8* b1_out, float8* b2_out, float8* ts_out,
                                          float8* det_abs_out)
{
    __global const float8* p = block->vertex;
    uint kx = r->permutation.x, ky = r->permutation.y, kz = r->permutation.z;
    float3 o = r->origin_permuted;
    float8 a_x = p[kx] - o.x, a_y = p[ky] - o.y, a_z = p[kz] - o.z;
    float8 b_x = p[3 + kx] - o.x, b_y = p[3 + ky] - o.y, b_z = p[3 + kz] - o.z;
    float8 c_x = p[6 + kx] - o.x, c_y = p[6 + ky] - o.y, c_z = p[6 + kz] - o.z;
    float sx = r->shear.x, sy = r->shear.y, sz = r->shear.z;
    float8 ax = a_x - sx * a_z, ay = a_y - sy * a_z;
    float8 bx = b_x - sx * b_z, by = b_y - sy * b_z;
    float8 cx = c_x - sx * c_z, cy = c_y - sy * c_z;
    float8 u = cx * by - cy * bx;
    float8 v = ax * cy - ay * cx;
    float8 w = bx * ay - by * ax;
#ifdef cl_khr_fp64
    /* An edge function of exactly zero may be a rounding artefact: redo it in double. */
    int8 zero = (u == 0.0f) | (v == 0.0f) | (w == 0.0f);
    if (lane_bits(zero) != 0u) {
        float8 du = (float8)(edge_function_double4(cx.lo, cy.lo, bx.lo, by.lo),
                             edge_function_double4(cx.hi, cy.hi, bx.hi, by.hi));
        float8 dv = (float8)(edge_function_double4(ax.lo, ay.lo, cx.lo, cy.lo),
                             edge_function_double4(ax.hi, ay.hi, cx.hi, cy.hi));
        float8 dw = (float8)(edge_function_double4(bx.lo, by.lo, ax.lo, ay.lo),
                             edge_function_double4(bx.hi, by.hi, ax.hi, ay.hi));
        u = select(u, du, zero);
        v = select(v, dv, zero);
        w = select(w, dw, zero);
    }
#endif
    int8 hit = ~(((u < 0.0f) | (v < 0.0f) | (w < 0.0f)) & ((u > 0.0f) | (v > 0.0f) | (w > 0.0f)));
    float8 det = u + v + w;
    hit &= det != 0.0f;
    float8 az = sz * a_z, bz = sz * b_z, cz = sz * c_z;
    float8 t_scaled = u * az + v * bz + w * cz;
    /* Compare t with (0, t_max) without dividing: flip signs to make det positive; NaN (a
     * degenerate ray, an empty lane) never hits. */
    float8 sign = select((float8)(1.0f), (float8)(-1.0f), det < 0.0f);
    float8 det_abs = det * sign;
    float8 ts = t_scaled * sign;
    hit &= (ts > 0.0f) & (ts < t_max * det_abs);
    /* Many leaf tests end here with no lane left (the ray passes beside every triangle,
     * or meets their planes beyond the closest hit so far): the division and the error
     * bound below are then skipped. The outputs
     * of lanes not hit are never read. */
    if (lane_bits(hit) == 0u) {
        *t_out = *b1_out = *b2_out = *ts_out = *det_abs_out = (float8)(0.0f);
        return 0u;
    }
    float8 inv_det = 1.0f / det;
    float8 t = t_scaled * inv_det;
    /* Conservative bound on the rounding error of t (pbrt-v3, section 3.9.6): a hit closer
     * than that may be the surface the ray starts on. Spawned origins are offset by the
     * hit point's error bound, but that bound is zero for a point exactly on a coordinate
     * plane (x = 0 walls), so this test is what stops those rays re-hitting the plane.
     * max, not fmax (a compare and a blend less per lane): they differ only where an
     * operand is NaN, which finite vertices and a finite ray never give (the one-triangle
     * test this replaced used fmax; renders were bit for bit the same). */
    float8 max_zt = max(fabs(az), max(fabs(bz), fabs(cz)));
    float8 max_xt = max(fabs(ax), max(fabs(bx), fabs(cx)));
    float8 max_yt = max(fabs(ay), max(fabs(by), fabs(cy)));
    float8 max_e = max(fabs(u), max(fabs(v), fabs(w)));
    int8 beyond_error = t > TRIANGLE_T_ERROR_BOUND(FLOAT_GAMMA, max_xt, max_yt, max_zt, max_e, inv_det);
#ifdef cl_khr_fp64
    /* A ray that grazes a triangle has a small determinant beside the bound's terms, and
     * float's bound can exceed a t that is clearly in front: a shadow ray leaving one face
     * of a convex mesh near an edge, along that edge, towards a light just outside its far
     * end, crossed the neighbouring face unseen (t 0.0527, bound 0.0562). Such lanes ask
     * again in double, whose bound is 2^29 times tighter. */
    int8 unsure = hit & ~beyond_error;
    if (lane_bits(unsure) != 0u) {
        float3 shear = (float3)(sx, sy, sz);
        int8 beyond_in_double =
            (int8)(t_beyond_error_double4(p[kx].lo, p[ky].lo, p[kz].lo, p[3 + kx].lo, p[3 + ky].lo, p[3 + kz].lo,
                                          p[6 + kx].lo, p[6 + ky].lo, p[6 + kz].lo, o, shear),
                   t_beyond_error_double4(p[kx].hi, p[ky].hi, p[kz].hi, p[3 + kx].hi, p[3 + ky].hi, p[3 + kz].hi,
                                          p[6 + kx].hi, p[6 + ky].hi, p[6 + kz].hi, o, shear));
        beyond_error |= unsure & beyond_in_double;
    }
#endif
    hit &= beyond_error & (block->triangle >= 0);
    *t_out = t;
    *b1_out = v * inv_det;
    *b2_out = w * inv_det;
    *ts_out = ts;
    *det_abs_out = det_abs;
    return lane_bits(hit);
}

#pragma OPENCL FP_CONTRACT ON
