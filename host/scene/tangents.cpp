#include "scene/tangents.h"

#include <cmath>

namespace pathcl {
namespace {

struct Derivatives {
    glm::dvec3 dp_du{0.0}, dp_dv{0.0};
};

// dP/du and dP/dv of one triangle, times its area (zero where its UVs have no area).
Derivatives triangle_derivatives(const glm::dvec3 p[3], const glm::dvec2 uv[3])
{
    glm::dvec3 e1 = p[1] - p[0], e2 = p[2] - p[0];
    glm::dvec2 d1 = uv[1] - uv[0], d2 = uv[2] - uv[0];
    double det = d1.x * d2.y - d2.x * d1.y;
    Derivatives d;
    if (!(std::fabs(det) > 1e-300) || !std::isfinite(det))
        return d;
    double area = 0.5 * glm::length(glm::cross(e1, e2));
    d.dp_du = (e1 * d2.y - e2 * d1.y) * (area / det);
    d.dp_dv = (e2 * d1.x - e1 * d2.x) * (area / det);
    return d;
}

// Any unit vector orthogonal to unit n (Duff et al. 2017).
glm::dvec3 orthogonal(const glm::dvec3& n)
{
    double sign = std::copysign(1.0, n.z);
    double a = -1.0 / (sign + n.z);
    double b = n.x * n.y * a;
    return glm::dvec3(1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x);
}

glm::dvec4 tangent_frame(const glm::dvec3& n, const Derivatives& d)
{
    glm::dvec3 t = d.dp_du - n * glm::dot(n, d.dp_du);
    double len = glm::length(t);
    if (!(len > 1e-12 * glm::length(d.dp_du)) || !(len > 0.0) || !std::isfinite(len))
        return glm::dvec4(orthogonal(n), 1.0);
    t /= len;
    // The bitangent w cross(n, t) must point up the image, along -dP/dv.
    double w = glm::dot(glm::cross(n, t), d.dp_dv) > 0.0 ? -1.0 : 1.0;
    return glm::dvec4(t, w);
}

glm::dvec3 unit_or(const glm::dvec3& v, const glm::dvec3& fallback)
{
    double len = glm::length(v);
    return (len > 0.0 && std::isfinite(len)) ? v / len : fallback;
}

} // namespace

std::vector<glm::dvec4> compute_tangents(const std::vector<glm::dvec3>& positions,
                                         const std::vector<glm::dvec3>& normals, const std::vector<glm::dvec2>& uvs,
                                         const std::vector<std::uint32_t>& triangles)
{
    std::size_t count = triangles.size() / 3;
    std::vector<glm::dvec4> out(count * 3);
    std::vector<Derivatives> per_triangle(count);
    std::vector<glm::dvec3> face_normal(count);
    for (std::size_t t = 0; t < count; ++t) {
        glm::dvec3 p[3];
        glm::dvec2 uv[3];
        for (int k = 0; k < 3; ++k) {
            p[k] = positions[triangles[3 * t + k]];
            uv[k] = uvs[triangles[3 * t + k]];
        }
        per_triangle[t] = triangle_derivatives(p, uv);
        face_normal[t] = unit_or(glm::cross(p[1] - p[0], p[2] - p[0]), glm::dvec3(0.0, 0.0, 1.0));
    }
    if (normals.empty()) { // flat shading: one frame per face
        for (std::size_t t = 0; t < count; ++t)
            out[3 * t] = out[3 * t + 1] = out[3 * t + 2] = tangent_frame(face_normal[t], per_triangle[t]);
        return out;
    }
    std::vector<Derivatives> per_vertex(positions.size());
    std::vector<glm::dvec3> face_sum(positions.size(), glm::dvec3(0.0));
    for (std::size_t t = 0; t < count; ++t)
        for (int k = 0; k < 3; ++k) {
            Derivatives& v = per_vertex[triangles[3 * t + k]];
            v.dp_du += per_triangle[t].dp_du;
            v.dp_dv += per_triangle[t].dp_dv;
            face_sum[triangles[3 * t + k]] += face_normal[t];
        }
    std::vector<glm::dvec4> vertex_frame(positions.size());
    std::vector<bool> done(positions.size(), false);
    for (std::size_t t = 0; t < count; ++t)
        for (int k = 0; k < 3; ++k) {
            std::uint32_t v = triangles[3 * t + k];
            if (!done[v]) {
                glm::dvec3 n = unit_or(normals[v], unit_or(face_sum[v], face_normal[t]));
                vertex_frame[v] = tangent_frame(n, per_vertex[v]);
                done[v] = true;
            }
            out[3 * t + k] = vertex_frame[v];
        }
    return out;
}

} // namespace pathcl
