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
#include "sample/warp.cl"
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
 * else 0. This and the two functions after it are out of line: only the few shading
 * points near a light reach them, and inlined into the path kernel they slowed every
 * other sample. */
PATHCL_NOINLINE static float triangle_solid_angle_near(float3 ref, float3 v0, float3 v1, float3 v2,
                                                       SphericalTriangle* s)
{
    *s = spherical_triangle(ref, v0, v1, v2);
    float omega = spherical_triangle_solid_angle(s);
    return omega <= TRIANGLE_SOLID_ANGLE_MAX ? omega : 0.0f;
}

/* The spherical triangle is sampled in proportion to the cosine at the shading point
 * (normal n), as pbrt-v4 does: the unit square is first warped by the bilinear
 * interpolation of the cosines at the corners its sides map to (u.y = 0: b; u = (0, 1):
 * a; u = (1, 1): c), each at least 0.01, so that no direction the triangle covers has
 * pdf 0 (the cosine is not linear in u, and a surface seen edge-on still transmits). */
static inline float4 cosine_warp_weights(const SphericalTriangle* s, float3 n)
{
    float at_b = fmax(0.01f, fabs(dot(n, s->b)));
    return (float4)(at_b, at_b, fmax(0.01f, fabs(dot(n, s->a))), fmax(0.01f, fabs(dot(n, s->c))));
}

/* A direction within the spherical triangle s of solid angle omega for the numbers u, and
 * its solid-angle pdf. */
PATHCL_NOINLINE static float3 sample_triangle_solid_angle(const SphericalTriangle* s, float omega, float3 n, float2 u,
                                                          float* pdf)
{
    float4 w = cosine_warp_weights(s, n);
    float2 warped = sample_bilinear(u, w);
    *pdf = bilinear_pdf(warped, w) / omega;
    return sample_spherical_triangle(s, omega, warped);
}

/* The solid-angle pdf with which sample_triangle_solid_angle draws the direction wi. */
PATHCL_NOINLINE static float triangle_solid_angle_pdf(const SphericalTriangle* s, float omega, float3 n, float3 wi)
{
    return bilinear_pdf(invert_spherical_triangle_sample(s, omega, wi), cosine_warp_weights(s, n)) / omega;
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

/* The solid-angle pdf of a light sample taken from ref (shading normal n) in the direction
 * wi, reaching the point dist away on triangle light `light` where the cosine at the light
 * is cos_light. */
static inline float triangle_light_pdf_from(const Light* light, float pmf, float3 ref, float3 n, float3 wi, float dist,
                                            float cos_light)
{
#ifdef PATHCL_SOLID_ANGLE_TRIANGLES
    SphericalTriangle s;
    float omega = triangle_light_solid_angle(light, ref, &s);
    if (omega > 0.0f)
        return cos_light > 0.0f ? pmf * triangle_solid_angle_pdf(&s, omega, n, wi) : 0.0f;
#endif
    return triangle_light_pdf(light, pmf, dist, cos_light);
}

/* A point on the triangle seen from ref (shading normal n): within the solid angle it
 * subtends, in proportion to the cosine at ref, or uniform by area (square-root
 * parameterization). */
static inline void sample_triangle_light(const KernelData* kd, const Light* light, float pmf, float3 ref, float3 n,
                                         float2 u, LightSample* ls)
{
    float3 v0 = light->data.triangle.v0.xyz, v1 = light->data.triangle.v1.xyz, v2 = light->data.triangle.v2.xyz;
    float b1, b2;
    float omega = 0.0f, direction_pdf = 0.0f;
#ifdef PATHCL_SOLID_ANGLE_TRIANGLES
    SphericalTriangle st;
    omega = triangle_light_solid_angle(light, ref, &st);
    if (omega > 0.0f && !triangle_barycentrics_along(ref, sample_triangle_solid_angle(&st, omega, n, u, &direction_pdf),
                                                     v0, v1, v2, &b1, &b2))
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
        ls->pdf = cos_light > 0.0f ? pmf * direction_pdf : 0.0f;
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
