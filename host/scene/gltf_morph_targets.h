// Morph targets at the default weights (glTF 2.0 3.7.2.2): a primitive's POSITION,
// NORMAL and TANGENT are its own plus the weighted sum of its targets' displacements,
// with the node's weights, else the mesh's, else zero. pathcl renders one frame, so the
// default weights are all it needs; animations are not read.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace tinygltf {
class Model;
struct Primitive;
} // namespace tinygltf

namespace pathcl {

// Summed displacements per vertex of one primitive: empty where no target moves that
// attribute (or every weight is 0).
struct MorphDeltas {
    std::vector<glm::dvec3> position, normal, tangent;
    std::size_t ignored_attributes = 0; // targets of other attributes (TEXCOORD_n, COLOR_n), not applied
};

// The displacements of `prim`'s targets under `weights` (node.weights, else mesh.weights),
// for `vertex_count` vertices. Throws pathcl::Error("SOURCE: WHAT ...") when the weights
// do not match the targets or a target accessor is not one finite VEC3 per vertex.
// `quantized`: KHR_mesh_quantization allows integer displacements.
MorphDeltas morph_deltas(const tinygltf::Model& model, const tinygltf::Primitive& prim,
                         const std::vector<double>& weights, std::size_t vertex_count, bool quantized,
                         const std::string& source, const std::string& what);

} // namespace pathcl
