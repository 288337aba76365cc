#include "scene/texture_slots.h"

namespace pathcl {

const std::array<TextureSlot, TEXTURE_SLOT_COUNT>& texture_slot_table()
{
    static const std::array<TextureSlot, TEXTURE_SLOT_COUNT> table = {{
        {TEXTURE_SLOT_BASE_COLOR, "baseColorTexture", nullptr, true},
        {TEXTURE_SLOT_METALLIC_ROUGHNESS, "metallicRoughnessTexture", nullptr, false},
        {TEXTURE_SLOT_EMISSIVE, "emissiveTexture", nullptr, true},
        {TEXTURE_SLOT_NORMAL, "normalTexture", nullptr, false},
        {TEXTURE_SLOT_SPECULAR, "specularTexture", "KHR_materials_specular", false},
        {TEXTURE_SLOT_SPECULAR_COLOR, "specularColorTexture", "KHR_materials_specular", true},
        {TEXTURE_SLOT_TRANSMISSION, "transmissionTexture", "KHR_materials_transmission", false},
        {TEXTURE_SLOT_CLEARCOAT, "clearcoatTexture", "KHR_materials_clearcoat", false},
        {TEXTURE_SLOT_CLEARCOAT_ROUGHNESS, "clearcoatRoughnessTexture", "KHR_materials_clearcoat", false},
        {TEXTURE_SLOT_CLEARCOAT_NORMAL, "clearcoatNormalTexture", "KHR_materials_clearcoat", false},
        {TEXTURE_SLOT_SHEEN_COLOR, "sheenColorTexture", "KHR_materials_sheen", true},
        {TEXTURE_SLOT_SHEEN_ROUGHNESS, "sheenRoughnessTexture", "KHR_materials_sheen", false},
        {TEXTURE_SLOT_ANISOTROPY, "anisotropyTexture", "KHR_materials_anisotropy", false},
    }};
    return table;
}

} // namespace pathcl
