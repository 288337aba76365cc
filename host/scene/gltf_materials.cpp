// import_materials: the core material (alpha included), its extensions (emissive
// strength, specular, transmission, clearcoat, sheen, anisotropy, ior (0 included), volume with attenuation,
// unlit; a
// pbrSpecularGlossiness material replaces the metallic-roughness part), the texture of
// each slot, then the range check.
#include "scene/gltf_materials.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <tiny_gltf.h>

#include "common/error.h"
#include "scene/gltf_specular_glossiness.h"
#include "scene/gltf_textures.h"
#include "scene/gltf_values.h"
#include "scene/texture_slots.h"

namespace pathcl {
namespace {

// The ranges glTF and the KHR material extensions allow; anything else is an error that
// names the material and the field, rather than NaN or negative energy in the kernels.
void check_material(const SceneMaterial& m, const std::string& where)
{
    auto in01 = [](float v) { return v >= 0.0f && v <= 1.0f; };
    auto fail = [&](const char* what) { throw Error(where + ": " + what); };
    for (int i = 0; i < 3; ++i) {
        if (!in01(m.base_color[i]) || !in01(m.alpha))
            fail("baseColorFactor must lie in [0, 1]");
        if (!(m.emission[i] >= 0.0f) || !std::isfinite(m.emission[i]))
            fail("emission (emissiveFactor x emissiveStrength) must be finite and >= 0");
        if (!(m.specular_color[i] >= 0.0f) || !std::isfinite(m.specular_color[i]))
            fail("KHR_materials_specular specularColorFactor must be finite and >= 0");
        if (!in01(m.sheen_color[i]))
            fail("KHR_materials_sheen sheenColorFactor must lie in [0, 1]");
    }
    if (!in01(m.metallic))
        fail("metallicFactor must lie in [0, 1]");
    if (!in01(m.roughness))
        fail("roughnessFactor must lie in [0, 1]");
    if (!in01(m.specular))
        fail("KHR_materials_specular specularFactor must lie in [0, 1]");
    if (!in01(m.transmission))
        fail("KHR_materials_transmission transmissionFactor must lie in [0, 1]");
    if (!in01(m.clearcoat))
        fail("KHR_materials_clearcoat clearcoatFactor must lie in [0, 1]");
    if (!in01(m.clearcoat_roughness))
        fail("KHR_materials_clearcoat clearcoatRoughnessFactor must lie in [0, 1]");
    if (!in01(m.sheen_roughness))
        fail("KHR_materials_sheen sheenRoughnessFactor must lie in [0, 1]");
    if (!in01(m.anisotropy))
        fail("KHR_materials_anisotropy anisotropyStrength must lie in [0, 1]");
    if (!std::isfinite(m.anisotropy_rotation))
        fail("KHR_materials_anisotropy anisotropyRotation must be finite");
    if (!(m.ior >= 1.0f || m.ior == 0.0f) || !std::isfinite(m.ior))
        fail("KHR_materials_ior ior must be finite and >= 1, or 0");
    if (!(m.alpha_cutoff >= 0.0f) || !std::isfinite(m.alpha_cutoff))
        fail("alphaCutoff must be finite and >= 0");
}

// The KHR_texture_transform object of a textureInfo's extensions, or null.
const tinygltf::Value* texture_transform(const tinygltf::ExtensionMap& extensions)
{
    auto it = extensions.find("KHR_texture_transform");
    return it == extensions.end() ? nullptr : &it->second;
}

// Where the core material keeps the textureInfo of a slot (tinygltf gives each its own
// member; the normal texture's type differs, so the three fields it shares are taken).
struct CoreTextureInfo {
    int index, texcoord;
    const tinygltf::ExtensionMap* extensions;
};

CoreTextureInfo core_texture_info(const tinygltf::Material& m, int slot)
{
    switch (slot) {
    case TEXTURE_SLOT_BASE_COLOR:
        return {m.pbrMetallicRoughness.baseColorTexture.index, m.pbrMetallicRoughness.baseColorTexture.texCoord,
                &m.pbrMetallicRoughness.baseColorTexture.extensions};
    case TEXTURE_SLOT_METALLIC_ROUGHNESS:
        return {m.pbrMetallicRoughness.metallicRoughnessTexture.index,
                m.pbrMetallicRoughness.metallicRoughnessTexture.texCoord,
                &m.pbrMetallicRoughness.metallicRoughnessTexture.extensions};
    case TEXTURE_SLOT_EMISSIVE:
        return {m.emissiveTexture.index, m.emissiveTexture.texCoord, &m.emissiveTexture.extensions};
    case TEXTURE_SLOT_NORMAL:
        return {m.normalTexture.index, m.normalTexture.texCoord, &m.normalTexture.extensions};
    default:
        return {-1, 0, nullptr};
    }
}

SceneMaterial import_material(const tinygltf::Material& m, TextureImporter& textures, const std::string& source,
                              const std::string& where)
{
    SceneMaterial out;
    out.name = m.name;
    const auto& pbr = m.pbrMetallicRoughness;
    if (pbr.baseColorFactor.size() >= 3)
        out.base_color = glm::vec3(glm::dvec3(pbr.baseColorFactor[0], pbr.baseColorFactor[1], pbr.baseColorFactor[2]));
    if (pbr.baseColorFactor.size() == 4)
        out.alpha = static_cast<float>(pbr.baseColorFactor[3]);
    if (m.alphaMode == "MASK")
        out.alpha_mode = AlphaMode::Mask;
    else if (m.alphaMode == "BLEND")
        out.alpha_mode = AlphaMode::Blend;
    else if (m.alphaMode != "OPAQUE")
        throw Error(source + ": " + where + ": alphaMode must be OPAQUE, MASK or BLEND, not " + quote(m.alphaMode));
    out.alpha_cutoff = static_cast<float>(m.alphaCutoff);
    out.metallic = static_cast<float>(pbr.metallicFactor);
    out.roughness = static_cast<float>(pbr.roughnessFactor);
    double strength = 1.0;
    auto it = m.extensions.find("KHR_materials_emissive_strength");
    if (it != m.extensions.end())
        strength = number_or(it->second, "emissiveStrength", 1.0);
    if (m.emissiveFactor.size() == 3)
        out.emission = glm::vec3(glm::dvec3(m.emissiveFactor[0], m.emissiveFactor[1], m.emissiveFactor[2]) * strength);
    out.double_sided = m.doubleSided;
    if (auto e = m.extensions.find("KHR_materials_specular"); e != m.extensions.end()) {
        out.specular = static_cast<float>(number_or(e->second, "specularFactor", 1.0));
        out.specular_color = vec3_or(e->second, "specularColorFactor", glm::vec3(1.0f));
    }
    if (auto e = m.extensions.find("KHR_materials_transmission"); e != m.extensions.end()) {
        out.transmission = static_cast<float>(number_or(e->second, "transmissionFactor", 0.0));
    }
    if (auto e = m.extensions.find("KHR_materials_clearcoat"); e != m.extensions.end()) {
        out.clearcoat = static_cast<float>(number_or(e->second, "clearcoatFactor", 0.0));
        out.clearcoat_roughness = static_cast<float>(number_or(e->second, "clearcoatRoughnessFactor", 0.0));
        if (e->second.Has("clearcoatNormalTexture")) {
            out.clearcoat_normal_scale =
                static_cast<float>(number_or(e->second.Get("clearcoatNormalTexture"), "scale", 1.0));
            if (!std::isfinite(out.clearcoat_normal_scale))
                throw Error(source + ": " + where +
                            ": KHR_materials_clearcoat clearcoatNormalTexture scale must be finite");
        }
    }
    if (auto e = m.extensions.find("KHR_materials_sheen"); e != m.extensions.end()) {
        out.sheen_color = vec3_or(e->second, "sheenColorFactor", glm::vec3(0.0f));
        out.sheen_roughness = static_cast<float>(number_or(e->second, "sheenRoughnessFactor", 0.0));
    }
    if (auto e = m.extensions.find("KHR_materials_anisotropy"); e != m.extensions.end()) {
        out.anisotropy = static_cast<float>(number_or(e->second, "anisotropyStrength", 0.0));
        out.anisotropy_rotation = static_cast<float>(number_or(e->second, "anisotropyRotation", 0.0));
    }
    if (auto e = m.extensions.find("KHR_materials_ior"); e != m.extensions.end())
        out.ior = static_cast<float>(number_or(e->second, "ior", 1.5));
    const auto sg = m.extensions.find("KHR_materials_pbrSpecularGlossiness");
    const bool spec_gloss = sg != m.extensions.end();
    if (auto e = m.extensions.find("KHR_materials_volume"); e != m.extensions.end()) {
        double thickness = number_or(e->second, "thicknessFactor", 0.0);
        if (!(thickness >= 0.0) || !std::isfinite(thickness))
            throw Error(source + ": " + where + ": KHR_materials_volume thicknessFactor must be finite and >= 0");
        out.thin_walled = thickness == 0.0;
        // Beer-Lambert inside the solid: attenuationColor is what is left after
        // attenuationDistance (default infinity: clear).
        double distance = number_or(e->second, "attenuationDistance", std::numeric_limits<double>::infinity());
        if (!(distance > 0.0))
            throw Error(source + ": " + where + ": KHR_materials_volume attenuationDistance must be > 0");
        glm::dvec3 color(vec3_or(e->second, "attenuationColor", glm::vec3(1.0f)));
        for (int c = 0; c < 3; ++c) {
            if (!(color[c] >= 0.0 && color[c] <= 1.0))
                throw Error(source + ": " + where + ": KHR_materials_volume attenuationColor must lie in [0, 1]");
            double sigma = std::isinf(distance) ? 0.0 : color[c] == 0.0 ? HUGE_VAL : -std::log(color[c]) / distance;
            out.absorption[c] =
                static_cast<float>(std::min(sigma, static_cast<double>(std::numeric_limits<float>::max())));
        }
    }

    // The texture of every slot (occlusionTexture is not read: a path tracer computes
    // occlusion).
    for (const TextureSlot& ts : texture_slot_table()) {
        if (spec_gloss && specular_glossiness_replaces(ts.slot))
            continue; // the metallic-roughness fallback of a specular-glossiness material
        const std::string slot_where = where + " " + ts.name;
        if (ts.extension) {
            auto e = m.extensions.find(ts.extension);
            if (e != m.extensions.end() && e->second.Has(ts.name))
                out.textures[static_cast<std::size_t>(ts.slot)] = textures.read(e->second.Get(ts.name), slot_where);
            continue;
        }
        CoreTextureInfo info = core_texture_info(m, ts.slot);
        if (info.index >= 0)
            out.textures[static_cast<std::size_t>(ts.slot)] =
                textures.read(info.index, info.texcoord, texture_transform(*info.extensions), slot_where);
    }
    // One tangent frame per triangle follows the first of normalTexture, clearcoatNormalTexture
    // and anisotropyTexture (tangent_texcoord); a later one on another set is approximate.
    const SceneTexture* frame = nullptr;
    const char* frame_name = nullptr;
    for (const TextureSlot& ts : texture_slot_table()) {
        if (ts.slot != TEXTURE_SLOT_NORMAL && ts.slot != TEXTURE_SLOT_CLEARCOAT_NORMAL &&
            ts.slot != TEXTURE_SLOT_ANISOTROPY)
            continue;
        const SceneTexture& t = out.textures[static_cast<std::size_t>(ts.slot)];
        if (!t.present())
            continue;
        if (!frame) {
            frame = &t;
            frame_name = ts.name;
        } else if (t.texcoord != frame->texcoord) {
            warn(source + ": " + where + ": " + ts.name + " reads TEXCOORD_" + std::to_string(t.texcoord) +
                 " but the tangents follow " + frame_name + "'s TEXCOORD_" + std::to_string(frame->texcoord) +
                 " (one tangent frame per triangle): " +
                 (ts.slot == TEXTURE_SLOT_ANISOTROPY ? "the anisotropy direction" : "the coat's normal map") +
                 " is approximate");
        }
    }
    if (m.normalTexture.index >= 0) {
        out.normal_scale = static_cast<float>(m.normalTexture.scale);
        if (!std::isfinite(out.normal_scale))
            throw Error(source + ": " + where + ": normalTexture scale must be finite");
    }
    if (spec_gloss)
        import_specular_glossiness(sg->second, out, textures, source, where);
    out.unlit = m.extensions.count("KHR_materials_unlit") != 0;
    if (out.unlit)
        out.emission = glm::vec3(0.0f); // unlit: the base colour is all it shows, and it is no light
    if (out.ior == 0.0f && out.transmission > 0.0f) {
        // ior 0 makes the interface's Fresnel term 1: no light enters the solid.
        warn(source + ": " + where +
             ": KHR_materials_ior ior 0 (specular-glossiness mode) transmits no light; "
             "its transmission is not rendered");
        out.transmission = 0.0f;
        out.textures[TEXTURE_SLOT_TRANSMISSION] = SceneTexture{};
    }
    if (out.anisotropy > 0.0f && out.transmission > 0.0f && !out.thin_walled)
        warn(source + ": " + where +
             ": KHR_materials_anisotropy on a transmitting solid is approximate: its interface keeps the "
             "isotropic roughness");
    return out;
}

} // namespace

std::vector<SceneMaterial> import_materials(const tinygltf::Model& model, TextureImporter& textures,
                                            const std::string& source)
{
    std::vector<SceneMaterial> materials;
    for (std::size_t i = 0; i < model.materials.size(); ++i) {
        std::string where = "material " + std::to_string(i) + " (" + model.materials[i].name + ")";
        materials.push_back(import_material(model.materials[i], textures, source, where));
        check_material(materials.back(), source + ": " + where);
    }
    return materials;
}

} // namespace pathcl
