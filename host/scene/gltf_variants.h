// KHR_materials_variants: a file's named material variants (a product in several
// colours, say), and the material each primitive takes in the one chosen. The default
// (no variant chosen) is each primitive's own material, as the extension specifies.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace tinygltf {
class Model;
struct Primitive;
} // namespace tinygltf

namespace pathcl {

// The variant names, in the file's order (empty without the extension). Throws
// pathcl::Error("SOURCE: KHR_materials_variants ...") for a malformed list.
std::vector<std::string> material_variants(const tinygltf::Model& model, const std::string& source);

// The index of variant `wanted` among `names`; -1 for "" (the default). Throws
// ParameterError("variant", ...) naming the variants there are when it is not one of them.
int variant_index(const std::vector<std::string>& names, const std::string& wanted, const std::string& source);

// The glTF material index `prim` takes in variant `variant` (-1: the default): the
// material of the mapping that lists the variant, else prim.material. Every mapping is
// checked whatever the choice: `where` ("SOURCE: node 2 ... primitive 1") names the
// primitive in the error for a malformed mapping or an index that does not exist.
int variant_material(const tinygltf::Primitive& prim, int variant, std::size_t variant_count,
                     std::size_t material_count, const std::string& where);

} // namespace pathcl
