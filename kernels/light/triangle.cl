/* Area lights: emissive triangles, emitting from the front face only, sampled uniformly
 * by area and converted to a solid-angle pdf, or (--triangle-sampling solid-angle)
 * uniformly within the solid angle they subtend where that is large
 * (light/triangle_sampling.h). A textured emitter's radiance is its emissive texel at the
 * sampled point, as a ray hitting that point would see it, times the triangle's alpha
 * coverage there when alpha can cut it (a ray hits the point with that probability). */
#include "features.h"
#include "geom/surface_point.cl"
#include "kernel_data.cl"
#include "light/light_sample_record.cl"
#include "light/spherical_triangle.cl"
#include "light/triangle_sampling.h"
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

#ifdef PATHCL_SOLID_ANGLE_TRIANGLES
/* The solid angle of triangle v0 v1 v2 seen from ref, when below TRIANGLE_SOLID_ANGLE_MAX,
 * else 0. Out of line, as is sample_spherical_triangle: only the few shading points near a
 * light reach them, and inlined into the path kernel they slowed every other sample. */
PATHCL_NOINLINE static float triangle_solid_angle_near(float3 ref, float3 v0, float3 v1, float3 v2,
                                                       SphericalTriangle* s)
{
    *s = spherical_triangle(ref, v0, v1, v2);
    float omega = spherical_triangle_solid_angle(s);
    return omega <= TRIANGLE_SOLID_ANGLE_MAX ? omega : 0.0f;
}

/* The solid angle triangle light `light` subtends from ref when it is sampled by solid
 * angle there, else 0 (sampled by area). Light sampling and the pdf at a BSDF ray's hit
 * call it with the same ref, so they decide alike. */
static inline float triangle_light_solid_angle(const Light* light, float3 ref, SphericalTriangle* s)
{
    float3 v0 = light->data.triangle.v0.xyz, v1 = light->data.triangle.v1.xyz, v2 = light->data.triangle.v2.xyz;
    float3 to_centroid = (v0 + v1 + v2) * (1.0f / 3.0f) - ref;
    if (!(light->data.triangle.area > TRIANGLE_SOLID_ANGLE_MIN * dot(to_centroid, to_centroid)))
        return 0.0f;
    return triangle_solid_angle_near(ref, v0, v1, v2, s);
}
#endif

/* The solid-angle pdf of a light sample taken from ref reaching the point dist away on
 * triangle light `light`, where the cosine at the light is cos_light. */
static inline float triangle_light_pdf_from(const Light* light, float pmf, float3 ref, float dist, float cos_light)
{
#ifdef PATHCL_SOLID_ANGLE_TRIANGLES
    SphericalTriangle s;
    float omega = triangle_light_solid_angle(light, ref, &s);
    if (omega > 0.0f)
        return cos_light > 0.0f ? pmf / omega : 0.0f;
#endif
    return triangle_light_pdf(light, pmf, dist, cos_light);
}

/* A point on the triangle: uniform in the solid angle it subtends from ref, or uniform by
 * area (square-root parameterization). */
static inline void sample_triangle_light(const KernelData* kd, const Light* light, float pmf, float3 ref, float2 u,
                                         LightSample* ls)
{
    float3 v0 = light->data.triangle.v0.xyz, v1 = light->data.triangle.v1.xyz, v2 = light->data.triangle.v2.xyz;
    float b1, b2;
    float omega = 0.0f;
#ifdef PATHCL_SOLID_ANGLE_TRIANGLES
    SphericalTriangle st;
    omega = triangle_light_solid_angle(light, ref, &st);
    if (omega > 0.0f &&
        !triangle_barycentrics_along(ref, sample_spherical_triangle(&st, omega, u), v0, v1, v2, &b1, &b2))
        return;
#endif
    if (!(omega > 0.0f)) {
        float su = sqrt(u.x);
        b1 = 1.0f - su;
        b2 = u.y * su;
    }
    ls->p = barycentric_point(v0, v1, v2, b1, b2, &ls->p_error);
    ls->n = normalize(cross(v1 - v0, v2 - v0));
    float3 to_light = ls->p - ref;
    float dist = length(to_light);
    if (!(dist > 0.0f))
        return;
    ls->wi = to_light / dist;
    float cos_light = -dot(ls->wi, ls->n);
    if (omega > 0.0f)
        ls->pdf = cos_light > 0.0f ? pmf / omega : 0.0f;
    else
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
