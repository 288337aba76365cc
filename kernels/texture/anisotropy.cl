/* KHR_materials_anisotropy's direction at a hit: the direction of the larger roughness is
 * (cos r, sin r) in the tangent, bitangent plane (r = anisotropyRotation, counter-clockwise
 * from the tangent towards the bitangent), or the anisotropyTexture's RG direction turned
 * by r, whose B channel scales the strength. The tangent frame is the interpolated vertex
 * tangents' around the shading normal (after any normal map), so the direction lies in the
 * shading plane; the BSDF's frame is built on it (closure/bsdf_params.cl). Compiled only
 * for scenes with an anisotropic material (PATHCL_HAS_ANISOTROPY). */
#include "features.h"
#include "geom/surface_point.cl"
#include "geom/tangent_frame.cl"
#include "kernel_data.cl"
#include "texture/lookup.cl"

#ifdef PATHCL_HAS_ANISOTROPY

/* Sets sp->t_aniso (and scales the strength by the texture) for an anisotropic material
 * `m` (a private copy); leaves it 0 where the tangent frame is degenerate, and the BSDF
 * then takes any direction in the surface. */
static inline void apply_anisotropy(Material* m, SurfacePoint* sp, Hit hit, const KernelData* kd)
{
    if (!(m->anisotropy.x > 0.0f))
        return;
    float2 dir = m->anisotropy.yz;
#ifdef PATHCL_HAS_TEXTURES
    if (m->textures[TEXTURE_SLOT_ANISOTROPY] != TEXTURE_NONE) {
        float3 texel = texture_at(kd, m->textures[TEXTURE_SLOT_ANISOTROPY], hit.triangle, hit.b1, hit.b2).xyz;
        float2 d = 2.0f * texel.xy - 1.0f;
        float len = length(d);
        d = len > 1.0e-6f ? d / len : (float2)(1.0f, 0.0f); /* no direction: the tangent's */
        dir = (float2)(dir.x * d.x - dir.y * d.y, dir.y * d.x + dir.x * d.y);
        m->anisotropy.x *= texel.z;
    }
#endif
    /* The frame belongs to the front (counter-clockwise) side, as the normal map's does. */
    float3 n = sp->front_face ? sp->ns : -sp->ns;
    float3 t, b;
    if (tangent_frame(n, hit_tangents(kd, hit), hit.b1, hit.b2, &t, &b))
        sp->t_aniso = dir.x * t + dir.y * b;
}

#endif /* PATHCL_HAS_ANISOTROPY */
