// Vertex tangents for normal mapping, computed from texture-coordinate derivatives when a
// primitive has no TANGENT attribute (glTF asks for MikkTSpace; this is the classic
// per-vertex accumulation, which agrees with it on well-behaved meshes but is not
// bit-identical: MikkTSpace also splits vertices at tangent-space seams and weights by
// angle).
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace pathcl {

// One tangent per triangle corner (triangle t, corner k at 3 t + k), in the space of the
// positions: xyz unit and orthogonal to the normal, pointing along increasing u (dP/du);
// w = +1 or -1 such that w cross(n, t) points along decreasing v (glTF's "+Y is up" in an
// image whose v runs down), so a mirrored UV layout gets w = -1.
// With per-vertex `normals` (one per position), dP/du and dP/dv are summed over the
// triangles sharing a vertex (area-weighted) and made orthogonal to the vertex normal
// (Gram-Schmidt); without normals (flat shading) each triangle gets its own tangent,
// orthogonal to its face normal. Where the UVs give no direction (zero UV area), any unit
// vector orthogonal to the normal, with w = +1.
std::vector<glm::dvec4> compute_tangents(const std::vector<glm::dvec3>& positions,
                                         const std::vector<glm::dvec3>& normals, const std::vector<glm::dvec2>& uvs,
                                         const std::vector<std::uint32_t>& triangles);

} // namespace pathcl
