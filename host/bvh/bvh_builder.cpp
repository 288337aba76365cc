#include "bvh/bvh_builder.h"

#include <algorithm>
#include <array>
#include <bit>
#include <limits>
#include <numeric>

namespace pathcl {
namespace {

constexpr int kBins = 32;
constexpr float kTraversalCost = 1.0f; // relative to one triangle test
constexpr float kIntersectCost = 1.0f;

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
    std::vector<BvhNode> nodes;
    Bvh* out;

    struct Child {
        Box box;
        int index; // node index, or first triangle for a leaf
        int count; // 0: inner node
    };

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
        float split_cost = (area > 0.0f) ? kTraversalCost + kIntersectCost * best_cost / area
                                         : std::numeric_limits<float>::infinity();
        if (best_axis >= 0 && n <= kBvhMaxLeafSize && leaf_cost <= split_cost)
            return leaf();

        std::size_t mid;
        if (best_axis >= 0) {
            float scale = kBins / extent[best_axis];
            auto it = std::partition(order.begin() + static_cast<std::ptrdiff_t>(begin),
                                     order.begin() + static_cast<std::ptrdiff_t>(end),
                                     [&](std::uint32_t t) {
                                         int b = std::min(kBins - 1, static_cast<int>((centroid[t][best_axis] -
                                                                                       cbounds.lo[best_axis]) * scale));
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
        nodes[self] = make_node(left, right);
        return Child{bounds, static_cast<int>(self), 0};
    }

    static BvhNode make_node(const Child& l, const Child& r)
    {
        BvhNode node;
        node.left_min = {l.box.lo.x, l.box.lo.y, l.box.lo.z, std::bit_cast<float>(l.index)};
        node.left_max = {l.box.hi.x, l.box.hi.y, l.box.hi.z, std::bit_cast<float>(l.count)};
        node.right_min = {r.box.lo.x, r.box.lo.y, r.box.lo.z, std::bit_cast<float>(r.index)};
        node.right_max = {r.box.hi.x, r.box.hi.y, r.box.hi.z, std::bit_cast<float>(r.count)};
        return node;
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

Bvh build_bvh(const BvhBuildInput& input)
{
    Bvh bvh;
    std::size_t n = input.box_min.size();
    Builder b{input, {}, {}, {}, &bvh};
    b.centroid.resize(n);
    for (std::size_t i = 0; i < n; ++i)
        b.centroid[i] = 0.5f * (input.box_min[i] + input.box_max[i]);
    b.order.resize(n);
    std::iota(b.order.begin(), b.order.end(), 0u);

    Builder::Child empty{Box{}, -1, 0};
    if (n == 0) {
        b.nodes.push_back(Builder::make_node(empty, empty));
    } else {
        // The first node build() allocates is the root, index 0.
        Builder::Child top = b.build(0, n, 1);
        if (top.count > 0) // the whole scene is one leaf: hang it under an inner root
            b.nodes.push_back(Builder::make_node(top, empty));
    }
    bvh.nodes = std::move(b.nodes);
    bvh.triangle_order = std::move(b.order);
    return bvh;
}

} // namespace pathcl
