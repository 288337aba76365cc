/* glTF alpha as geometry (alphaMode MASK and BLEND): whether a ray's hit on a triangle
 * counts. A triangle's alpha at a point is baseColorFactor's alpha x the base colour
 * texture's alpha x COLOR_0's alpha; its coverage is
 *   MASK:  1 where alpha >= alphaCutoff, else 0 (no surface at all: a cut-out);
 *   BLEND: alpha, clamped to [0, 1] (the fraction of the point the surface covers).
 * Rays that look for the closest hit keep a hit with probability equal to its coverage
 * (a coin hashed from the ray and the triangle, so the decision does not depend on the
 * order the traversal meets triangles in, and two sheets on one ray get independent
 * coins); shadow rays are attenuated by 1 - coverage of every surface they cross, so a
 * light sample sees the expected value that the coin gives a ray on average. Only
 * triangles marked TRIANGLE_ALPHA_TESTED are asked, and only programs compiled with
 * PATHCL_HAS_ALPHA contain this code. */
#include "features.h"
#include "kernel_data.cl"
#include "texture/lookup.cl"
#include "util/hash.cl"

#ifdef PATHCL_HAS_ALPHA

/* The coverage of triangle `triangle` at barycentrics (b1, b2), in [0, 1]. */
static inline float surface_coverage(const KernelData* kd, int triangle, float b1, float b2)
{
    __global const Material* m = &kd->materials[kd->shading[triangle].material];
    float alpha = m->base_color.w;
#ifdef PATHCL_HAS_VERTEX_COLORS
    {
        TriangleColors c = kd->colors[triangle];
        alpha *= (1.0f - b1 - b2) * c.c0.w + b1 * c.c1.w + b2 * c.c2.w;
    }
#endif
#ifdef PATHCL_HAS_TEXTURES
    int base_texture = m->textures[TEXTURE_SLOT_BASE_COLOR];
    if (base_texture != TEXTURE_NONE)
        alpha *= texture_at(kd, base_texture, triangle, b1, b2).w;
#endif
    if (m->flags & MATERIAL_ALPHA_MASK)
        return alpha >= m->alpha_cutoff ? 1.0f : 0.0f;
    return clamp(alpha, 0.0f, 1.0f);
}

/* A per-ray seed for the coverage coins: the ray's origin and direction, bit for bit. */
static inline uint alpha_ray_seed(float3 origin, float3 dir)
{
    uint h = hash_u32(as_uint(origin.x));
    h = hash_combine(h, as_uint(origin.y));
    h = hash_combine(h, as_uint(origin.z));
    h = hash_combine(h, as_uint(dir.x));
    h = hash_combine(h, as_uint(dir.y));
    return hash_combine(h, as_uint(dir.z));
}

/* Whether a closest-hit ray with seed `ray_seed` keeps its hit on `triangle`: always
 * where the coverage is 1, never where it is 0, else with probability coverage. */
static inline bool alpha_keeps_hit(const KernelData* kd, uint ray_seed, int triangle, float b1, float b2)
{
    float coverage = surface_coverage(kd, triangle, b1, b2);
    return u32_to_unit_float(hash_combine(ray_seed, (uint)triangle)) < coverage;
}

#endif /* PATHCL_HAS_ALPHA */
