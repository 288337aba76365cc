// The texture slots of a material, in one table that the loader (where glTF keeps each
// slot's textureInfo), the packer (whether its texels are sRGB colour) and every loop over
// a material's textures iterate. The slot numbers are the kernels' (Material.textures,
// kernels/texture/texture_slots.h); what a texel does to the material is in
// kernels/texture/material_inputs.cl.
#pragma once

#include <array>

#include "texture/texture_slots.h"

namespace pathcl {

struct TextureSlot {
    int slot;              // TEXTURE_SLOT_*
    const char* name;      // the textureInfo's glTF name, e.g. "baseColorTexture"
    const char* extension; // the material extension holding it; nullptr: the core material
    bool srgb;             // colour texels, sRGB-encoded (decoded to linear before filtering)
};

const std::array<TextureSlot, TEXTURE_SLOT_COUNT>& texture_slot_table();

} // namespace pathcl
