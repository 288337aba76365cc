// One TriangleBlock per triangle, its triangle in lane 0: for the test kernels that test
// every triangle on its own with the traversal's own test (brute-force references).
#pragma once

#include <vector>

#include "bvh/bvh_builder.h"
#include "bvh/triangle_blocks.h"

namespace pathcl::test {

inline std::vector<TriangleBlock> single_triangle_blocks(const std::vector<Triangle>& triangles)
{
    // A stand-in tree whose every leaf is one triangle: block k then holds triangle k.
    std::vector<BvhNode> one_each((triangles.size() + kBvhWidth - 1) / kBvhWidth);
    for (std::size_t t = 0; t < one_each.size() * kBvhWidth; ++t) {
        const bool used = t < triangles.size();
        one_each[t / kBvhWidth].index.s[t % kBvhWidth] = used ? static_cast<std::int32_t>(t) : -1;
        one_each[t / kBvhWidth].count.s[t % kBvhWidth] = used ? 1 : 0;
    }
    std::vector<TriangleBlock> blocks;
    make_triangle_blocks(one_each, 0, triangles, blocks);
    return blocks;
}

} // namespace pathcl::test
