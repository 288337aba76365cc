/* --light-sampler tree (PATHCL_LIGHT_TREE): next event estimation's light picked by a
 * descent of the light tree (host/compile/light_tree.cpp), each step taking one of a node's
 * eight children with probability in proportion to its importance at the shading point,
 * all eight weighed by one float8 computation (Conty Estevez and Kulla 2018, section 4.2).
 * The probability of any light at a point is computed exactly along its leaf's trail, as
 * MIS needs where a BSDF-sampled ray hits a light. Infinite lights sit beside the tree:
 * picked with probability frame->infinite_pick, uniformly among them. */
#include "features.h"
#include "kernel_data.cl"
#include "light/light_record_warm.cl"
#include "util/hash.cl"
#include "util/math.cl"
#include "util/prefetch.cl"

#ifdef PATHCL_LIGHT_TREE

/* light_tree_trail's entry of an infinite light. */
#define LIGHT_TREE_INFINITE_TRAIL 0xfffffffffffffffful

/* Every LIGHT_TREE_FRESH_LEVELS levels the descent takes a fresh number: rescaled at each
 * level, the first one has few bits left after about six. */
#define LIGHT_TREE_FRESH_LEVELS 5u

/* cos(max(0, a - b)) from the cosines and sines of angles a, b in [0, pi], per lane. */
static inline float8 cos_of_clamped_difference8(float8 cos_a, float8 sin_a, float8 cos_b, float8 sin_b)
{
    return select(cos_a * cos_b + sin_a * sin_b, (float8)(1.0f), cos_a > cos_b);
}

/* The importance of each of a node's eight children at the point ref with shading normal
 * n (zero: none): an estimate of how much of its power reaches the point, held between an
 * upper and a lower bound. The upper bound (Conty Estevez and Kulla 2018) is
 *   phi cos(theta') / d^2, times cos(theta'_i) at a surface,
 * where d is the distance to its bounding sphere's centre (at least its radius), theta'
 * the smallest angle between the direction from it to the point and any direction its
 * lights emit along (their normals' cone widened by the sphere's angular radius theta_b),
 * and theta'_i the smallest angle between the normal (either side: transmission) and any
 * direction to the sphere. The lower bound takes the largest angles instead,
 * theta + theta_o + theta_b and theta_i + theta_b, and is 0 unless every light of the
 * child emits towards every point of the sphere around the point's direction. The
 * estimate is what Lambertian emitters at the centre would send towards the point:
 *   phi max(0, m . w) / d^2, times cos(theta'_i) at a surface,
 * with m the power-weighted mean of their normals (m . w is at least mean_axis_along
 * cos(theta) - mean_axis_across sin(theta)). It comes close to what a small patch of
 * emitters that all face the point sends, where the upper bound weighs a patch of a
 * glowing sphere seen edge-on like one that faces the point. The importance is
 *   s upper + (1 - s) min(upper, max(lower, estimate)),  s = LIGHT_TREE_UPPER_SHARE:
 * the share s of the upper bound keeps every child that might reach the point above 0
 * (the pmf must be wherever the light can be), and bounds how far an estimate that is
 * too low (emitters that face every way, whose mean normal is short) can lower a child's
 * weight. Zero where none of its lights can emit towards the point, and in empty lanes. */
static inline float8 light_tree_importance(__global const LightTreeNode* node, float3 ref, float3 n)
{
    /* Every cosine and sine of an angle at the point comes from a product with the
     * unnormalized direction d, computed while 1 / |d| is: the chain of square roots and
     * divisions a lane waits on is one long, not three. */
    float8 dx = (float8)(ref.x) - node->centre_x, dy = (float8)(ref.y) - node->centre_y,
           dz = (float8)(ref.z) - node->centre_z;
    float8 dist2 = dx * dx + dy * dy + dz * dz;
    float8 radius2 = node->radius2;
    float8 ax = node->axis_x, ay = node->axis_y, az = node->axis_z;
    float8 dot_w = ax * dx + ay * dy + az * dz;
    float8 cx = ay * dz - az * dy, cy = az * dx - ax * dz, cz = ax * dy - ay * dx;
    float8 cross_w = sqrt(cx * cx + cy * cy + cz * cz); /* |axis x d| = |d| sin(theta) */
    int8 outside = dist2 > radius2;                     /* inside the sphere it subtends every direction */
    float8 leg = sqrt(fmax(dist2 - radius2, 0.0f));     /* to where a tangent touches the sphere */
    float8 radius = sqrt(radius2);
    float8 inv_dist = 1.0f / sqrt(dist2);
    /* At the centre itself (d = 0) every direction lies within theta_b = pi, which alone
     * decides there: any angle theta serves. */
    int8 apart = dist2 > 0.0f;
    float8 cos_w = select((float8)(1.0f), dot_w * inv_dist, apart);
    cos_w = fmin(select(cos_w, fabs(cos_w), node->two_sided), 1.0f);
    float8 sin_w = select((float8)(0.0f), fmin(cross_w * inv_dist, 1.0f), apart);
    float8 cos_b = select((float8)(-1.0f), fmin(leg * inv_dist, 1.0f), outside);   /* read where outside: */
    float8 sin_b = select((float8)(0.0f), fmin(radius * inv_dist, 1.0f), outside); /* inv_dist finite */
    float8 cos_o = node->cos_o, sin_o = node->sin_o, cos_e = node->cos_e;
    /* theta_o + theta_b, at most pi (past it, pi: every direction within it either way).
     * It reaches pi where theta_o >= pi - theta_b, cos_o <= -cos_b: decided on the stored
     * cosines, not on the sign of the sum's sine, which is -0 at 2 pi (a cone of every
     * direction seen from inside its sphere). */
    float8 cos_ob = cos_o * cos_b - sin_o * sin_b, sin_ob = sin_o * cos_b + cos_o * sin_b;
    int8 past_pi = cos_o <= -cos_b;
    cos_ob = select(cos_ob, (float8)(-1.0f), past_pi);
    sin_ob = select(sin_ob, (float8)(0.0f), past_pi);
    float8 cos_p = cos_of_clamped_difference8(cos_w, sin_w, cos_ob, sin_ob);
    float8 inv_d2 = 1.0f / fmax(dist2, radius2);
    float8 importance = node->phi * cos_p * inv_d2;
    /* The lower bound, where theta + theta_b + theta_o <= theta_e. With each of the three
     * at most pi/2, their sum is at most pi where its sine is not negative, and there its
     * cosine orders it. */
    float8 cos_wbo = cos_w * cos_ob - sin_w * sin_ob, sin_wbo = sin_w * cos_ob + cos_w * sin_ob;
    int8 inside_e = (cos_w >= 0.0f) & (cos_b >= 0.0f) & (cos_o >= 0.0f) & (sin_wbo >= 0.0f) & (cos_wbo >= cos_e);
    float8 low = select((float8)(0.0f), node->phi * cos_wbo * inv_d2, inside_e);
    float8 estimate = node->phi * fmax(node->mean_axis_along * cos_w - node->mean_axis_across * sin_w, 0.0f) * inv_d2;
    if (any(n != 0.0f)) {
        float8 dot_i = (float8)(n.x) * dx + (float8)(n.y) * dy + (float8)(n.z) * dz;
        float8 cos_i = select((float8)(1.0f), fmin(fabs(dot_i) * inv_dist, 1.0f), apart);
        float8 sin_i = sqrt(fmax(0.0f, 1.0f - cos_i * cos_i));
        float8 cos_pi = cos_of_clamped_difference8(cos_i, sin_i, cos_b, sin_b);
        importance *= cos_pi;
        estimate *= cos_pi;
        low *= fmax(cos_i * cos_b - sin_i * sin_b, 0.0f);
    }
    int8 reaches = (cos_p >= node->cos_e) & (node->phi > 0.0f);
    importance = select((float8)(0.0f), fmax(importance, 0.0f), reaches);
    float8 between = fmin(fmax(fmax(low, estimate), 0.0f), importance);
    return LIGHT_TREE_UPPER_SHARE * importance + (1.0f - LIGHT_TREE_UPPER_SHARE) * between;
}

/* The weights of a node's children at (ref, n) in weight[] (the largest 1; a child of
 * infinite importance, a point light at the point itself, takes all the weight) and their
 * children in child[]; returns their sum, 0 where none can reach the point. */
static inline float light_tree_weights(const KernelData* kd, int node, float3 ref, float3 n, float* weight, int* child)
{
    __global const LightTreeNode* nd = &kd->light_tree[node];
    float8 importance = light_tree_importance(nd, ref, n);
    float4 m4 = fmax(importance.lo, importance.hi);
    float2 m2 = fmax(m4.lo, m4.hi);
    float m = fmax(m2.x, m2.y);
    if (!(m > 0.0f))
        return 0.0f;
    float8 w = isinf(m) ? select((float8)(0.0f), (float8)(1.0f), isinf(importance)) : importance / m;
    vstore8(w, 0, weight);
    vstore8(nd->child, 0, child);
    /* Summed pairwise in registers, not lane after lane from the array just stored. */
    float4 s4 = w.lo + w.hi;
    float2 s2 = s4.lo + s4.hi;
    return s2.x + s2.y;
}

/* Starts the cluster whose header is light_tree_cluster[first] into the cache, as
 * light_record_warm does a light's record: a node's cluster leaves are weighed before one
 * is picked among. */
static inline void light_tree_cluster_warm(const KernelData* kd, int first)
{
    cache_line_warm((__global const int*)&kd->light_tree_cluster[first]);
}

/* Picks one of the lights of the cluster whose header is light_tree_cluster[first] by the
 * number u, in proportion to their power, through their alias table: u times their
 * number gives the slot, its fraction the coin (lights of power 0 keep no share); its
 * probability times p in *pmf. */
static inline int light_tree_cluster_pick(const KernelData* kd, int first, float u, float p, float* pmf)
{
    __global const LightTreeClusterLight* c = kd->light_tree_cluster + first + 1;
    int n = c[-1].light;
    float x = u * (float)n; /* below n: u < 1, n at most LIGHT_TREE_CLUSTER_MAX */
    int slot = min((int)x, n - 1);
    __global const LightTreeClusterLight* e = c + slot;
    if (!(x - (float)slot < e->keep))
        e = c + e->alias;
    *pmf = p * e->pmf;
    return e->light;
}

/* p times the probability that light_tree_cluster_pick picks `light` of that cluster (0
 * where it is not one of its lights). */
static inline float light_tree_cluster_pmf(const KernelData* kd, int first, int light, float p)
{
    __global const LightTreeClusterLight* c = kd->light_tree_cluster + first;
    int lo = 1, hi = c[0].light;
    while (lo < hi) {
        int mid = (lo + hi) >> 1;
        if (c[mid].light < light)
            lo = mid + 1;
        else
            hi = mid;
    }
    return c[lo].light == light ? p * c[lo].pmf : 0.0f;
}

/* Picks a light for the shading point ref with normal n by the number u; its probability
 * in *pmf. -1 (and pmf 0) where the descent reaches a node none of whose children can
 * reach the point (the parents' bounds are looser than theirs). fresh_key seeds the
 * numbers of the deeper levels. */
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
        /* Where lanes are lights, their records start into the cache while the lanes are
         * weighed: the one picked is read right after. */
        int8 lanes = kd->light_tree[node].child;
        if (any(lanes < 0)) {
            int leaves[LIGHT_TREE_WIDTH];
            vstore8(lanes, 0, leaves);
            for (uint k = 0u; k < LIGHT_TREE_WIDTH; ++k) {
                if (leaves[k] < 0) {
                    int leaf = -1 - leaves[k];
                    if (leaf & LIGHT_TREE_CLUSTER)
                        light_tree_cluster_warm(kd, LIGHT_TREE_LEAF_INDEX(leaf));
                    else
                        light_record_warm(kd, leaf);
                }
            }
        }
        float weight[LIGHT_TREE_WIDTH];
        int child[LIGHT_TREE_WIDTH];
        float total = light_tree_weights(kd, node, ref, n, weight, child);
        if (!(total > 0.0f))
            return -1;
        /* The lane whose share of [0, total) holds u total; lanes of weight 0 hold none. */
        float target = u * total, below = 0.0f;
        uint lane = 0u;
        for (uint k = 0u; k < LIGHT_TREE_WIDTH; ++k) {
            if (weight[k] > 0.0f) {
                lane = k;
                if (target < below + weight[k])
                    break;
                below += weight[k];
            }
        }
        p *= weight[lane] / total;
        u = fmin(fmax(target - below, 0.0f) / weight[lane], ONE_MINUS_EPSILON);
        if (child[lane] < 0) {
            int leaf = -1 - child[lane];
            if (leaf & LIGHT_TREE_CLUSTER)
                return light_tree_cluster_pick(kd, LIGHT_TREE_LEAF_INDEX(leaf), u, p, pmf);
            *pmf = p;
            return leaf;
        }
        node = child[lane];
        if (depth % LIGHT_TREE_FRESH_LEVELS == 0u)
            u = u32_to_unit_float(hash_combine(fresh_key, depth));
    }
}

/* The probability that light_tree_pick picks `light` at (ref, n): the same arithmetic
 * along the light's path, so a hit on a light weighs it exactly as its sample would. The
 * path is the light's binary trail: at each node, the lane whose code it starts with (the
 * real lanes come first; a tree of one light has one lane of code 0). */
static inline float light_tree_pmf(const KernelData* kd, const FrameParams* frame, float3 ref, float3 n, int light)
{
    ulong trail = kd->light_tree_trail[light];
    float infinite = frame->infinite_pick;
    if (trail == LIGHT_TREE_INFINITE_TRAIL)
        return infinite / (float)frame->infinite_count;
    float p = 1.0f - infinite;
    int node = 0;
    for (;;) {
        float weight[LIGHT_TREE_WIDTH];
        int child[LIGHT_TREE_WIDTH], code[LIGHT_TREE_WIDTH];
        float total = light_tree_weights(kd, node, ref, n, weight, child);
        if (!(total > 0.0f))
            return 0.0f;
        vstore8(kd->light_tree[node].code, 0, code);
        uint lane = 0u, length = 0u;
        for (uint k = 0u; k < LIGHT_TREE_WIDTH; ++k) {
            length = (uint)LIGHT_TREE_CODE_LENGTH(code[k]);
            if ((uint)(trail & ((1ul << length) - 1ul)) == (uint)LIGHT_TREE_CODE_BITS(code[k])) {
                lane = k;
                break;
            }
        }
        p *= weight[lane] / total;
        if (child[lane] < 0) {
            int leaf = -1 - child[lane];
            return leaf & LIGHT_TREE_CLUSTER ? light_tree_cluster_pmf(kd, LIGHT_TREE_LEAF_INDEX(leaf), light, p) : p;
        }
        node = child[lane];
        trail >>= length;
    }
}

#endif /* PATHCL_LIGHT_TREE */
