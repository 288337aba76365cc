/* The path tracer: one camera ray per work-item, followed through up to max_bounces
 * scattering events. Needs every other kernel file.
 *
 * Estimator (the rendering equation, unrolled): at each vertex
 *   L += beta * Le(wo)                      emission, MIS-weighted against light sampling
 *   L += beta * f cos Le / p_light * w      next event estimation (shadow ray), MIS weight
 *   beta *= f cos / p_bsdf                  continue the path by BSDF sampling
 * with the power heuristic w = p^2 / (p_light^2 + p_bsdf^2) and unbiased Russian roulette
 * after 3 bounces. Feature flags (PATHCL_HAS_*) come from the scene; code for features a
 * scene lacks is not compiled. */

#define RR_START_BOUNCE 3

inline float power_heuristic(float pdf_a, float pdf_b)
{
    float a = pdf_a * pdf_a, b = pdf_b * pdf_b;
    if (isinf(a))
        return 1.0f;
    return (a + b > 0.0f) ? a / (a + b) : 0.0f;
}

inline float max_component(float3 v)
{
    return fmax(v.x, fmax(v.y, v.z));
}

__kernel void trace_paths(__global const Ray* rays, __global const BvhNode* nodes,
                          __global const Triangle* triangles,
                          __global const TriangleShading* shading,
                          __global const Material* materials, __global const Light* lights,
                          __global FilmPixel* film, __global uint* bad_samples,
                          FrameParams frame)
{
    uint x = get_global_id(0);
    uint y = get_global_id(1);
    if (x >= frame.width || y >= frame.height)
        return;
    uint pixel = y * frame.width + x;

    Ray ray = rays[pixel];
    float3 origin = ray.origin.xyz;
    float3 dir = ray.direction.xyz;
    float3 radiance = (float3)(0.0f);
    float3 beta = (float3)(1.0f);
    float prev_bsdf_pdf = 0.0f;
    bool prev_delta = true; /* camera rays see emission with full weight */

    for (uint depth = 0;; ++depth) {
        Hit hit = bvh_trace(nodes, triangles, origin, dir, INFINITY, false);
        if (hit.triangle < 0)
            break; /* escaped: no environment yet */
        float3 wo = -dir;
        SurfacePoint sp = surface_point(triangles, shading, hit, wo);
        Material m = materials[sp.material];

#ifdef PATHCL_HAS_AREA_LIGHTS
        /* Emission leaves the front face only. */
        if (sp.front_face && sp.emitter >= 0) {
            float3 le = m.emission.xyz;
            if (prev_delta) {
                radiance += beta * le;
            } else {
                Light light = lights[sp.emitter];
                float cos_light = dot(sp.ng, wo);
                float light_pdf = triangle_light_pdf(&light, hit.t, cos_light);
                radiance += beta * le * power_heuristic(prev_bsdf_pdf, light_pdf);
            }
        }
#endif
        if (depth >= frame.max_bounces)
            break;
        /* A single-sided surface seen from behind is black but still blocks light. */
        if (!sp.front_face && !(m.flags & MATERIAL_DOUBLE_SIDED))
            break;

        SamplerState sampler = sampler_start(pixel, frame.sample_index, frame.seed,
                                             DIM_PATH_START + depth * DIMS_PER_BOUNCE);

#ifdef PATHCL_HAS_AREA_LIGHTS
        /* Next event estimation: one shadow ray to a point on a light. */
        if (frame.light_count > 0u) {
            LightSample ls = light_sample(lights, frame.light_count, sp.p, &sampler);
            if (ls.pdf > 0.0f) {
                float3 wi = normalize(ls.p - sp.p);
                BsdfEval e = bsdf_eval(&m, &sp, wo, wi);
                if (max_component(e.f_cos) > 0.0f) {
                    float3 from = offset_ray_origin(sp.p, sp.p_error, sp.ng, wi);
                    float3 to = offset_ray_origin(ls.p, ls.p_error, ls.n, -wi);
                    Hit blocker = bvh_trace(nodes, triangles, from, to - from,
                                            SHADOW_RAY_EXTENT, true);
                    if (blocker.triangle < 0) {
                        float w = power_heuristic(ls.pdf, e.pdf);
                        radiance += beta * e.f_cos * ls.radiance * (w / ls.pdf);
                    }
                }
            }
        } else {
            sampler.dimension += 4u;
        }
#endif

        /* Continue the path by sampling the BSDF. */
        BsdfSample bs = bsdf_sample(&m, &sp, wo, sampler_get_2d(&sampler));
        if (!(bs.pdf > 0.0f))
            break;
        beta *= bs.weight;
        prev_bsdf_pdf = bs.pdf;
        prev_delta = bs.delta;
        origin = offset_ray_origin(sp.p, sp.p_error, sp.ng, bs.wi);
        dir = bs.wi;

        /* Russian roulette: survive with probability q, divide by q (unbiased). */
        if (depth + 1u >= RR_START_BOUNCE) {
            float q = fmin(1.0f, max_component(beta));
            if (sampler_get_1d(&sampler) >= q)
                break;
            beta /= q;
        }
    }
    film_add_sample(film, bad_samples, pixel, radiance);
}
