#include "bvh/triangle_blocks.h"

#include <limits>
#include <stdexcept>
#include <string>

#include "bvh/bvh_builder.h"

namespace pathcl {

void make_triangle_blocks(std::vector<BvhNode>& nodes, std::size_t first_node, const std::vector<Triangle>& triangles,
                          std::vector<TriangleBlock>& blocks)
{
    const float nan = std::numeric_limits<float>::quiet_NaN();
    for (std::size_t n = first_node; n < nodes.size(); ++n)
        for (int k = 0; k < kBvhWidth; ++k) {
            const std::int32_t count = nodes[n].count.s[k], first = nodes[n].index.s[k];
            if (count <= 0)
                continue;
            if (count > kBvhMaxLeafSize || first < 0 || static_cast<std::size_t>(first) + count > triangles.size())
                throw std::logic_error("make_triangle_blocks: leaf " + std::to_string(first) + "+" +
                                       std::to_string(count) + " is not a leaf of up to eight stored triangles");
            TriangleBlock b;
            for (pcl_float8& row : b.vertex)
                for (float& x : row.s)
                    x = nan;
            for (std::int32_t& t : b.triangle.s)
                t = -1;
            for (std::int32_t j = 0; j < count; ++j) {
                const Triangle& t = triangles[static_cast<std::size_t>(first + j)];
                const pcl_float4* v[3] = {&t.v0, &t.v1, &t.v2};
                for (int i = 0; i < 3; ++i) {
                    b.vertex[3 * i + 0].s[j] = v[i]->x;
                    b.vertex[3 * i + 1].s[j] = v[i]->y;
                    b.vertex[3 * i + 2].s[j] = v[i]->z;
                }
                b.triangle.s[j] = first + j;
            }
            if (blocks.size() >= static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max()))
                throw std::length_error("make_triangle_blocks: more leaves than a BvhNode can index");
            nodes[n].index.s[k] = static_cast<std::int32_t>(blocks.size());
            blocks.push_back(b);
        }
}

std::vector<TriangleLeaf> triangle_leaves(const std::vector<BvhNode>& nodes, std::size_t first_node,
                                          const std::vector<TriangleBlock>& blocks, std::size_t triangle_count)
{
    std::vector<TriangleLeaf> leaves(triangle_count);
    std::size_t found = 0;
    for (std::size_t n = first_node; n < nodes.size(); ++n)
        for (int k = 0; k < kBvhWidth; ++k) {
            const std::int32_t block = nodes[n].index.s[k];
            if (nodes[n].count.s[k] <= 0)
                continue;
            if (block < 0 || static_cast<std::size_t>(block) >= blocks.size())
                throw std::logic_error("triangle_leaves: node " + std::to_string(n) + " names block " +
                                       std::to_string(block) + " of " + std::to_string(blocks.size()));
            for (const std::int32_t t : blocks[static_cast<std::size_t>(block)].triangle.s) {
                if (t < 0)
                    continue;
                if (static_cast<std::size_t>(t) >= triangle_count || leaves[static_cast<std::size_t>(t)].block >= 0)
                    throw std::logic_error("triangle_leaves: triangle " + std::to_string(t) +
                                           " is past the triangles or in two leaves");
                leaves[static_cast<std::size_t>(t)] = {static_cast<std::int32_t>(n), block};
                ++found;
            }
        }
    if (found != triangle_count)
        throw std::logic_error("triangle_leaves: " + std::to_string(triangle_count - found) + " of " +
                               std::to_string(triangle_count) + " triangles are in no leaf");
    return leaves;
}

} // namespace pathcl
