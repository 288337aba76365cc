#include "scene/gltf_specular_glossiness.h"

#include <tiny_gltf.h>

#include "common/error.h"
#include "scene/gltf_textures.h"
#include "scene/gltf_values.h"

namespace pathcl {

bool specular_glossiness_replaces(int slot)
{
    return slot == TEXTURE_SLOT_BASE_COLOR || slot == TEXTURE_SLOT_METALLIC_ROUGHNESS ||
           slot == TEXTURE_SLOT_SPECULAR || slot == TEXTURE_SLOT_SPECULAR_COLOR || slot == TEXTURE_SLOT_TRANSMISSION;
}

void import_specular_glossiness(const tinygltf::Value& sg, SceneMaterial& out, TextureImporter& textures,
                                const std::string& source, const std::string& where)
{
    const std::string at = source + ": " + where + ": KHR_materials_pbrSpecularGlossiness ";
    auto in01 = [](float v) { return v >= 0.0f && v <= 1.0f; };
    glm::vec4 diffuse = vec4_or(sg, "diffuseFactor", glm::vec4(1.0f));
    glm::vec3 specular = vec3_or(sg, "specularFactor", glm::vec3(1.0f));
    auto glossiness = static_cast<float>(number_or(sg, "glossinessFactor", 1.0));
    for (int i = 0; i < 4; ++i)
        if (!in01(diffuse[i]))
            throw Error(at + "diffuseFactor must lie in [0, 1]");
    for (int i = 0; i < 3; ++i)
        if (!in01(specular[i]))
            throw Error(at + "specularFactor must lie in [0, 1]");
    if (!in01(glossiness))
        throw Error(at + "glossinessFactor must lie in [0, 1]");

    // Whatever the metallic-roughness fallback of the file said is replaced.
    SceneMaterial defaults;
    out.base_color = glm::vec3(diffuse);
    out.alpha = diffuse.w;
    out.metallic = 0.0f;
    out.roughness = 1.0f - glossiness;
    out.glossiness = glossiness;
    out.specular = 1.0f;
    out.specular_color = specular;
    out.ior = 0.0f;
    out.transmission = defaults.transmission;
    out.thin_walled = defaults.thin_walled;
    out.absorption = defaults.absorption;
    if (sg.Has("diffuseTexture"))
        out.textures[TEXTURE_SLOT_BASE_COLOR] = textures.read(sg.Get("diffuseTexture"), where + " diffuseTexture");
    if (sg.Has("specularGlossinessTexture")) {
        // One texture, read twice: its sRGB colour tints the layer (the specular colour
        // slot), its linear alpha is glossiness (the roughness slot, MATERIAL_GLOSSINESS).
        SceneTexture t = textures.read(sg.Get("specularGlossinessTexture"), where + " specularGlossinessTexture");
        out.textures[TEXTURE_SLOT_SPECULAR_COLOR] = t;
        out.textures[TEXTURE_SLOT_METALLIC_ROUGHNESS] = t;
        out.glossiness_texture = true;
    }
}

} // namespace pathcl
