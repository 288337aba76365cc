/* Kernels that time one stage of a render each (pathcl bench --kernels): closest-hit and
 * any-hit traversal of the rays in kd.rays, diffuse-bounce and shadow rays made from the
 * camera rays' hits, and film accumulation. The render program's kernels come along. Each
 * writes a result the host never reads (kd.bad_samples), so that none is optimized away. */
#include "bvh/traversal.cl"
#include "film/film.cl"
#include "film/pixel.cl"
#include "geom/ray_offset.cl"
#include "geom/surface_point.cl"
#include "kernel_data.cl"
#include "light/light_sample.cl"
#include "program.cl"
#include "sample/sampler.cl"
#include "sample/warp.cl"

/* The distance a bench ray is traced to: direction.w when positive (shadow rays), else
 * unbounded. */
static inline float bench_ray_extent(Ray r)
{
    return r.direction.w > 0.0f ? r.direction.w : INFINITY;
}

PATHCL_KERNEL void bench_closest_hit(PATHCL_KERNEL_PARAMS FrameParams frame)
{
    PATHCL_KERNEL_DATA;
    uint2 xy;
    uint pixel;
    if (!frame_pixel(&frame, &xy, &pixel))
        return;
    Ray r = kd.rays[pixel];
    kd.bad_samples[pixel] = (uint)bvh_closest_hit(&kd, r.origin.xyz, r.direction.xyz, bench_ray_extent(r)).triangle;
}

PATHCL_KERNEL void bench_any_hit(PATHCL_KERNEL_PARAMS FrameParams frame)
{
    PATHCL_KERNEL_DATA;
    uint2 xy;
    uint pixel;
    if (!frame_pixel(&frame, &xy, &pixel))
        return;
    Ray r = kd.rays[pixel];
    kd.bad_samples[pixel] = bvh_visibility(&kd, r.origin.xyz, r.direction.xyz, bench_ray_extent(r)) == 0.0f;
}

/* Replaces each camera ray by a ray leaving its first hit: cosine-distributed about the
 * shading normal (diffuse != 0), or towards a point on a light picked as next event
 * estimation picks it (a shadow ray, its extent in direction.w). A ray that hit nothing
 * stays as it is. */
PATHCL_KERNEL void bench_bounce_rays(PATHCL_KERNEL_PARAMS FrameParams frame, uint diffuse)
{
    PATHCL_KERNEL_DATA;
    uint2 xy;
    uint pixel;
    if (!frame_pixel(&frame, &xy, &pixel))
        return;
    Ray r = kd.rays[pixel];
    Hit hit = bvh_closest_hit(&kd, r.origin.xyz, r.direction.xyz, INFINITY);
    if (hit.triangle < 0)
        return;
    float3 wo = -r.direction.xyz;
    SurfacePoint sp = surface_point(&kd, hit, wo);
    SamplerState s = sampler_start(pixel, frame.sample_index, frame.seed, 0u);
    Ray out;
    if (diffuse != 0u || frame.light_count == 0u) {
        float3 t, b;
        make_basis(sp.ns, &t, &b);
        float3 wi = to_world(sample_cosine_hemisphere(sampler_get_2d(&s)), t, b, sp.ns);
        out.origin = (float4)(spawn_ray_origin(&sp, wi), 0.0f);
        out.direction = (float4)(wi, 0.0f);
    } else {
        LightSample ls = light_sample(&kd, &frame, sp.p, sp.ns, &s);
        float3 from = spawn_ray_origin(&sp, ls.wi);
        float3 dir = ls.wi;
        float extent = 0.0f; /* unbounded */
        if (!ls.at_infinity) {
            dir = ls.p - from;
            extent = SHADOW_RAY_EXTENT;
        }
        out.origin = (float4)(from, 0.0f);
        out.direction = (float4)(dir, extent);
    }
    kd.rays[pixel] = out;
}

PATHCL_KERNEL void bench_film(PATHCL_KERNEL_PARAMS FrameParams frame)
{
    PATHCL_KERNEL_DATA;
    uint2 xy;
    uint pixel;
    if (!frame_pixel(&frame, &xy, &pixel))
        return;
    film_add_sample(kd.film, kd.bad_samples, pixel, (float3)(0.25f, 0.5f, 0.75f));
}
