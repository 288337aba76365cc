// Random triangle sets for BVH tests: a soup of random triangles of mixed sizes, and a
// closed, jittered sphere (shared edges and vertices, where traversal bugs show).
#pragma once

#include <cstdint>
#include <random>
#include <vector>

#include <glm/glm.hpp>

namespace pathcl::test {

// 3 vertices per triangle.
inline std::vector<glm::vec3> random_triangle_soup(std::size_t count, std::uint32_t seed)
{
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    std::uniform_real_distribution<float> logsize(-3.0f, -0.5f);
    std::vector<glm::vec3> v;
    for (std::size_t i = 0; i < count; ++i) {
        glm::vec3 c(u(rng), u(rng), u(rng));
        float s = std::pow(10.0f, logsize(rng));
        for (int k = 0; k < 3; ++k)
            v.push_back(c + s * glm::vec3(u(rng), u(rng), u(rng)));
    }
    return v;
}

inline std::vector<glm::vec3> jittered_sphere(int stacks, int slices, std::uint32_t seed)
{
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> jitter(-0.02f, 0.02f);
    std::vector<glm::vec3> grid;
    for (int i = 0; i <= stacks; ++i)
        for (int j = 0; j < slices; ++j) {
            float theta = 3.14159265f * static_cast<float>(i) / static_cast<float>(stacks);
            float phi = 6.2831853f * static_cast<float>(j) / static_cast<float>(slices);
            float r = 1.0f + ((i == 0 || i == stacks) ? 0.0f : jitter(rng));
            grid.push_back(
                r * glm::vec3(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi)));
        }
    // Poles: one shared vertex each, so the mesh is closed.
    for (int j = 1; j < slices; ++j) {
        grid[static_cast<std::size_t>(j)] = grid[0];
        grid[static_cast<std::size_t>(stacks * slices + j)] = grid[static_cast<std::size_t>(stacks * slices)];
    }
    std::vector<glm::vec3> v;
    auto at = [&](int i, int j) { return grid[static_cast<std::size_t>(i * slices + (j % slices))]; };
    for (int i = 0; i < stacks; ++i)
        for (int j = 0; j < slices; ++j) {
            if (i != stacks - 1)
                v.insert(v.end(), {at(i, j), at(i + 1, j + 1), at(i + 1, j)});
            if (i != 0)
                v.insert(v.end(), {at(i, j), at(i, j + 1), at(i + 1, j + 1)});
        }
    return v;
}

} // namespace pathcl::test
