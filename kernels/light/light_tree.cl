/* --light-sampler tree (PATHCL_LIGHT_TREE): next event estimation's light picked by a
 * descent of the light tree (host/render/light_tree.cpp), each step taking a child with
 * probability in proportion to its importance at the shading point (light/light_tree.h),
 * and the probability of any light at a point computed exactly along its leaf's trail, as
 * MIS needs where a BSDF-sampled ray hits a light. Infinite lights sit beside the tree:
 * picked with probability frame->infinite_pick, uniformly among them. */
#include "features.h"
#include "kernel_data.cl"
#include "light/light_tree.h"
#include "util/hash.cl"
#include "util/math.cl"

#ifdef PATHCL_LIGHT_TREE

/* light_tree_trail's entry of an infinite light. */
#define LIGHT_TREE_INFINITE_TRAIL 0xfffffffffffffffful

/* Every LIGHT_TREE_FRESH_LEVELS levels the descent takes a fresh number: rescaled at each
 * level, the first one has no bits left after about twenty. */
#define LIGHT_TREE_FRESH_LEVELS 16u

/* The importance of `node` at ref, where the shading normal is n (light/light_tree.h). */
static inline float light_tree_importance(__global const LightTreeNode* node, float3 ref, float3 n)
{
    float3 lo = node->lo.xyz, hi = node->hi.xyz;
    float3 d = ref - 0.5f * (lo + hi);
    float dist2 = dot(d, d);
    float3 diagonal = hi - lo;
    float radius2 = 0.25f * dot(diagonal, diagonal); /* of the box's bounding sphere */
    float3 w = dist2 > 0.0f ? d / sqrt(dist2) : (float3)(0.0f, 0.0f, 1.0f);
    float cos_w = dot(node->axis.xyz, w);
    if (node->two_sided)
        cos_w = fabs(cos_w);
    float cos_b = dist2 > radius2 ? sqrt(fmax(0.0f, 1.0f - radius2 / dist2)) : -1.0f;
    return light_cone_importance(node->lo.w, node->hi.w, node->axis.w, fmax(dist2, radius2), cos_w, cos_b,
                                 fabs(dot(w, n)));
}

/* The probability that the descent takes inner node `node`'s first child at (ref, n); -1
 * where neither child's lights can reach the point. */
static inline float light_tree_first_child(const KernelData* kd, int node, float3 ref, float3 n)
{
    float a = light_tree_importance(&kd->light_tree[node + 1], ref, n);
    float b = light_tree_importance(&kd->light_tree[kd->light_tree[node].child], ref, n);
    float m = fmax(a, b);
    if (!(m > 0.0f))
        return -1.0f;
    if (isinf(m)) /* a point light at the point itself */
        return isinf(a) ? (isinf(b) ? 0.5f : 1.0f) : 0.0f;
    a /= m;
    b /= m;
    return a / (a + b);
}

/* Picks a light for the shading point ref with normal n by the number u; its probability
 * in *pmf. -1 (and pmf 0) where no light can reach the point. fresh_key seeds the numbers
 * of the deeper levels. */
static inline int light_tree_pick(const KernelData* kd, const FrameParams* frame, float3 ref, float3 n, float u,
                                  uint fresh_key, float* pmf)
{
    *pmf = 0.0f;
    float infinite = frame->infinite_pick;
    if (u < infinite) {
        uint k = min((uint)(u / infinite * (float)frame->infinite_count), frame->infinite_count - 1u);
        *pmf = infinite / (float)frame->infinite_count;
        return kd->light_tree_infinite[k];
    }
    if (!(infinite < 1.0f))
        return -1;
    u = fmin((u - infinite) / (1.0f - infinite), ONE_MINUS_EPSILON);
    float p = 1.0f - infinite;
    int node = 0;
    for (uint depth = 1;; ++depth) {
        int second = kd->light_tree[node].child;
        if (second < 0) {
            *pmf = p;
            return -1 - second;
        }
        float first = light_tree_first_child(kd, node, ref, n);
        if (first < 0.0f)
            return -1;
        if (u < first) {
            u = fmin(u / first, ONE_MINUS_EPSILON);
            p *= first;
            node = node + 1;
        } else {
            u = fmin((u - first) / (1.0f - first), ONE_MINUS_EPSILON);
            p *= 1.0f - first;
            node = second;
        }
        if (depth % LIGHT_TREE_FRESH_LEVELS == 0u)
            u = u32_to_unit_float(hash_combine(fresh_key, depth));
    }
}

/* The probability that light_tree_pick picks `light` at (ref, n): the same arithmetic
 * along the light's trail, so a hit on a light weighs it exactly as its sample would. */
static inline float light_tree_pmf(const KernelData* kd, const FrameParams* frame, float3 ref, float3 n, int light)
{
    ulong trail = kd->light_tree_trail[light];
    float infinite = frame->infinite_pick;
    if (trail == LIGHT_TREE_INFINITE_TRAIL)
        return infinite / (float)frame->infinite_count;
    float p = 1.0f - infinite;
    int node = 0;
    for (;;) {
        int second = kd->light_tree[node].child;
        if (second < 0)
            return p;
        float first = light_tree_first_child(kd, node, ref, n);
        if (first < 0.0f)
            return 0.0f;
        if (trail & 1ul) {
            p *= 1.0f - first;
            node = second;
        } else {
            p *= first;
            node = node + 1;
        }
        trail >>= 1;
    }
}

#endif /* PATHCL_LIGHT_TREE */
