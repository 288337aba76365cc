/* A material's per-hit inputs: its textures, the vertex colour and the normal map,
 * applied once per shading point to a private copy of its Material. Each texture value
 * multiplies its factor as glTF defines, COLOR_0 multiplies the base colour, and a normal
 * texture replaces the shading normal. The BSDF and the emission code then read the copy,
 * so they need no texture code of their own; triangle lights read their emissive texture
 * at the sampled point through the same texture_at, so a light sample and a ray that hits
 * the same point see the same radiance. Scenes without textures or vertex colours compile
 * none of this (PATHCL_HAS_MATERIAL_INPUTS). */
#include "bvh/traversal.cl"
#include "features.h"
#include "geom/surface_point.cl"
#include "geom/tangent_frame.cl"
#include "kernel_data.cl"
#include "texture/lookup.cl"
#include "texture/normal_map.cl"

#ifdef PATHCL_HAS_MATERIAL_INPUTS

/* Applies the material's textures, the vertex colour and the normal map at a hit: `m` is
 * the hit triangle's material (a private copy), `sp` its surface point, wo the direction
 * back along the ray. */
static inline void apply_material_inputs(Material* m, SurfacePoint* sp, float3 wo, Hit hit, const KernelData* kd)
{
#ifdef PATHCL_HAS_VERTEX_COLORS
    {
        TriangleColors c = kd->colors[hit.triangle];
        float b0 = 1.0f - hit.b1 - hit.b2;
        m->base_color.xyz *= b0 * c.c0.xyz + hit.b1 * c.c1.xyz + hit.b2 * c.c2.xyz;
    }
#endif
#ifdef PATHCL_HAS_TEXTURES
    int tri = hit.triangle;
    if (m->textures[TEXTURE_SLOT_BASE_COLOR] != TEXTURE_NONE)
        m->base_color.xyz *= texture_at(kd, m->textures[TEXTURE_SLOT_BASE_COLOR], tri, hit.b1, hit.b2).xyz;
    if (m->textures[TEXTURE_SLOT_METALLIC_ROUGHNESS] != TEXTURE_NONE) {
        float4 mr = texture_at(kd, m->textures[TEXTURE_SLOT_METALLIC_ROUGHNESS], tri, hit.b1, hit.b2);
        if (m->flags & MATERIAL_GLOSSINESS) {
            m->roughness = 1.0f - m->roughness * mr.w;
        } else {
            m->roughness *= mr.y;
            m->metallic *= mr.z;
        }
    }
    if (m->textures[TEXTURE_SLOT_EMISSIVE] != TEXTURE_NONE)
        m->emission.xyz *= texture_at(kd, m->textures[TEXTURE_SLOT_EMISSIVE], tri, hit.b1, hit.b2).xyz;
    if (m->textures[TEXTURE_SLOT_SPECULAR] != TEXTURE_NONE)
        m->specular_color.w *= texture_at(kd, m->textures[TEXTURE_SLOT_SPECULAR], tri, hit.b1, hit.b2).w;
    if (m->textures[TEXTURE_SLOT_SPECULAR_COLOR] != TEXTURE_NONE)
        m->specular_color.xyz *= texture_at(kd, m->textures[TEXTURE_SLOT_SPECULAR_COLOR], tri, hit.b1, hit.b2).xyz;
    if (m->textures[TEXTURE_SLOT_TRANSMISSION] != TEXTURE_NONE)
        m->transmission *= texture_at(kd, m->textures[TEXTURE_SLOT_TRANSMISSION], tri, hit.b1, hit.b2).x;
#ifdef PATHCL_HAS_CLEARCOAT
    if (m->textures[TEXTURE_SLOT_CLEARCOAT] != TEXTURE_NONE)
        m->clearcoat *= texture_at(kd, m->textures[TEXTURE_SLOT_CLEARCOAT], tri, hit.b1, hit.b2).x;
    if (m->textures[TEXTURE_SLOT_CLEARCOAT_ROUGHNESS] != TEXTURE_NONE)
        m->clearcoat_roughness *= texture_at(kd, m->textures[TEXTURE_SLOT_CLEARCOAT_ROUGHNESS], tri, hit.b1, hit.b2).y;
#endif
#ifdef PATHCL_HAS_SHEEN
    if (m->textures[TEXTURE_SLOT_SHEEN_COLOR] != TEXTURE_NONE)
        m->sheen.xyz *= texture_at(kd, m->textures[TEXTURE_SLOT_SHEEN_COLOR], tri, hit.b1, hit.b2).xyz;
    if (m->textures[TEXTURE_SLOT_SHEEN_ROUGHNESS] != TEXTURE_NONE)
        m->sheen.w *= texture_at(kd, m->textures[TEXTURE_SLOT_SHEEN_ROUGHNESS], tri, hit.b1, hit.b2).w;
#endif
#ifdef PATHCL_HAS_NORMAL_MAPS
    /* The tangent frame belongs to the front (counter-clockwise) side; map there, then turn
     * the result to wo's side like the interpolated normal. */
    float side = sp->front_face ? 1.0f : -1.0f;
#ifdef PATHCL_HAS_CLEARCOAT
    /* The coat's own normal map bends the interpolated normal (sp->n_coat), not the base's
     * mapped one. */
    if (m->textures[TEXTURE_SLOT_CLEARCOAT_NORMAL] != TEXTURE_NONE) {
        float3 texel = texture_at(kd, m->textures[TEXTURE_SLOT_CLEARCOAT_NORMAL], tri, hit.b1, hit.b2).xyz;
        float3 mapped =
            normal_from_map(side * sp->n_coat, hit_tangents(kd, hit), hit.b1, hit.b2, texel, m->clearcoat_normal_scale);
        sp->n_coat = keep_reflection_above_surface(sp->ng, wo, side * mapped);
    }
#endif
    if (m->textures[TEXTURE_SLOT_NORMAL] != TEXTURE_NONE) {
        float3 texel = texture_at(kd, m->textures[TEXTURE_SLOT_NORMAL], tri, hit.b1, hit.b2).xyz;
        float3 mapped = normal_from_map(side * sp->ns, hit_tangents(kd, hit), hit.b1, hit.b2, texel, m->normal_scale);
        sp->ns = keep_reflection_above_surface(sp->ng, wo, side * mapped);
    }
#endif
#endif
}

#endif /* PATHCL_HAS_MATERIAL_INPUTS */
