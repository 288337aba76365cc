// Binned SAH BVH over triangles, flattened to the two-wide BvhNode array the kernels
// traverse with a fixed stack (kernels/bvh.cl). Node 0 is the root and is always an inner
// node; leaves live inside their parent as (first triangle, count).
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "shared_types.h"

namespace pathcl {

struct BvhBuildInput {
    std::vector<glm::vec3> box_min, box_max; // per triangle
};

struct Bvh {
    std::vector<BvhNode> nodes;
    // Leaf order: triangle_order[i] is the input triangle stored at position i.
    std::vector<std::uint32_t> triangle_order;
    int depth = 0;       // longest root-to-leaf path, in nodes
    int leaf_count = 0;
    int max_leaf_size = 0;
};

// Depth never exceeds the kernels' traversal stack (BVH_STACK_SIZE in bvh.cl).
constexpr int kBvhMaxDepth = 60;
constexpr int kBvhMaxLeafSize = 8;

Bvh build_bvh(const BvhBuildInput& input);

// Convenience: boxes of triangles given as three vertices each.
BvhBuildInput bvh_input_from_triangles(const std::vector<glm::vec3>& vertices);

} // namespace pathcl
