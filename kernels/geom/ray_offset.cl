/* Robust ray spawning. Spawned rays start at the hit point pushed along the geometric
 * normal by pbrt's conservative bound on the point's rounding error, then rounded one
 * more ulp away. The bound scales with the coordinates, so this stays correct at 1e-6 and
 * at 1e6 from the origin, where any fixed epsilon is either too small (acne) or too big
 * (leaks). */
#include "geom/surface_point.cl"

/* Origin for a ray leaving p in direction w (on either side of the surface n). */
static inline float3 offset_ray_origin(float3 p, float3 p_error, float3 n, float3 w)
{
    float d = dot(fabs(n), p_error);
    float3 offset = d * n;
    if (dot(w, n) < 0.0f)
        offset = -offset;
    float3 po = p + offset;
    po = select(po, nextafter(po, (float3)(INFINITY)), offset > 0.0f);
    po = select(po, nextafter(po, (float3)(-INFINITY)), offset < 0.0f);
    return po;
}

/* The part of a shadow ray's segment that is tested, as a fraction of its length. The
 * end point on an area or sphere light is already pushed off its surface by its error
 * bound, and a point light has no surface, so only a few ulps are left out: an occluder
 * 1e-4 of the way from the light (a lamp shade) still casts its shadow. */
#define SHADOW_RAY_EXTENT (1.0f - 8.0f * 0x1.0p-24f)

/* Whether a direction on the shading normal's side (cos_ig = its cosine with ng) counts
 * as leaving on wo's side. Above the geometric surface it does. Below it only where the
 * point is lifted onto the smooth surface: a ray from there towards wi that meets the
 * mesh is shadowed by it, as the coarse mesh would shadow it, and one that clears it is
 * lit, as the smooth surface would be; that is Hanika's terminator fix. Without a lift a
 * ray below the triangle would start behind it and could leak light through it. */
static inline bool above_surface(const SurfacePoint* sp, float cos_ig)
{
    return cos_ig > 0.0f || sp->lifted;
}

/* Origin for a ray leaving the surface point in direction w: a reflected ray (on the
 * shading normal's side) from the smooth surface, pushed off wo's side of the triangle;
 * a transmitted one from the triangle, pushed off its far side. */
static inline float3 spawn_ray_origin(const SurfacePoint* sp, float3 w)
{
    if (dot(w, sp->ns) > 0.0f && above_surface(sp, dot(w, sp->ng)))
        return offset_ray_origin(sp->p_smooth, sp->p_error, sp->ng, sp->ng);
    return offset_ray_origin(sp->p, sp->p_error, sp->ng, w);
}

/* Where a shading point's light samples are seen from: reflected rays (shadow rays
 * included) leave from there, so that a light's pdf at the point and on the hits of its
 * BSDF rays, which is measured from there, agree. */
static inline float3 light_sample_origin(const SurfacePoint* sp)
{
    return sp->lifted ? sp->p_smooth : sp->p;
}
