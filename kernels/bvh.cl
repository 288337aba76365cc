/* Closest-hit and any-hit traversal of the four-wide BVH, with the watertight ray/triangle
 * test of Woop, Benthin and Wald (JCGT 2013). Needs: shared_types.h.
 *
 * Watertightness needs each edge function computed identically by both triangles that
 * share the edge, so floating-point contraction (fma) is off for this file: an fma would
 * round the two orders of a shared edge differently and let rays slip between them. */

#pragma OPENCL FP_CONTRACT OFF

#ifdef cl_khr_fp64
#pragma OPENCL EXTENSION cl_khr_fp64 : enable
#endif

/* host/bvh/bvh_builder.h kBvhStackSize: the builder checks every tree fits. */
#define BVH_STACK_SIZE 96

/* pbrt's gamma(n): bound on the relative error of n chained float operations. */
#define FLOAT_GAMMA(n) ((float)(n) * 0x1.0p-24f / (1.0f - (float)(n) * 0x1.0p-24f))

typedef struct {
    float3 origin;
    float3 inv_dir;
    /* Woop's shear: the permutation making dir.z the largest axis, and shear constants. */
    uint4 permutation;
    float3 shear; /* (Sx, Sy, Sz) */
} RayTraversal;

typedef struct {
    float t;
    float b1, b2; /* barycentric weights of v1 and v2 */
    int triangle; /* -1: no hit */
} Hit;

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

/* Slab tests against the four child boxes of a node at once (float4 lanes), with the far
 * distance enlarged by 1 + 2 gamma(3) so that rounding never culls a box the ray touches
 * (Ize 2013). Returns each child's entry distance, INFINITY where the ray misses it. */
static inline float4 ray_box_entry4(const RayTraversal* r, const BvhNode* node, float tmax)
{
    float4 ox = (float4)(r->origin.x), oy = (float4)(r->origin.y), oz = (float4)(r->origin.z);
    float4 ix = (float4)(r->inv_dir.x), iy = (float4)(r->inv_dir.y), iz = (float4)(r->inv_dir.z);
    float4 t0x = (node->lo_x - ox) * ix, t1x = (node->hi_x - ox) * ix;
    float4 t0y = (node->lo_y - oy) * iy, t1y = (node->hi_y - oy) * iy;
    float4 t0z = (node->lo_z - oz) * iz, t1z = (node->hi_z - oz) * iz;
    float4 tnear = fmax(fmax(fmin(t0x, t1x), fmin(t0y, t1y)), fmax(fmin(t0z, t1z), (float4)(0.0f)));
    float4 tfar = fmin(fmin(fmax(t0x, t1x), fmax(t0y, t1y)), fmin(fmax(t0z, t1z), (float4)(tmax)));
    tfar *= 1.0f + 2.0f * FLOAT_GAMMA(3);
    return select((float4)(INFINITY), tnear, islessequal(tnear, tfar));
}

/* Watertight ray/triangle test. On a hit closer than *t_max, updates hit and *t_max. */
static inline bool ray_triangle(const RayTraversal* r, __global const Triangle* tri, float t_max,
                         float* t_out, float* b1_out, float* b2_out)
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
    if (ts <= 0.0f || ts >= t_max * det_abs)
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
    if (t <= delta_t)
        return false;
    *t_out = t;
    *b1_out = v * inv_det;
    *b2_out = w * inv_det;
    return true;
}

/* Closest hit along origin + t dir, t in (0, t_max). Set any_hit to stop at the first hit
 * (shadow rays). Children are visited nearest entry first; the others wait on the stack
 * with their entry distance and are dropped once a closer hit is known. */
static inline Hit bvh_trace(__global const BvhNode* nodes, __global const Triangle* triangles,
                            float3 origin, float3 dir, float t_max, bool any_hit)
{
    RayTraversal r = ray_traversal_setup(origin, dir);
    Hit hit;
    hit.t = t_max;
    hit.b1 = 0.0f;
    hit.b2 = 0.0f;
    hit.triangle = -1;

    int2 stack[BVH_STACK_SIZE];
    float stack_entry[BVH_STACK_SIZE];
    int sp = 0;
    int2 cur = (int2)(0, 0); /* (index, count); count 0: inner node; the root is inner */
    for (;;) {
        if (cur.y > 0) {
            for (int i = cur.x; i < cur.x + cur.y; ++i) {
                float t, b1, b2;
                if (ray_triangle(&r, &triangles[i], hit.t, &t, &b1, &b2)) {
                    hit.t = t;
                    hit.b1 = b1;
                    hit.b2 = b2;
                    hit.triangle = i;
                    if (any_hit)
                        return hit;
                }
            }
        } else {
            BvhNode node = nodes[cur.x];
            float4 entry = ray_box_entry4(&r, &node, hit.t);
            float e[4] = {entry.x, entry.y, entry.z, entry.w};
            int index[4] = {node.index.x, node.index.y, node.index.z, node.index.w};
            int count[4] = {node.count.x, node.count.y, node.count.z, node.count.w};
            /* Push every child the ray enters, farthest first, and continue with the
             * nearest (popped at once): a small insertion sort on the entry distance. */
            int base = sp;
            for (int j = 0; j < 4; ++j) {
                if (e[j] == INFINITY || index[j] < 0)
                    continue;
                int k = sp++;
                while (k > base && stack_entry[k - 1] < e[j]) {
                    stack[k] = stack[k - 1];
                    stack_entry[k] = stack_entry[k - 1];
                    --k;
                }
                stack[k] = (int2)(index[j], count[j]);
                stack_entry[k] = e[j];
            }
        }
        /* The next child the ray still reaches before its closest hit so far (with the
         * box test's own allowance for rounding, so no box that a closer hit could lie in
         * is skipped). */
        do {
            if (sp == 0)
                return hit;
            --sp;
        } while (stack_entry[sp] > hit.t * (1.0f + 2.0f * FLOAT_GAMMA(3)));
        cur = stack[sp];
    }
}

#pragma OPENCL FP_CONTRACT ON
