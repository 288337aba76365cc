// The traversal's view of a tree's leaves: each leaf's triangles copied into a
// TriangleBlock (kernels/types.h), eight lanes axis by axis, and the leaf's child slot
// pointed at its block instead of its first triangle.
#pragma once

#include <cstddef>
#include <vector>

#include "types.h"

namespace pathcl {

// Rewrites the leaves of nodes[first_node..] (children with count > 0, naming
// triangles[index .. index + count - 1]) to name the blocks they append to `blocks`, in
// node and slot order. Nodes before first_node (a top-level tree, whose leaves name
// instances) are left alone.
void make_triangle_blocks(std::vector<BvhNode>& nodes, std::size_t first_node, const std::vector<Triangle>& triangles,
                          std::vector<TriangleBlock>& blocks);

} // namespace pathcl
