// KHR_draco_mesh_compression: each compressed primitive is decoded by Google's Draco
// library before the import. The decoded indices and attributes go into a new buffer,
// under new accessors of the types the file's accessors declare, and the primitive is
// pointed at them: from then on it is read like any other, with every check.
#pragma once

#include <cstddef>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

namespace tinygltf {
class Model;
}

namespace pathcl {

// tinygltf (2.7) refuses a primitive whose indices accessor has no bufferView, which is
// how a Draco primitive's indices are written. So before it parses the file, the
// "indices" of each Draco primitive is taken out of the JSON and kept here, by mesh and
// primitive index, for decode_draco_primitives.
using DracoIndices = std::map<std::pair<std::size_t, std::size_t>, int>;

// When `doc` (the file's parsed JSON, whose text is `json_size` bytes: the file, or its
// GLB's JSON chunk) has Draco primitives with indices: takes them out of `doc`, fills
// `indices` and returns the file re-written around the changed JSON (a GLB re-assembled
// around a new JSON chunk). Else returns nothing and the file is loaded as it is.
std::vector<unsigned char> detach_draco_indices(const std::vector<unsigned char>& file, bool binary,
                                                std::size_t json_size, nlohmann::json& doc, DracoIndices& indices);

// Whether any primitive of `model` carries KHR_draco_mesh_compression.
bool has_draco_primitives(const tinygltf::Model& model);

// Decodes every compressed primitive of `model` in place (and removes its extension
// object, so a second call finds nothing to do). Throws pathcl::Error naming `source`,
// the mesh and the primitive when the extension object, its buffer view or the Draco
// data is broken, or when the decoded mesh disagrees with the primitive's accessors.
// `detached`: what detach_draco_indices took out of the file; a primitive not in it uses
// its own indices.
void decode_draco_primitives(tinygltf::Model& model, const std::string& source, const DracoIndices& detached = {});

} // namespace pathcl
