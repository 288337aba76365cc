/* The texture slots of a material, in the order of Material.textures and of the host's
 * slot table (host/scene/texture_slots.h), which says how the loader reads each and the
 * packer uploads it. What a slot's texel does to the material is in
 * kernels/texture/material_inputs.cl. */
#ifndef PATHCL_TEXTURE_TEXTURE_SLOTS_H
#define PATHCL_TEXTURE_TEXTURE_SLOTS_H

#define TEXTURE_SLOT_BASE_COLOR 0          /* RGB (sRGB) scales baseColorFactor */
#define TEXTURE_SLOT_METALLIC_ROUGHNESS 1  /* B scales metallicFactor, G roughnessFactor */
#define TEXTURE_SLOT_EMISSIVE 2            /* RGB (sRGB) scales the emission */
#define TEXTURE_SLOT_NORMAL 3              /* tangent-space normal, scaled by normal_scale */
#define TEXTURE_SLOT_SPECULAR 4            /* A scales specularFactor */
#define TEXTURE_SLOT_SPECULAR_COLOR 5      /* RGB (sRGB) scales specularColorFactor */
#define TEXTURE_SLOT_TRANSMISSION 6        /* R scales transmissionFactor */
#define TEXTURE_SLOT_CLEARCOAT 7           /* R scales clearcoatFactor */
#define TEXTURE_SLOT_CLEARCOAT_ROUGHNESS 8 /* G scales clearcoatRoughnessFactor */
#define TEXTURE_SLOT_CLEARCOAT_NORMAL 9    /* the coat's tangent-space normal, scaled by clearcoat_normal_scale */
#define TEXTURE_SLOT_SHEEN_COLOR 10        /* RGB (sRGB) scales sheenColorFactor */
#define TEXTURE_SLOT_SHEEN_ROUGHNESS 11    /* A scales sheenRoughnessFactor */
#define TEXTURE_SLOT_ANISOTROPY 12         /* RG direction in [-1, 1] tangent space, B scales anisotropyStrength */
#define TEXTURE_SLOT_COUNT 13

#endif
