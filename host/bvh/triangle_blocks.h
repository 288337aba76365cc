// The traversal's view of a tree's leaves: each leaf's triangles copied into a
// TriangleBlock (kernels/types.h), eight lanes axis by axis, and the leaf's child slot
// pointed at its block instead of its first triangle.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "types.h"

namespace pathcl {

// Rewrites the leaves of nodes[first_node..] (children with count > 0, naming
// triangles[index .. index + count - 1]) to name the blocks they append to `blocks`, in
// node and slot order. Nodes before first_node (a top-level tree, whose leaves name
// instances) are left alone.
void make_triangle_blocks(std::vector<BvhNode>& nodes, std::size_t first_node, const std::vector<Triangle>& triangles,
                          std::vector<TriangleBlock>& blocks);

// Where a stored triangle's leaf is, once make_triangle_blocks has run: the node whose slot
// names the leaf, and the leaf's block. The shadow ray towards a point on an emissive
// triangle ends in that leaf, which the megakernel starts into the cache before it traces
// (Light.leaf_node, Light.leaf_block).
struct TriangleLeaf {
    std::int32_t node = -1, block = -1;
};

// By stored triangle (triangles[0 .. triangle_count)): the leaves that nodes[first_node..]
// name in `blocks`. Throws std::logic_error if a triangle is in no leaf or in two.
std::vector<TriangleLeaf> triangle_leaves(const std::vector<BvhNode>& nodes, std::size_t first_node,
                                          const std::vector<TriangleBlock>& blocks, std::size_t triangle_count);

} // namespace pathcl
