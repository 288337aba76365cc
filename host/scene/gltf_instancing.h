// EXT_mesh_gpu_instancing: a node's per-instance TRANSLATION, ROTATION and SCALE
// attributes, each instance's transform applied before the node's own. The importer
// draws the node's mesh once per instance (gltf_loader.cpp: instances of a mesh stored
// once).
#pragma once

#include <cstddef>
#include <functional>
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
// type, the counts differ, or a value is not finite. `check_count` is called with the
// number of instances before their transforms are allocated (it may throw).
std::vector<glm::dmat4> instance_transforms(const tinygltf::Model& model, const tinygltf::Node& node,
                                            const glm::dmat4& node_world, bool quantized, const std::string& source,
                                            const std::string& what,
                                            const std::function<void(std::size_t)>& check_count);

} // namespace pathcl
