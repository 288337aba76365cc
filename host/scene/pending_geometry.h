// The geometry of a glTF import before the render-space origin is known: triangles in
// double-precision world space with their optional attributes. The primitive import fills
// it and render_space rounds it to float relative to the origin, so a scene far from the
// world origin keeps its full float precision.
#pragma once

#include <array>
#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace pathcl {

struct PendingTriangle {
    glm::dvec3 v[3];
    glm::dvec3 n[3];
    bool has_normals = false;
    int material = 0;
};

// A drawing of an instanced mesh: the mesh's index among PendingGeometry::mesh_starts and
// its world transform.
struct PendingInstance {
    std::size_t mesh = 0;
    glm::dmat4 world{1.0};
};

struct PendingGeometry {
    // The triangles drawn once, in world space, then those of each instanced mesh in its
    // own space: mesh k's start at mesh_starts[k] (ascending; the last runs to the end).
    std::vector<PendingTriangle> triangles;
    std::vector<std::size_t> mesh_starts;
    std::vector<PendingInstance> instances;
    // Their optional attributes, in step with `triangles` (see Scene): texcoords[n] for
    // each set n some texture reads (texcoord_used[n]); tangents (world space, not yet
    // normalized) when some material has a normal texture (tangents_used); colors from
    // the first primitive with COLOR_0 on (earlier triangles get white when it arrives).
    std::vector<std::vector<TriangleUv>> texcoords;
    std::vector<bool> texcoord_used;
    bool tangents_used = false;
    std::vector<std::array<glm::dvec4, 3>> tangents;
    std::vector<TriangleColor> colors;
};

// The colour of a triangle whose primitive has no COLOR_0 while another one has.
inline const TriangleColor kWhiteTriangleColor{glm::vec4(1.0f), glm::vec4(1.0f), glm::vec4(1.0f)};

} // namespace pathcl
