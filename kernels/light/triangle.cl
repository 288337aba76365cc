/* Area lights: emissive triangles, emitting from the front face only, sampled uniformly
 * by area and converted to a solid-angle pdf. A textured emitter's radiance is its
 * emissive texel at the sampled point, as a ray hitting that point would see it, times
 * the triangle's alpha coverage there when alpha can cut it (a ray hits the point with
 * that probability). */
#include "features.h"
#include "geom/surface_point.cl"
#include "kernel_data.cl"
#include "light/light_sample_record.cl"
#include "texture/alpha.cl"
#include "texture/lookup.cl"

#ifdef PATHCL_HAS_AREA_LIGHTS

/* Solid-angle pdf of reaching a point on triangle light `light` (picked with probability
 * pmf) from a point dist away, where cos_light is the cosine at the light:
 * pmf / (area * cos / d^2). */
static inline float triangle_light_pdf(const Light* light, float pmf, float dist, float cos_light)
{
    if (cos_light <= 0.0f)
        return 0.0f;
    return pmf * dist * dist / (light->data.triangle.area * cos_light);
}

/* A uniform point on the triangle (square-root parameterization). */
static inline void sample_triangle_light(const KernelData* kd, const Light* light, float pmf, float3 ref, float2 u,
                                         LightSample* ls)
{
    float su = sqrt(u.x);
    float b1 = 1.0f - su;
    float b2 = u.y * su;
    float3 v0 = light->data.triangle.v0.xyz, v1 = light->data.triangle.v1.xyz, v2 = light->data.triangle.v2.xyz;
    ls->p = barycentric_point(v0, v1, v2, b1, b2, &ls->p_error);
    ls->n = normalize(cross(v1 - v0, v2 - v0));
    float3 to_light = ls->p - ref;
    float dist = length(to_light);
    if (!(dist > 0.0f))
        return;
    ls->wi = to_light / dist;
    float cos_light = -dot(ls->wi, ls->n);
    ls->pdf = triangle_light_pdf(light, pmf, dist, cos_light);
    ls->radiance = (ls->pdf > 0.0f) ? light->radiance.xyz : (float3)(0.0f);
#ifdef PATHCL_HAS_TEXTURES
    /* The emissive texture at the sampled point, as a ray hitting it would see it. */
    if (light->data.triangle.texture != TEXTURE_NONE && ls->pdf > 0.0f)
        ls->radiance *= texture_at(kd, light->data.triangle.texture, light->data.triangle.triangle, b1, b2).xyz;
#endif
#ifdef PATHCL_HAS_ALPHA
    int tri = light->data.triangle.triangle;
    if (ls->pdf > 0.0f && kd->triangles[tri].v0.w != 0.0f)
        ls->radiance *= surface_coverage(kd, tri, b1, b2);
#endif
}

#endif /* PATHCL_HAS_AREA_LIGHTS */
