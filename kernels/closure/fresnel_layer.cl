/* The material's Fresnel terms: Schlick's for the conductor (as glTF defines it), the
 * KHR_materials_specular dielectric layer (the exact normalized Fresnel curve, scaled and
 * tinted), and the share of light the layer passes to the transmission lobe. */
#include "closure/bsdf_params.cl"
#include "closure/fresnel.h"
#include "features.h"
#include "util/math.cl"

#ifdef PATHCL_FULL_BSDF

/* Schlick's approximation, as glTF defines the conductor Fresnel term. */
static inline float3 fresnel_schlick(float3 f0, float cos_i)
{
    return f0 + (1.0f - f0) * schlick_weight(cos_i);
}

/* The dielectric layer's reflectance F_d (see the header comment). */
static inline float3 fresnel_specular_layer(const BsdfParams* p, float cos_i)
{
#ifdef PATHCL_HAS_SCHLICK_LAYER
    float s = layer_curve(cos_i, p->eta); /* eta 0: ior 0's Schlick curve */
#else
    float s = normalized_fresnel(cos_i, p->eta);
#endif
    return p->specular * (p->f0c + (1.0f - p->f0c) * s);
}

/* Reflectance of the dielectric layer's share of the specular reflection lobe. The
 * transmissive share of the layer is the rough interface, whose energy is restored by
 * glass_scale (1 when smooth, or when there is none). */
static inline float3 fresnel_layer_reflection(const BsdfParams* p, float3 f_layer)
{
    float layer_scale = (1.0f - p->transmission) + p->transmission * p->glass_scale;
    return (1.0f - p->metallic) * layer_scale * f_layer;
}

/* Reflectance of the specular reflection lobe: conductor and dielectric layer mixed. */
static inline float3 fresnel_reflection(const BsdfParams* p, float cos_i, float3 f_layer)
{
    return p->metallic * fresnel_schlick(p->base_color, cos_i) + fresnel_layer_reflection(p, f_layer);
}

/* What the dielectric layer lets through to the transmission lobe. */
static inline float base_weight(const BsdfParams* p, float3 f_layer)
{
    return (1.0f - p->metallic) * (1.0f - max3(f_layer));
}

#endif /* PATHCL_FULL_BSDF */
