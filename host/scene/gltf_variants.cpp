#include "scene/gltf_variants.h"

#include <tiny_gltf.h>

#include "common/error.h"

namespace pathcl {
namespace {

const char* const kExtension = "KHR_materials_variants";

// A JSON integer in [0, count), else -1.
int index_in(const tinygltf::Value& v, std::size_t count)
{
    if (!v.IsInt())
        return -1;
    int i = v.GetNumberAsInt();
    return i >= 0 && static_cast<std::size_t>(i) < count ? i : -1;
}

} // namespace

std::vector<std::string> material_variants(const tinygltf::Model& model, const std::string& source)
{
    std::vector<std::string> names;
    auto it = model.extensions.find(kExtension);
    if (it == model.extensions.end())
        return names;
    const tinygltf::Value& variants = it->second.Get("variants");
    if (!variants.IsArray())
        throw Error(source + ": " + kExtension + " variants must be an array");
    for (std::size_t i = 0; i < variants.ArrayLen(); ++i) {
        const tinygltf::Value& name = variants.Get(static_cast<int>(i)).Get("name");
        if (!name.IsString())
            throw Error(source + ": " + kExtension + " variant " + std::to_string(i) + " has no name string");
        names.push_back(name.Get<std::string>());
    }
    return names;
}

int variant_index(const std::vector<std::string>& names, const std::string& wanted, const std::string& source)
{
    if (wanted.empty())
        return -1;
    for (std::size_t i = 0; i < names.size(); ++i)
        if (names[i] == wanted)
            return static_cast<int>(i);
    std::string there;
    for (const std::string& n : names)
        there += (there.empty() ? "" : ", ") + (quote(n));
    throw ParameterError("variant", "there is no material variant " + quote(wanted) + ": " + source +
                                        (names.empty() ? " has none" : " has " + there));
}

int variant_material(const tinygltf::Primitive& prim, int variant, std::size_t variant_count,
                     std::size_t material_count, const std::string& where)
{
    auto it = prim.extensions.find(kExtension);
    if (it == prim.extensions.end())
        return prim.material;
    const tinygltf::Value& mappings = it->second.Get("mappings");
    if (!mappings.IsArray())
        throw Error(where + ": " + kExtension + " mappings must be an array");
    int chosen = prim.material;
    for (std::size_t k = 0; k < mappings.ArrayLen(); ++k) {
        const std::string at = where + ": " + kExtension + " mapping " + std::to_string(k);
        const tinygltf::Value& mapping = mappings.Get(static_cast<int>(k));
        int material = index_in(mapping.Get("material"), material_count);
        if (material < 0)
            throw Error(at + ": material must be the index of one of the file's " + std::to_string(material_count) +
                        " materials");
        const tinygltf::Value& variants = mapping.Get("variants");
        if (!variants.IsArray() || variants.ArrayLen() == 0)
            throw Error(at + ": variants must be a non-empty array of variant indices");
        for (std::size_t j = 0; j < variants.ArrayLen(); ++j) {
            int v = index_in(variants.Get(static_cast<int>(j)), variant_count);
            if (v < 0)
                throw Error(at + ": variants lists a variant that does not exist (the file has " +
                            std::to_string(variant_count) + ")");
            if (v == variant)
                chosen = material;
        }
    }
    return chosen;
}

} // namespace pathcl
