// BVH invariants on the host: every triangle in exactly one leaf, boxes tight and nested,
// no empty leaves, depth within the kernels' stack.
#include <bit>
#include <functional>

#include <gtest/gtest.h>

#include "bvh/bvh_builder.h"
#include "support/random_meshes.h"

namespace pathcl {
namespace {

struct Ref {
    int index, count;
};

Ref left_of(const BvhNode& n) { return {std::bit_cast<int>(n.left_min.w), std::bit_cast<int>(n.left_max.w)}; }
Ref right_of(const BvhNode& n) { return {std::bit_cast<int>(n.right_min.w), std::bit_cast<int>(n.right_max.w)}; }

// Walks the tree, checking each child box equals the union of its triangles' boxes, and
// counts how often each triangle slot appears in a leaf.
void check_tree(const Bvh& bvh, const BvhBuildInput& in, bool allow_empty_child)
{
    std::vector<int> seen(bvh.triangle_order.size(), 0);
    int max_depth = 0;
    std::function<void(Ref, glm::vec3, glm::vec3, int)> visit = [&](Ref ref, glm::vec3 lo, glm::vec3 hi, int depth) {
        max_depth = std::max(max_depth, depth);
        glm::vec3 ulo(INFINITY), uhi(-INFINITY);
        if (ref.count > 0) {
            for (int i = ref.index; i < ref.index + ref.count; ++i) {
                ASSERT_GE(i, 0);
                ASSERT_LT(static_cast<std::size_t>(i), seen.size());
                seen[static_cast<std::size_t>(i)] += 1;
                std::uint32_t t = bvh.triangle_order[static_cast<std::size_t>(i)];
                ulo = glm::min(ulo, in.box_min[t]);
                uhi = glm::max(uhi, in.box_max[t]);
            }
        } else {
            ASSERT_GE(ref.index, 0);
            ASSERT_LT(static_cast<std::size_t>(ref.index), bvh.nodes.size());
            const BvhNode& n = bvh.nodes[static_cast<std::size_t>(ref.index)];
            for (auto [child, cmin, cmax] : {std::tuple{left_of(n), n.left_min, n.left_max},
                                             std::tuple{right_of(n), n.right_min, n.right_max}}) {
                if (child.index < 0) {
                    EXPECT_TRUE(allow_empty_child) << "empty child in a tree with several leaves";
                    continue;
                }
                EXPECT_GT(child.count >= 0 ? 1 : 0, 0) << "negative leaf count";
                glm::vec3 clo(cmin.x, cmin.y, cmin.z), chi(cmax.x, cmax.y, cmax.z);
                // Nested: a child's box lies inside its parent's.
                EXPECT_TRUE(glm::all(glm::greaterThanEqual(clo, lo)) && glm::all(glm::lessThanEqual(chi, hi)));
                visit(child, clo, chi, depth + 1);
                ulo = glm::min(ulo, clo);
                uhi = glm::max(uhi, chi);
            }
        }
        // Tight: the box is exactly the union of what it holds.
        EXPECT_EQ(ulo, lo);
        EXPECT_EQ(uhi, hi);
    };
    const BvhNode& root = bvh.nodes[0];
    glm::vec3 lo = glm::min(glm::vec3(root.left_min.x, root.left_min.y, root.left_min.z),
                            glm::vec3(root.right_min.x, root.right_min.y, root.right_min.z));
    glm::vec3 hi = glm::max(glm::vec3(root.left_max.x, root.left_max.y, root.left_max.z),
                            glm::vec3(root.right_max.x, root.right_max.y, root.right_max.z));
    visit(Ref{0, 0}, lo, hi, 1);
    for (std::size_t i = 0; i < seen.size(); ++i)
        ASSERT_EQ(seen[i], 1) << "triangle slot " << i << " appears " << seen[i] << " times";
    EXPECT_LE(max_depth, kBvhMaxDepth + 1);
    // triangle_order is a permutation.
    std::vector<int> perm(seen.size(), 0);
    for (std::uint32_t t : bvh.triangle_order)
        perm[t] += 1;
    for (int c : perm)
        ASSERT_EQ(c, 1);
}

TEST(BvhBuilder, RandomSoupInvariants)
{
    for (std::uint32_t seed : {1u, 2u, 3u}) {
        auto v = test::random_triangle_soup(5000, seed);
        BvhBuildInput in = bvh_input_from_triangles(v);
        Bvh bvh = build_bvh(in);
        check_tree(bvh, in, false);
        EXPECT_LE(bvh.max_leaf_size, kBvhMaxLeafSize);
        EXPECT_GT(bvh.leaf_count, 5000 / kBvhMaxLeafSize);
    }
}

TEST(BvhBuilder, ClosedSphereInvariants)
{
    auto v = test::jittered_sphere(40, 80, 7);
    BvhBuildInput in = bvh_input_from_triangles(v);
    check_tree(build_bvh(in), in, false);
}

TEST(BvhBuilder, SingleTriangleHangsUnderInnerRoot)
{
    std::vector<glm::vec3> v = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    BvhBuildInput in = bvh_input_from_triangles(v);
    Bvh bvh = build_bvh(in);
    ASSERT_EQ(bvh.nodes.size(), 1u);
    EXPECT_EQ(left_of(bvh.nodes[0]).count, 1);
    EXPECT_EQ(right_of(bvh.nodes[0]).index, -1);
    check_tree(bvh, in, true);
}

TEST(BvhBuilder, EmptySceneHasOneRootWithTwoEmptyChildren)
{
    Bvh bvh = build_bvh(BvhBuildInput{});
    ASSERT_EQ(bvh.nodes.size(), 1u);
    EXPECT_EQ(left_of(bvh.nodes[0]).index, -1);
    EXPECT_EQ(right_of(bvh.nodes[0]).index, -1);
}

TEST(BvhBuilder, IdenticalTrianglesStillSplitIntoSmallLeaves)
{
    // SAH cannot separate coincident centroids; the builder must still bound leaf size.
    std::vector<glm::vec3> v;
    for (int i = 0; i < 1000; ++i)
        v.insert(v.end(), {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
    BvhBuildInput in = bvh_input_from_triangles(v);
    Bvh bvh = build_bvh(in);
    check_tree(bvh, in, false);
    EXPECT_LE(bvh.max_leaf_size, kBvhMaxLeafSize);
}

} // namespace
} // namespace pathcl
