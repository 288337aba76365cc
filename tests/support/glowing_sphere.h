// A glowing UV sphere as the light tree sees it: each quad of stacks x slices split in
// two, one-sided emissive triangles wound to face outward, with what the light tree tests
// compare the tree against (each triangle's centroid, normal and area).
#pragma once

#include <cmath>
#include <numbers>
#include <vector>

#include <glm/geometric.hpp>

#include "compile/light_tree.h"

namespace pathcl::test {

// Emissive triangles as the light tree sees them (a glowing sphere's, or any).
struct GlowingSphere {
    std::vector<LightBounds> lights; // power = area
    std::vector<glm::dvec3> centroid, normal;
    std::vector<double> area;
};

// Appends the one-sided emissive triangle a, b, c (facing where it winds counter-clockwise).
inline void add_emitter(GlowingSphere& s, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c)
{
    const glm::dvec3 cr = glm::cross(b - a, c - a);
    LightBounds t;
    t.lo = glm::min(a, glm::min(b, c));
    t.hi = glm::max(a, glm::max(b, c));
    t.phi = 0.5 * glm::length(cr);
    t.cone = {glm::normalize(cr), 1.0, 0.0};
    s.lights.push_back(t);
    s.centroid.push_back((a + b + c) / 3.0);
    s.normal.push_back(t.cone.axis);
    s.area.push_back(t.phi);
}

// The sphere around `centre`, its poles on y turned by turn_z about z and then by turn_x
// about x (radians; 0 and 0 leave them on y): turned, its poles, where the triangles
// crowd, lie off the axes.
inline GlowingSphere glowing_sphere(int stacks, int slices, const glm::dvec3& centre, double radius,
                                    double turn_z = 0.0, double turn_x = 0.0)
{
    auto vertex = [&](int i, int j) {
        const double theta = std::numbers::pi * i / stacks, phi = 2.0 * std::numbers::pi * j / slices;
        glm::dvec3 v(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
        v = {v.x * std::cos(turn_z) - v.y * std::sin(turn_z), v.x * std::sin(turn_z) + v.y * std::cos(turn_z), v.z};
        v = {v.x, v.y * std::cos(turn_x) - v.z * std::sin(turn_x), v.y * std::sin(turn_x) + v.z * std::cos(turn_x)};
        return centre + radius * v;
    };
    GlowingSphere s;
    auto add = [&](const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) { add_emitter(s, a, b, c); };
    for (int i = 0; i < stacks; ++i)
        for (int j = 0; j < slices; ++j) {
            // Wound outward: counter-clockwise seen from outside.
            const glm::dvec3 a = vertex(i, j), b = vertex(i + 1, j), c = vertex(i + 1, j + 1), d = vertex(i, j + 1);
            if (i > 0)
                add(a, d, b);
            if (i < stacks - 1)
                add(b, d, c);
        }
    return s;
}

} // namespace pathcl::test
