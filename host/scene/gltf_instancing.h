// EXT_mesh_gpu_instancing: a node's per-instance TRANSLATION, ROTATION and SCALE
// attributes, each instance's transform applied before the node's own. The instances are
// imported as copies of the mesh (memory in proportion to the copies; a two-level BVH
// would keep the mesh once).
#pragma once

#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace tinygltf {
class Model;
class Node;
} // namespace tinygltf

namespace pathcl {

// The world transform of each instance of `node`'s mesh (node_world x T x R x S of the
// instance), or {node_world} when the node has no EXT_mesh_gpu_instancing. Throws
// pathcl::Error naming `source` and `what` (the node) when an attribute is of the wrong
// type, the counts differ, or a value is not finite.
std::vector<glm::dmat4> instance_transforms(const tinygltf::Model& model, const tinygltf::Node& node,
                                            const glm::dmat4& node_world, bool quantized, const std::string& source,
                                            const std::string& what);

} // namespace pathcl
