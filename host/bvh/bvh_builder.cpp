#include "bvh/bvh_builder.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>

namespace pathcl {
namespace {

constexpr int kBins = 32;
constexpr float kTraversalCost = 1.0f; // relative to one triangle test
constexpr float kIntersectCost = 1.0f;
// A box bound moved outwards by one ulp, and by at least twice the smallest normal float
// near zero, where one ulp is a denormal: a device without denormals (optional in OpenCL
// 1.2) would flush the distance to the moved plane to zero, and 0 x inf is NaN again.
float widen_down(float x)
{
    return std::min(std::nextafter(x, -std::numeric_limits<float>::infinity()),
                    x - 2.0f * std::numeric_limits<float>::min());
}
float widen_up(float x)
{
    return std::max(std::nextafter(x, std::numeric_limits<float>::infinity()),
                    x + 2.0f * std::numeric_limits<float>::min());
}

// The bin of a centroid `offset` past the centroid bounds' low side, `scale` bins a unit:
// clamped before the conversion to int, which is undefined for NaN and values beyond
// int (bounds that overflow float make an infinite extent, a zero scale and NaN here).
int bin_index(float offset, float scale)
{
    const float x = offset * scale;
    if (!(x > 0.0f))
        return 0;
    if (!(x < static_cast<float>(kBins - 1)))
        return kBins - 1;
    return static_cast<int>(x);
}

struct Box {
    glm::vec3 lo{std::numeric_limits<float>::infinity()};
    glm::vec3 hi{-std::numeric_limits<float>::infinity()};
    void grow(const glm::vec3& p_lo, const glm::vec3& p_hi)
    {
        lo = glm::min(lo, p_lo);
        hi = glm::max(hi, p_hi);
    }
    void grow(const Box& b) { grow(b.lo, b.hi); }
    float area() const
    {
        glm::vec3 d = hi - lo;
        return (d.x < 0.0f) ? 0.0f : 2.0f * (d.x * d.y + d.y * d.z + d.z * d.x);
    }
};

struct Builder {
    Builder(const BvhBuildInput& input, Bvh* output) : in(input), out(output) {}
    const BvhBuildInput& in;
    std::vector<glm::vec3> centroid;
    std::vector<std::uint32_t> order;
    Bvh* out;

    struct Child {
        Box box;
        int index; // binary node index, or first triangle for a leaf; -1: empty
        int count; // 0: inner node
    };
    struct BinaryNode {
        Child child[2];
    };
    std::vector<BinaryNode> nodes; // the binary SAH tree, collapsed afterwards

    // Builds the subtree over order[begin, end) and returns it as a child reference.
    Child build(std::size_t begin, std::size_t end, int depth)
    {
        Box bounds, cbounds;
        for (std::size_t i = begin; i < end; ++i) {
            std::uint32_t t = order[i];
            bounds.grow(in.box_min[t], in.box_max[t]);
            cbounds.grow(centroid[t], centroid[t]);
        }
        std::size_t n = end - begin;
        out->depth = std::max(out->depth, depth);
        auto leaf = [&]() { return Child{bounds, static_cast<int>(begin), static_cast<int>(n)}; };
        if (n <= 1 || depth >= kBvhMaxDepth)
            return leaf();

        // Binned SAH over the axis-aligned planes of every axis.
        float best_cost = std::numeric_limits<float>::infinity();
        int best_axis = -1, best_split = 0;
        glm::vec3 extent = cbounds.hi - cbounds.lo;
        for (int axis = 0; axis < 3; ++axis) {
            if (!(extent[axis] > 0.0f))
                continue;
            std::array<Box, kBins> bin_box;
            std::array<std::size_t, kBins> bin_count{};
            float scale = kBins / extent[axis];
            for (std::size_t i = begin; i < end; ++i) {
                std::uint32_t t = order[i];
                int b = bin_index(centroid[t][axis] - cbounds.lo[axis], scale);
                bin_box[static_cast<std::size_t>(b)].grow(in.box_min[t], in.box_max[t]);
                bin_count[static_cast<std::size_t>(b)] += 1;
            }
            std::array<float, kBins> right_area{};
            std::array<std::size_t, kBins> right_count{};
            Box acc;
            std::size_t cnt = 0;
            for (int b = kBins - 1; b > 0; --b) {
                acc.grow(bin_box[static_cast<std::size_t>(b)]);
                cnt += bin_count[static_cast<std::size_t>(b)];
                right_area[static_cast<std::size_t>(b)] = acc.area();
                right_count[static_cast<std::size_t>(b)] = cnt;
            }
            acc = Box{};
            cnt = 0;
            for (int b = 0; b < kBins - 1; ++b) {
                acc.grow(bin_box[static_cast<std::size_t>(b)]);
                cnt += bin_count[static_cast<std::size_t>(b)];
                std::size_t rc = right_count[static_cast<std::size_t>(b + 1)];
                if (cnt == 0 || rc == 0)
                    continue;
                float sah = acc.area() * static_cast<float>(cnt) +
                            right_area[static_cast<std::size_t>(b + 1)] * static_cast<float>(rc);
                if (sah < best_cost) {
                    best_cost = sah;
                    best_axis = axis;
                    best_split = b + 1;
                }
            }
        }
        float area = bounds.area();
        float leaf_cost = kIntersectCost * static_cast<float>(n);
        float split_cost =
            (area > 0.0f) ? kTraversalCost + kIntersectCost * best_cost / area : std::numeric_limits<float>::infinity();
        if (best_axis >= 0 && n <= kBvhMaxLeafSize && leaf_cost <= split_cost)
            return leaf();

        std::size_t mid;
        if (best_axis >= 0) {
            float scale = kBins / extent[best_axis];
            auto it =
                std::partition(order.begin() + static_cast<std::ptrdiff_t>(begin),
                               order.begin() + static_cast<std::ptrdiff_t>(end), [&](std::uint32_t t) {
                                   return bin_index(centroid[t][best_axis] - cbounds.lo[best_axis], scale) < best_split;
                               });
            mid = static_cast<std::size_t>(it - order.begin());
        } else {
            // All centroids coincide: SAH cannot separate them; split the list in half.
            if (n <= kBvhMaxLeafSize)
                return leaf();
            mid = begin + n / 2;
        }
        if (mid == begin || mid == end)
            mid = begin + n / 2;

        std::size_t self = nodes.size();
        nodes.emplace_back();
        Child left = build(begin, mid, depth + 1);
        Child right = build(mid, end, depth + 1);
        nodes[self] = BinaryNode{{left, right}};
        return Child{bounds, static_cast<int>(self), 0};
    }

    // The eight-wide tree chosen by cost (Ylitie, Karras and Laine 2017): every binary
    // subtree may become one slot of its parent's wide node (a leaf of its triangles, when
    // at most eight, or a wide node of its own) or be spread over several slots, its
    // children's. cost[n][i - 1] is the least expected cost of binary node n's subtree in
    // at most i slots, a node's or leaf's cost weighted by its box's area (the chance that
    // a ray enters it); choose_wide fills the table bottom up, emit_wide reads it back.
    std::vector<std::array<float, kBvhWidth>> cost;
    // How cost[n][i - 1] is reached for i >= 2: kFewerSlots (as in i - 1 slots) or the
    // slots the left child gets (the right child gets the rest). choice[n][0] is the left
    // child's share of the eight slots of n's own wide node (emit_wide).
    static constexpr std::int8_t kFewerSlots = -1;
    std::vector<std::array<std::int8_t, kBvhWidth>> choice;
    std::vector<std::uint8_t> as_leaf;          // one slot: a leaf, not a wide node
    std::vector<int> first_triangle, triangles; // each binary node's range of `order`

    float slot_cost(const Child& c, int slots) const
    {
        if (c.count > 0)
            return c.box.area() * kBvhLeafCost;
        return cost[static_cast<std::size_t>(c.index)][static_cast<std::size_t>(slots - 1)];
    }
    // The best split of binary node n's two children over at most `slots` slots (>= 2);
    // its cost, and the left child's share in *left.
    float split_cost(int n, int slots, int* left) const
    {
        const BinaryNode& b = nodes[static_cast<std::size_t>(n)];
        float best = std::numeric_limits<float>::infinity();
        for (int j = 1; j < slots; ++j) {
            float c = slot_cost(b.child[0], j) + slot_cost(b.child[1], slots - j);
            if (c < best) {
                best = c;
                *left = j;
            }
        }
        return best;
    }
    void choose_wide()
    {
        const std::size_t count = nodes.size();
        cost.assign(count, {});
        choice.assign(count, {});
        as_leaf.assign(count, 0);
        first_triangle.assign(count, 0);
        triangles.assign(count, 0);
        // Children come after their parent (build() numbers a node before its subtrees).
        for (std::size_t k = count; k-- > 0;) {
            const BinaryNode& b = nodes[k];
            if (b.child[0].index < 0 || b.child[1].index < 0)
                continue; // the root of a scene of one leaf or none: emit_wide takes its children as they are
            int tris = 0, first = std::numeric_limits<int>::max();
            Box box;
            for (const Child& c : b.child) {
                box.grow(c.box);
                tris += c.count > 0 ? c.count : triangles[static_cast<std::size_t>(c.index)];
                first = std::min(first, c.count > 0 ? c.index : first_triangle[static_cast<std::size_t>(c.index)]);
            }
            triangles[k] = tris;
            first_triangle[k] = first;
            const float area = box.area();
            int left = 1;
            const float node = area * kBvhWideNodeCost + split_cost(static_cast<int>(k), kBvhWidth, &left);
            const float leaf = tris <= kBvhMaxLeafSize ? area * kBvhLeafCost : std::numeric_limits<float>::infinity();
            as_leaf[k] = leaf <= node;
            cost[k][0] = std::min(leaf, node);
            choice[k][0] = static_cast<std::int8_t>(left); // the wide node's split, from `node`
            for (int i = 2; i <= kBvhWidth; ++i) {
                const float spread = split_cost(static_cast<int>(k), i, &left);
                const bool fewer = cost[k][static_cast<std::size_t>(i - 2)] <= spread;
                cost[k][static_cast<std::size_t>(i - 1)] = fewer ? cost[k][static_cast<std::size_t>(i - 2)] : spread;
                choice[k][static_cast<std::size_t>(i - 1)] = fewer ? kFewerSlots : static_cast<std::int8_t>(left);
            }
        }
    }
    // The slots child c takes when it may have at most `slots` of them.
    void wide_slots(const Child& c, int slots, std::vector<Child>* kids) const
    {
        if (c.count > 0) {
            kids->push_back(c);
            return;
        }
        const std::size_t n = static_cast<std::size_t>(c.index);
        while (slots > 1 && choice[n][static_cast<std::size_t>(slots - 1)] == kFewerSlots)
            --slots;
        if (slots == 1) {
            kids->push_back(as_leaf[n] ? Child{c.box, first_triangle[n], triangles[n]} : c);
            return;
        }
        const int left = choice[n][static_cast<std::size_t>(slots - 1)];
        wide_slots(nodes[n].child[0], left, kids);
        wide_slots(nodes[n].child[1], slots - left, kids);
    }
    // The wide node of binary node n (chosen by choose_wide); returns its index.
    int emit_wide(int n)
    {
        std::vector<Child> kids;
        const BinaryNode& b = nodes[static_cast<std::size_t>(n)];
        if (b.child[0].index < 0 || b.child[1].index < 0) {
            for (const Child& c : b.child)
                if (c.index >= 0)
                    kids.push_back(c);
        } else {
            const int left = choice[static_cast<std::size_t>(n)][0];
            wide_slots(b.child[0], left, &kids);
            wide_slots(b.child[1], kBvhWidth - left, &kids);
        }
        return store_wide(kids, [this](int child) { return emit_wide(child); });
    }

    // The fallback for a tree too deep for the traversal stack: each node takes the
    // grandchildren of a binary one (a child that is a leaf stands for itself), at most
    // four children, so every wide level spans at least two binary levels and pushes at
    // most three entries: within the stack whatever the tree's shape. Returns the node's
    // index.
    std::vector<BvhNode> wide;

    int collapse_four(int binary)
    {
        std::vector<Child> kids;
        for (const Child& c : nodes[static_cast<std::size_t>(binary)].child) {
            if (c.index < 0)
                continue; // empty (only under the root of a scene with one leaf or none)
            if (c.count == 0) {
                for (const Child& g : nodes[static_cast<std::size_t>(c.index)].child)
                    if (g.index >= 0)
                        kids.push_back(g);
            } else {
                kids.push_back(c);
            }
        }
        return store_wide(kids, [this](int child) { return collapse_four(child); });
    }

    // Stores a wide node of the given children (at most eight); `inner(binary)` makes the
    // wide node of an inner child. Returns the node's index.
    template <typename Inner>
    int store_wide(const std::vector<Child>& kids, Inner inner)
    {
        const int k = static_cast<int>(kids.size());
        int self = static_cast<int>(wide.size());
        wide.emplace_back();
        BvhNode node{};
        float* lo[3] = {node.lo_x.s, node.lo_y.s, node.lo_z.s};
        float* hi[3] = {node.hi_x.s, node.hi_y.s, node.hi_z.s};
        for (int j = 0; j < kBvhWidth; ++j) {
            const bool used = j < k;
            // An empty slot gets an inverted box. A used one is widened outwards (one ulp,
            // widen_down/up), so that a ray parallel to an axis in the plane of a face is
            // strictly inside the slab (traversal.cl ray_box_entry8).
            for (int a = 0; a < 3; ++a) {
                lo[a][j] = used ? widen_down(kids[j].box.lo[a]) : std::numeric_limits<float>::infinity();
                hi[a][j] = used ? widen_up(kids[j].box.hi[a]) : -std::numeric_limits<float>::infinity();
            }
            node.count.s[j] = used ? kids[j].count : 0;
            node.index.s[j] = used ? (kids[j].count > 0 ? kids[j].index : inner(kids[j].index)) : -1;
        }
        wide[static_cast<std::size_t>(self)] = node;
        return self;
    }

    // Stack entries traversal may need below node i: it pushes all but one of the
    // children it enters.
    int stack_needed(int i, int depth)
    {
        const BvhNode& n = wide[static_cast<std::size_t>(i)];
        int children = 0, deepest = 0;
        out->wide_depth = std::max(out->wide_depth, depth);
        for (int j = 0; j < kBvhWidth; ++j) {
            if (n.index.s[j] < 0)
                continue;
            ++children;
            if (n.count.s[j] == 0) {
                deepest = std::max(deepest, stack_needed(n.index.s[j], depth + 1));
            } else {
                out->leaf_count += 1;
                out->max_leaf_size = std::max(out->max_leaf_size, n.count.s[j]);
            }
        }
        return std::max(children - 1, 0) + deepest;
    }
};

} // namespace

BvhBuildInput bvh_input_from_triangles(const std::vector<glm::vec3>& v)
{
    BvhBuildInput in;
    std::size_t n = v.size() / 3;
    in.box_min.resize(n);
    in.box_max.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        in.box_min[i] = glm::min(v[3 * i], glm::min(v[3 * i + 1], v[3 * i + 2]));
        in.box_max[i] = glm::max(v[3 * i], glm::max(v[3 * i + 1], v[3 * i + 2]));
    }
    return in;
}

Bvh build_bvh(const BvhBuildInput& input, int stack_size)
{
    Bvh bvh;
    std::size_t n = input.box_min.size();
    Builder b{input, &bvh};
    b.centroid.resize(n);
    for (std::size_t i = 0; i < n; ++i)
        b.centroid[i] = 0.5f * (input.box_min[i] + input.box_max[i]);
    b.order.resize(n);
    std::iota(b.order.begin(), b.order.end(), 0u);

    Builder::Child empty{Box{}, -1, 0};
    if (n == 0) {
        b.nodes.push_back(Builder::BinaryNode{{empty, empty}});
    } else {
        // The first node build() allocates is the binary root, index 0.
        Builder::Child top = b.build(0, n, 1);
        if (top.count > 0) // the whole scene is one leaf: hang it under an inner root
            b.nodes.push_back(Builder::BinaryNode{{top, empty}});
    }
    b.choose_wide();
    b.emit_wide(0); // the eight-wide root is node 0
    bvh.stack_needed = b.stack_needed(0, 1);
    // + 1: a node's children are all pushed before one is popped. Full nodes along a deep
    // path can push seven entries per three binary levels, more than the stack holds at the
    // depth cap; such a tree (it takes a contrived scene) gets nodes of at most four
    // children instead.
    if (bvh.stack_needed + 1 > stack_size) {
        b.wide.clear();
        bvh.wide_depth = 0;
        bvh.leaf_count = 0;
        bvh.max_leaf_size = 0;
        b.collapse_four(0);
        bvh.stack_needed = b.stack_needed(0, 1);
    }
    if (bvh.stack_needed + 1 > stack_size)
        throw std::logic_error("BVH needs a traversal stack of " + std::to_string(bvh.stack_needed));
    bvh.nodes = std::move(b.wide);
    bvh.triangle_order = std::move(b.order);
    return bvh;
}

} // namespace pathcl
