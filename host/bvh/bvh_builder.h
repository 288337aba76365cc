// Binned SAH BVH over triangles: built binary, then turned into the eight-wide BvhNode
// array the kernels traverse with a fixed stack (kernels/bvh/traversal.cl) by the
// collapse of least expected cost (Ylitie, Karras and Laine 2017): each binary subtree
// becomes a leaf of up to eight triangles, a wide node, or several slots of its parent.
// (The device tests a leaf's triangles from a block of eight lanes: triangle_blocks.h.)
// Node 0 is the root and is always an inner node; leaves live inside their parent as
// (first triangle, count).
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "types.h"

namespace pathcl {

struct BvhBuildInput {
    std::vector<glm::vec3> box_min, box_max; // per triangle
};

struct Bvh {
    std::vector<BvhNode> nodes;
    // Leaf order: triangle_order[i] is the input triangle stored at position i.
    std::vector<std::uint32_t> triangle_order;
    int depth = 0;        // longest root-to-leaf path of the binary tree, in nodes
    int wide_depth = 0;   // the same in the eight-wide tree
    int stack_needed = 0; // most traversal stack entries any ray can need
    int leaf_count = 0;
    int max_leaf_size = 0;
};

// The binary depth bound keeps the tree within the kernels' traversal stack: at most 31
// levels, each pushing at most 3 entries where nodes keep at most four children, the
// builder's fallback for a tree whose full nodes would need more (BVH_STACK_SIZE, types.h).
constexpr int kBvhMaxDepth = 60;
constexpr int kBvhWidth = BVH_WIDTH;
constexpr int kBvhStackSize = BVH_STACK_SIZE;
constexpr int kBvhMaxLeafSize = 8;
// The eight-wide tree's cost model (the collapse of least cost), relative to one
// triangle test of the binary SAH: a node visit (one float8 slab test and the ordering of
// the children entered), and a leaf's test, which takes its up to eight triangles in one
// pass of float8 arithmetic (ray_triangle_block) and so costs the same for any number.
constexpr float kBvhWideNodeCost = 1.0f;
constexpr float kBvhLeafCost = 2.0f;

// stack_size: the traversal stack the tree must fit (the kernels'; tests pass less to
// reach the fallback to nodes of at most four children).
Bvh build_bvh(const BvhBuildInput& input, int stack_size = kBvhStackSize);

// Convenience: boxes of triangles given as three vertices each.
BvhBuildInput bvh_input_from_triangles(const std::vector<glm::vec3>& vertices);

} // namespace pathcl
