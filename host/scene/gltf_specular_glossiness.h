// KHR_materials_pbrSpecularGlossiness (archived, still written by older exporters), read
// as the metallic-roughness material in KHR_materials_ior's specular-glossiness mode:
// metallic 0, base colour = diffuse, KHR_materials_specular colour = the specular colour,
// ior 0 (the dielectric layer's Fresnel curve is Schlick's from that colour at normal
// incidence to 1 at grazing, as the old extension's was), roughness = 1 - glossiness. An
// approximation: the old model scaled the diffuse by 1 - max(specular); this one gives
// the diffuse base what the layer does not reflect (albedo scaling, closure/bsdf.cl).
#pragma once

#include <string>

#include "scene/scene.h"

namespace tinygltf {
class Value;
}

namespace pathcl {

class TextureImporter;

// Whether the extension replaces the metallic-roughness texture of `slot` (its own
// textures or none take that slot's place): the material importer reads no texture into
// such a slot (nor decodes the fallback's images).
bool specular_glossiness_replaces(int slot);

// Sets `out`'s metallic-roughness factors, and the replaced slots it has textures for,
// from the extension object `sg`. Throws pathcl::Error("SOURCE: material N (name): ...") for a factor
// outside its range.
void import_specular_glossiness(const tinygltf::Value& sg, SceneMaterial& out, TextureImporter& textures,
                                const std::string& source, const std::string& where);

} // namespace pathcl
