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
        auto leaf = [&]() {
            out->leaf_count += 1;
            out->max_leaf_size = std::max(out->max_leaf_size, static_cast<int>(n));
            return Child{bounds, static_cast<int>(begin), static_cast<int>(n)};
        };
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
                int b = std::min(kBins - 1, static_cast<int>((centroid[t][axis] - cbounds.lo[axis]) * scale));
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
                float cost = acc.area() * static_cast<float>(cnt) +
                             right_area[static_cast<std::size_t>(b + 1)] * static_cast<float>(rc);
                if (cost < best_cost) {
                    best_cost = cost;
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
            auto it = std::partition(
                order.begin() + static_cast<std::ptrdiff_t>(begin), order.begin() + static_cast<std::ptrdiff_t>(end),
                [&](std::uint32_t t) {
                    int b =
                        std::min(kBins - 1, static_cast<int>((centroid[t][best_axis] - cbounds.lo[best_axis]) * scale));
                    return b < best_split;
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

    // The eight-wide tree: each node takes the grandchildren of a binary node (a child
    // that is a leaf stands for itself), so every eight-wide level spans at least two
    // binary levels; that bounds the traversal stack (stack_needed). It then opens its
    // largest inner child (by surface area: the likeliest to be entered) while the
    // grandchildren fit, so that nodes hold up to eight children and the tree has fewer
    // levels. Without `fill`, nodes keep only the grandchildren (at most four children,
    // three pushes per level: within the stack whatever the tree's shape). Returns the
    // node's index.
    std::vector<BvhNode> wide;

    int collapse(int binary, bool fill)
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
        while (fill) {
            int best = -1;
            float best_area = -1.0f;
            for (std::size_t i = 0; i < kids.size(); ++i)
                if (kids[i].count == 0) {
                    int grandkids = 0;
                    for (const Child& g : nodes[static_cast<std::size_t>(kids[i].index)].child)
                        grandkids += g.index >= 0;
                    if (kids.size() - 1 + static_cast<std::size_t>(grandkids) <= static_cast<std::size_t>(kBvhWidth) &&
                        kids[i].box.area() > best_area) {
                        best_area = kids[i].box.area();
                        best = static_cast<int>(i);
                    }
                }
            if (best < 0)
                break;
            Child open = kids[static_cast<std::size_t>(best)];
            kids.erase(kids.begin() + best);
            for (const Child& g : nodes[static_cast<std::size_t>(open.index)].child)
                if (g.index >= 0)
                    kids.push_back(g);
        }
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
            node.index.s[j] = used ? (kids[j].count > 0 ? kids[j].index : collapse(kids[j].index, fill)) : -1;
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
            if (n.count.s[j] == 0)
                deepest = std::max(deepest, stack_needed(n.index.s[j], depth + 1));
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
    Builder b{input, {}, {}, &bvh, {}, {}};
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
    b.collapse(0, true); // the eight-wide root is node 0
    bvh.stack_needed = b.stack_needed(0, 1);
    // + 1: a node's children are all pushed before one is popped. Full nodes along a deep
    // path can push seven entries per three binary levels, more than the stack holds at the
    // depth cap; such a tree (it takes a contrived scene) gets nodes of at most four
    // children instead.
    if (bvh.stack_needed + 1 > stack_size) {
        b.wide.clear();
        bvh.wide_depth = 0;
        b.collapse(0, false);
        bvh.stack_needed = b.stack_needed(0, 1);
    }
    if (bvh.stack_needed + 1 > stack_size)
        throw std::logic_error("BVH needs a traversal stack of " + std::to_string(bvh.stack_needed));
    bvh.nodes = std::move(b.wide);
    bvh.triangle_order = std::move(b.order);
    return bvh;
}

} // namespace pathcl
