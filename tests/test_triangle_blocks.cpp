// The traversal's leaf blocks (host/bvh/triangle_blocks.cpp): every leaf's triangles in
// the lanes of its own block, in leaf order, and nothing else in them; and each
// triangle's leaf found again (triangle_leaves). The traversal
// tests (test_bvh_traversal.cpp) check the hits found through them against every triangle
// tested one by one.
#include <cmath>
#include <cstdint>
#include <set>
#include <stdexcept>

#include <gtest/gtest.h>

#include "bvh/bvh_builder.h"
#include "bvh/triangle_blocks.h"
#include "support/leaf_triangles.h"
#include "support/random_meshes.h"

namespace pathcl::test_triangle_blocks {
namespace {

// A BVH, its triangles in leaf order, its nodes and their leaf blocks.
struct BlockedBvh {
    Bvh bvh;
    std::vector<Triangle> tris;
    std::vector<BvhNode> nodes;
    std::vector<TriangleBlock> blocks;
};

// A BVH over the triangles of v and its leaves' blocks made (its nodes rewritten); under
// a stand-in top level of a two-level BVH where asked: a copy of the BVH's nodes put before
// them, whose leaves name instances by index, not triangles, and the blocks made from the
// first node after it (bvh.nodes.size()).
BlockedBvh blocked_bvh(const std::vector<glm::vec3>& v, bool under_a_top_level = false)
{
    BlockedBvh b;
    b.bvh = build_bvh(bvh_input_from_triangles(v));
    b.tris = test::leaf_order_triangles(v, b.bvh);
    b.nodes = b.bvh.nodes;
    std::size_t first = 0;
    if (under_a_top_level) {
        b.nodes.insert(b.nodes.begin(), b.bvh.nodes.begin(), b.bvh.nodes.end());
        first = b.bvh.nodes.size();
    }
    make_triangle_blocks(b.nodes, first, b.tris, b.blocks);
    return b;
}

TEST(TriangleBlocks, EveryLeafNamesABlockOfItsTrianglesInOrder)
{
    const BlockedBvh blocked = blocked_bvh(test::jittered_sphere(20, 40, 3));
    const Bvh& bvh = blocked.bvh;
    const std::vector<Triangle>& tris = blocked.tris;
    const std::vector<BvhNode>& nodes = blocked.nodes;
    const std::vector<TriangleBlock>& blocks = blocked.blocks;
    ASSERT_EQ(blocks.size(), static_cast<std::size_t>(bvh.leaf_count));
    std::set<int> seen_blocks, seen_triangles;
    for (std::size_t n = 0; n < nodes.size(); ++n)
        for (int k = 0; k < kBvhWidth; ++k) {
            const int count = bvh.nodes[n].count.s[k], first = bvh.nodes[n].index.s[k];
            EXPECT_EQ(nodes[n].count.s[k], count);
            if (count == 0) { // inner nodes and empty slots keep their index
                EXPECT_EQ(nodes[n].index.s[k], first);
                continue;
            }
            const int b = nodes[n].index.s[k];
            ASSERT_GE(b, 0);
            ASSERT_LT(static_cast<std::size_t>(b), blocks.size());
            EXPECT_TRUE(seen_blocks.insert(b).second) << "block " << b << " named twice";
            const TriangleBlock& block = blocks[static_cast<std::size_t>(b)];
            for (int lane = 0; lane < kBvhWidth; ++lane) {
                if (lane >= count) {
                    EXPECT_EQ(block.triangle.s[lane], -1);
                    for (const pcl_float8& row : block.vertex)
                        EXPECT_TRUE(std::isnan(row.s[lane]));
                    continue;
                }
                const int t = first + lane;
                EXPECT_EQ(block.triangle.s[lane], t);
                seen_triangles.insert(t);
                const Triangle& tri = tris[static_cast<std::size_t>(t)];
                const pcl_float4* vert[3] = {&tri.v0, &tri.v1, &tri.v2};
                for (int i = 0; i < 3; ++i) {
                    EXPECT_EQ(block.vertex[3 * i + 0].s[lane], vert[i]->x);
                    EXPECT_EQ(block.vertex[3 * i + 1].s[lane], vert[i]->y);
                    EXPECT_EQ(block.vertex[3 * i + 2].s[lane], vert[i]->z);
                }
            }
        }
    EXPECT_EQ(seen_triangles.size(), tris.size());
}

TEST(TriangleBlocks, NodesBeforeTheFirstAreLeftAlone)
{
    // A two-level BVH's top-level leaves name instances, not triangles.
    const BlockedBvh b = blocked_bvh(test::random_triangle_soup(200, 4), true);
    EXPECT_EQ(b.blocks.size(), static_cast<std::size_t>(b.bvh.leaf_count));
    for (std::size_t n = 0; n < b.bvh.nodes.size(); ++n)
        for (int k = 0; k < kBvhWidth; ++k)
            EXPECT_EQ(b.nodes[n].index.s[k], b.bvh.nodes[n].index.s[k]);
}

TEST(TriangleBlocks, ALeafPastTheTrianglesIsRefused)
{
    auto v = test::random_triangle_soup(50, 5);
    const Bvh bvh = build_bvh(bvh_input_from_triangles(v));
    std::vector<Triangle> tris = test::leaf_order_triangles(v, bvh);
    tris.pop_back();
    std::vector<BvhNode> nodes = bvh.nodes;
    std::vector<TriangleBlock> blocks;
    EXPECT_THROW(make_triangle_blocks(nodes, 0, tris, blocks), std::logic_error);
}

// Every stored triangle's leaf, as triangle_leaves finds it: its block holds the triangle
// and its node's slot names that block. Broken variant seen failing: the node taken one
// past the right one.
void expect_leaves_hold_their_triangles(const std::vector<BvhNode>& nodes, std::size_t first_node,
                                        const std::vector<TriangleBlock>& blocks, std::size_t triangle_count)
{
    const std::vector<TriangleLeaf> leaves = triangle_leaves(nodes, first_node, blocks, triangle_count);
    ASSERT_EQ(leaves.size(), triangle_count);
    for (std::size_t t = 0; t < triangle_count; ++t) {
        const TriangleLeaf& leaf = leaves[t];
        ASSERT_GE(leaf.node, static_cast<std::int32_t>(first_node)) << "triangle " << t;
        ASSERT_LT(static_cast<std::size_t>(leaf.node), nodes.size()) << "triangle " << t;
        ASSERT_GE(leaf.block, 0) << "triangle " << t;
        ASSERT_LT(static_cast<std::size_t>(leaf.block), blocks.size()) << "triangle " << t;
        const BvhNode& node = nodes[static_cast<std::size_t>(leaf.node)];
        int slots = 0;
        for (int k = 0; k < kBvhWidth; ++k)
            slots += node.count.s[k] > 0 && node.index.s[k] == leaf.block;
        EXPECT_EQ(slots, 1) << "triangle " << t << ": node " << leaf.node << " names block " << leaf.block;
        int lanes = 0;
        for (const std::int32_t held : blocks[static_cast<std::size_t>(leaf.block)].triangle.s)
            lanes += held == static_cast<std::int32_t>(t);
        EXPECT_EQ(lanes, 1) << "triangle " << t << " in block " << leaf.block;
    }
}

TEST(TriangleLeaves, EachTriangleIsInTheBlockItsNodeNames)
{
    const BlockedBvh b = blocked_bvh(test::jittered_sphere(20, 40, 6));
    expect_leaves_hold_their_triangles(b.nodes, 0, b.blocks, b.tris.size());
}

TEST(TriangleLeaves, ATopLevelsLeavesAreNotTriangles)
{
    // The stand-in top level's leaves name instances by index: read as blocks, they would
    // put triangles in two leaves.
    const BlockedBvh b = blocked_bvh(test::random_triangle_soup(200, 7), true);
    expect_leaves_hold_their_triangles(b.nodes, b.bvh.nodes.size(), b.blocks, b.tris.size());
    EXPECT_THROW(triangle_leaves(b.nodes, 0, b.blocks, b.tris.size()), std::logic_error);
}

TEST(TriangleLeaves, ATriangleInNoLeafIsRefused)
{
    const BlockedBvh b = blocked_bvh(test::random_triangle_soup(50, 8));
    EXPECT_THROW(triangle_leaves(b.nodes, 0, b.blocks, b.tris.size() + 1), std::logic_error);
}

TEST(TriangleLeaves, ATriangleInTwoLeavesIsRefused)
{
    // One slot pointed at another leaf's block of as many triangles: every triangle is
    // still counted once on the whole, so only the check of each one's leaf can tell.
    BlockedBvh b = blocked_bvh(test::random_triangle_soup(200, 9));
    std::vector<std::pair<std::size_t, int>> slots; // leaf slots: node, lane
    for (std::size_t n = 0; n < b.nodes.size(); ++n)
        for (int k = 0; k < kBvhWidth; ++k)
            if (b.nodes[n].count.s[k] > 0)
                slots.emplace_back(n, k);
    bool redirected = false;
    for (std::size_t i = 0; i < slots.size() && !redirected; ++i)
        for (std::size_t j = i + 1; j < slots.size() && !redirected; ++j) {
            const BvhNode& first = b.nodes[slots[i].first];
            BvhNode& second = b.nodes[slots[j].first];
            if (first.count.s[slots[i].second] == second.count.s[slots[j].second]) {
                second.index.s[slots[j].second] = first.index.s[slots[i].second];
                redirected = true;
            }
        }
    ASSERT_TRUE(redirected) << "no two leaves of as many triangles";
    EXPECT_THROW(triangle_leaves(b.nodes, 0, b.blocks, b.tris.size()), std::logic_error);
}

} // namespace
} // namespace pathcl::test_triangle_blocks
