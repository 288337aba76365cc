// The triangle arrays the traversal test kernels bind: a mesh's triangles in a built
// BVH's leaf order, and one TriangleBlock per triangle (its triangle in lane 0) for the
// kernels that test every triangle on its own with the traversal's own test.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "bvh/bvh_builder.h"
#include "bvh/triangle_blocks.h"

namespace pathcl::test {

// Triangles given as three vertices each, in the leaf order of `bvh` (built over them).
inline std::vector<Triangle> leaf_order_triangles(const std::vector<glm::vec3>& v, const Bvh& bvh)
{
    std::vector<Triangle> tris;
    for (std::uint32_t t : bvh.triangle_order)
        tris.push_back(Triangle{{v[3 * t].x, v[3 * t].y, v[3 * t].z, 0},
                                {v[3 * t + 1].x, v[3 * t + 1].y, v[3 * t + 1].z, 0},
                                {v[3 * t + 2].x, v[3 * t + 2].y, v[3 * t + 2].z, 0}});
    return tris;
}

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
