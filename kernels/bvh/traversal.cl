/* Closest-hit and any-hit (visibility) traversal of the eight-wide BVH: one float8 slab
 * test for the eight children of a node, children entered nearest first, and one float8
 * pass of the triangle test for a leaf's triangles (its TriangleBlock).
 *
 * Two-level BVH (PATHCL_HAS_INSTANCES): node 0 is the root of a top-level tree whose
 * leaves name instances (types.h Instance); each instance's mesh has its own tree in the
 * same node array, over its triangles in its own space. A leaf's instances go on the
 * stack; entering one maps the ray into the instance's space (the direction is not
 * renormalized, so t is the same along both and hits compare across instances) and puts a
 * return mark under its tree's entries, which maps the ray back when it comes up.
 *
 * Floating-point contraction is off here as in triangle_intersect.cl: the box test's
 * rounding allowance is derived for separately rounded operations. */
#include "bvh/instance.cl"
#include "bvh/triangle_intersect.cl"
#include "features.h"
#include "kernel_data.cl"
#include "texture/alpha.cl"
#include "types.h"
#include "util/math.cl"

#pragma OPENCL FP_CONTRACT OFF

typedef struct {
    float t;
    float b1, b2; /* barycentric weights of v1 and v2 */
    int triangle; /* -1: no hit */
#ifdef PATHCL_HAS_INSTANCES
    int instance; /* the instance whose mesh holds the triangle */
#endif
} Hit;

#ifdef PATHCL_HAS_INSTANCES
/* Stack entries besides nodes (count 0) and leaves (count > 0). */
#define TRAVERSAL_ENTER_INSTANCE (-1) /* (instance, -1): traverse its mesh in its space */
#define TRAVERSAL_LEAVE_INSTANCE (-2) /* back in render space, at the top level */
#define TRAVERSAL_STACK_SIZE BVH_INSTANCED_STACK_SIZE

/* The ray in an instance's space; the same ray where the instance is the identity. */
static inline RayTraversal instance_ray(const Instance* inst, const RayTraversal* world, float3 origin, float3 dir)
{
    if (inst->flags & INSTANCE_IDENTITY)
        return *world;
    return ray_traversal_setup(affine_point(inst->to_object, origin), affine_direction(inst->to_object, dir));
}
#else
#define TRAVERSAL_STACK_SIZE BVH_STACK_SIZE
#endif

/* a < b ? a : b and a > b ? a : b, lane by lane: OpenCL C's min and max are undefined for
 * infinite or NaN arguments (an implementation may return anything), and the slab
 * distances below are +-inf for every ray parallel to an axis. A comparison is defined
 * for every float, and x86's minps and maxps are exactly these selects. */
static inline float8 slab_min(float8 a, float8 b)
{
    return select(b, a, a < b);
}

static inline float8 slab_max(float8 a, float8 b)
{
    return select(b, a, a > b);
}

/* Slab tests against the eight child boxes of a node at once (float8 lanes), with the far
 * distance enlarged by 1 + 2 gamma(3) so that rounding never culls a box the ray touches
 * (Ize 2013). Returns each child's entry distance, INFINITY where the ray misses it.
 *
 * slab_min and slab_max, not fmin and fmax (whose NaN handling costs a compare and a blend
 * per lane on CPUs): the only NaN is 0 x inf, a ray parallel to an axis starting exactly
 * in a slab's plane, and the selects pass it on or drop it by their operand order. The
 * builder widens every box outwards (one ulp; near zero two of the smallest normal
 * floats, which a device without denormals does not flush), so a ray in the plane of a
 * face of the geometry's box is strictly inside its slab (its t range is +-inf, no NaN),
 * and a NaN is met only by a ray in the widened plane, outside the geometry, which
 * touches nothing in the box: culling it or entering it is right either way. */
static inline float8 ray_box_entry8(const RayTraversal* r, __global const BvhNode* node, float tmax)
{
    float8 ox = (float8)(r->origin.x), oy = (float8)(r->origin.y), oz = (float8)(r->origin.z);
    float8 ix = (float8)(r->inv_dir.x), iy = (float8)(r->inv_dir.y), iz = (float8)(r->inv_dir.z);
    float8 t0x = (node->lo_x - ox) * ix, t1x = (node->hi_x - ox) * ix;
    float8 t0y = (node->lo_y - oy) * iy, t1y = (node->hi_y - oy) * iy;
    float8 t0z = (node->lo_z - oz) * iz, t1z = (node->hi_z - oz) * iz;
    float8 tnear =
        slab_max(slab_max(slab_min(t0x, t1x), slab_min(t0y, t1y)), slab_max(slab_min(t0z, t1z), (float8)(0.0f)));
    float8 tfar =
        slab_min(slab_min(slab_max(t0x, t1x), slab_max(t0y, t1y)), slab_min(slab_max(t0z, t1z), (float8)(tmax)));
    tfar *= 1.0f + 2.0f * FLOAT_GAMMA(3);
    return select((float8)(INFINITY), tnear, islessequal(tnear, tfar));
}

/* The lowest set bit's position (lanes != 0). */
static inline int lowest_lane(uint lanes)
{
    return 31 - (int)clz(lanes & (0u - lanes));
}

/* Closest hit along origin + dir, t in (0, t_max). Children are visited nearest entry
 * first; the others wait on the stack with their entry distance and are dropped once a
 * closer hit is known. A hit on an alpha-tested triangle counts only if its coverage
 * coin keeps it (texture/alpha.cl). */
static inline Hit bvh_closest_hit(const KernelData* kd, float3 origin, float3 dir, float t_max)
{
    __global const BvhNode* nodes = kd->nodes;
#ifdef PATHCL_HAS_ALPHA
    __global const Triangle* triangles = kd->triangles; /* their alpha flags */
#endif
    RayTraversal r = ray_traversal_setup(origin, dir);
#ifdef PATHCL_HAS_ALPHA
    uint alpha_seed = alpha_ray_seed(origin, dir);
#endif
    Hit hit;
    hit.t = t_max;
    hit.b1 = 0.0f;
    hit.b2 = 0.0f;
    hit.triangle = -1;

    int2 stack[TRAVERSAL_STACK_SIZE];
    float stack_entry[TRAVERSAL_STACK_SIZE];
    int sp = 0;
    int2 cur = (int2)(0, 0); /* (index, count); count 0: inner node; the root is inner */
#ifdef PATHCL_HAS_INSTANCES
    hit.instance = -1;
    const RayTraversal world = r;
    int instance = -1;      /* whose mesh is being traversed; -1: the top level */
    float cur_entry = 0.0f; /* where the ray enters the current entry's box */
#endif
    for (;;) {
#ifdef PATHCL_HAS_INSTANCES
        if (cur.y == TRAVERSAL_ENTER_INSTANCE) {
            Instance inst = kd->instances[cur.x];
            stack[sp] = (int2)(0, TRAVERSAL_LEAVE_INSTANCE);
            stack_entry[sp++] = -INFINITY; /* never skipped */
            r = instance_ray(&inst, &world, origin, dir);
            instance = cur.x;
            cur = (int2)(inst.root, 0);
            continue;
        }
        if (cur.y == TRAVERSAL_LEAVE_INSTANCE) {
            r = world;
            instance = -1;
        } else if (cur.y > 0 && instance < 0) {
            /* A top-level leaf: its instances, entered in order. */
            for (int i = cur.x + cur.y - 1; i >= cur.x; --i) {
                stack[sp] = (int2)(i, TRAVERSAL_ENTER_INSTANCE);
                stack_entry[sp++] = cur_entry;
            }
        } else
#endif
            if (cur.y > 0) {
            /* The leaf's triangles at once; then the lanes hit, in triangle order, each
             * asked again against the closest hit so far: the hits of testing them one by
             * one. */
            __global const TriangleBlock* block = &kd->triangle_blocks[cur.x];
            float8 t8, b18, b28, ts8, det8;
            uint lanes = ray_triangle_block(&r, block, hit.t, &t8, &b18, &b28, &ts8, &det8);
            if (lanes != 0u) {
                float t[8], b1[8], b2[8], ts[8], det_abs[8];
                int tri[8];
                vstore8(t8, 0, t);
                vstore8(b18, 0, b1);
                vstore8(b28, 0, b2);
                vstore8(ts8, 0, ts);
                vstore8(det8, 0, det_abs);
                vstore8(block->triangle, 0, tri);
                for (; lanes != 0u; lanes &= lanes - 1u) {
                    int j = lowest_lane(lanes);
                    if (!(ts[j] < hit.t * det_abs[j]))
                        continue;
#ifdef PATHCL_HAS_ALPHA
                    if (triangles[tri[j]].v0.w != 0.0f && !alpha_keeps_hit(kd, alpha_seed, tri[j], b1[j], b2[j]))
                        continue;
#endif
                    hit.t = t[j];
                    hit.b1 = b1[j];
                    hit.b2 = b2[j];
                    hit.triangle = tri[j];
#ifdef PATHCL_HAS_INSTANCES
                    hit.instance = instance;
#endif
                }
            }
        } else {
            __global const BvhNode* node = &nodes[cur.x];
            float8 entry = ray_box_entry8(&r, node, hit.t);
            float e[8];
            vstore8(entry, 0, e);
            int8 idx8 = node->index, cnt8 = node->count;
            int index[8], count[8];
            vstore8(idx8, 0, index);
            vstore8(cnt8, 0, count);
            /* Push every child the ray enters, farthest first, and continue with the
             * nearest (popped at once): a small insertion sort on the entry distance.
             * Unrolled, so that e, index and count stay in registers (PoCL kept the loop
             * and the arrays in memory; a compiler that ignores the pragma still runs it). */
            int base = sp;
#pragma unroll
            for (int j = 0; j < 8; ++j) {
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
#ifdef PATHCL_HAS_INSTANCES
        cur_entry = stack_entry[sp];
#endif
    }
}

/* The fraction of light that passes along origin + dir, t in (0, t_max) (shadow rays):
 * 0 at the first opaque hit, which ends the search (children in no order, no entry
 * distances); 1 when nothing is hit. An alpha-tested triangle passes 1 - its coverage
 * (each triangle sits in one leaf, so each is met once) and the search goes on. */
static inline float bvh_visibility(const KernelData* kd, float3 origin, float3 dir, float t_max)
{
    __global const BvhNode* nodes = kd->nodes;
#ifdef PATHCL_HAS_ALPHA
    __global const Triangle* triangles = kd->triangles; /* their alpha flags */
#endif
    RayTraversal r = ray_traversal_setup(origin, dir);
    float visibility = 1.0f;
    int2 stack[TRAVERSAL_STACK_SIZE];
    int sp = 0;
    int2 cur = (int2)(0, 0);
#ifdef PATHCL_HAS_INSTANCES
    const RayTraversal world = r;
    bool top_level = true;
#endif
    for (;;) {
#ifdef PATHCL_HAS_INSTANCES
        if (cur.y == TRAVERSAL_ENTER_INSTANCE) {
            Instance inst = kd->instances[cur.x];
            stack[sp++] = (int2)(0, TRAVERSAL_LEAVE_INSTANCE);
            r = instance_ray(&inst, &world, origin, dir);
            top_level = false;
            cur = (int2)(inst.root, 0);
            continue;
        }
        if (cur.y == TRAVERSAL_LEAVE_INSTANCE) {
            r = world;
            top_level = true;
        } else if (cur.y > 0 && top_level) {
            for (int i = cur.x; i < cur.x + cur.y; ++i)
                stack[sp++] = (int2)(i, TRAVERSAL_ENTER_INSTANCE);
        } else
#endif
            if (cur.y > 0) {
            __global const TriangleBlock* block = &kd->triangle_blocks[cur.x];
            float8 t8, b18, b28, ts8, det8;
            uint lanes = ray_triangle_block(&r, block, t_max, &t8, &b18, &b28, &ts8, &det8);
#ifdef PATHCL_HAS_ALPHA
            if (lanes != 0u) {
                float b1[8], b2[8];
                int tri[8];
                vstore8(b18, 0, b1);
                vstore8(b28, 0, b2);
                vstore8(block->triangle, 0, tri);
                for (; lanes != 0u; lanes &= lanes - 1u) {
                    int j = lowest_lane(lanes);
                    if (triangles[tri[j]].v0.w != 0.0f) {
                        visibility *= 1.0f - surface_coverage(kd, tri[j], b1[j], b2[j]);
                        if (visibility > 0.0f)
                            continue;
                    }
                    return 0.0f;
                }
            }
#else
            if (lanes != 0u)
                return 0.0f;
#endif
        } else {
            __global const BvhNode* node = &nodes[cur.x];
            float8 entry = ray_box_entry8(&r, node, t_max);
            float e[8];
            vstore8(entry, 0, e);
            int index[8], count[8];
            vstore8(node->index, 0, index);
            vstore8(node->count, 0, count);
            /* Every child the ray enters, in slot order (unrolled, as above). An empty
             * slot's inverted box passes the slab test: its index (-1) tells. */
#pragma unroll
            for (int j = 0; j < 8; ++j)
                if (e[j] != INFINITY && index[j] >= 0)
                    stack[sp++] = (int2)(index[j], count[j]);
        }
        if (sp == 0)
            return visibility;
        cur = stack[--sp];
    }
}

#pragma OPENCL FP_CONTRACT ON
