/* The path tracer: one camera ray per work-item, followed through up to max_bounces
 * scattering events. Needs every other kernel file.
 *
 * Estimator (the rendering equation, unrolled): at each vertex
 *   L += beta * Le(wo) * w_bsdf              emission reached by the previous BSDF sample
 *   L += beta * f cos Le / p_light * w_light next event estimation (shadow ray)
 *   beta *= f cos / p_bsdf                   continue the path by BSDF sampling
 * The strategy (frame.strategy) sets the weights:
 *   bsdf:       w_bsdf = 1, no light sampling;
 *   nee:        w_bsdf = 0, w_light = 1 (BSDF rays carry indirect light only);
 *   mis:        power heuristic, w = p^2 / (p_light^2 + p_bsdf^2);
 *   one-sample: a coin picks ONE technique per bounce (probability 1/2 each) and its
 *               sample is divided by the mixture pdf (p_light + p_bsdf) / 2 (Veach's
 *               one-sample model; the coin's probability is inside the mixture).
 * Emission seen by camera rays (or after a delta BSDF) always has weight 1. Russian
 * roulette after 3 bounces is unbiased. Feature flags (PATHCL_HAS_*) come from the scene;
 * code for features a scene lacks is not compiled. */

#define RR_START_BOUNCE 3

/* Random dimensions within a bounce (DIMS_PER_BOUNCE of them). */
#define DIM_TECHNIQUE 0
#define DIM_LIGHT 1 /* 4: pick (2) and point (2) */
#define DIM_BSDF 5  /* 2 */
#define DIM_RR 7
#define DIM_BSDF_LOBE 8

static inline float power_heuristic(float pdf_a, float pdf_b)
{
    float a = pdf_a * pdf_a, b = pdf_b * pdf_b;
    if (isinf(a))
        return 1.0f;
    return (a + b > 0.0f) ? a / (a + b) : 0.0f;
}

static inline float max_component(float3 v)
{
    return fmax(v.x, fmax(v.y, v.z));
}

/* Weight of emission found by a BSDF-sampled ray whose pdf was bsdf_pdf, where light
 * sampling would have produced the same direction with light_pdf. */
static inline float bsdf_hit_weight(uint strategy, bool technique_was_bsdf, float bsdf_pdf, float light_pdf)
{
    switch (strategy) {
    case STRATEGY_BSDF:
        return 1.0f;
    case STRATEGY_NEE:
        /* Light sampling carries this light, unless it cannot produce this direction
         * (a zero-width cell of a float CDF, say): then only the BSDF finds it. */
        return light_pdf > 0.0f ? 0.0f : 1.0f;
    case STRATEGY_ONE_SAMPLE:
        /* beta already holds f cos / p_bsdf: this turns it into f cos / p_mixture. */
        return technique_was_bsdf ? bsdf_pdf / (0.5f * (bsdf_pdf + light_pdf)) : 0.0f;
    default:
        return power_heuristic(bsdf_pdf, light_pdf);
    }
}

/* Factor applied to f cos Le of a light sample with pdfs light_pdf and bsdf_pdf
 * (0 when the strategy does not sample lights at this vertex). */
static inline float light_sample_factor(uint strategy, bool technique_is_light, float light_pdf, float bsdf_pdf)
{
    switch (strategy) {
    case STRATEGY_BSDF:
        return 0.0f;
    case STRATEGY_NEE:
        return 1.0f / light_pdf;
    case STRATEGY_ONE_SAMPLE:
        return technique_is_light ? 1.0f / (0.5f * (light_pdf + bsdf_pdf)) : 0.0f;
    default:
        return power_heuristic(light_pdf, bsdf_pdf) / light_pdf;
    }
}

__kernel void trace_paths(__global const Ray* rays, __global const BvhNode* nodes,
                          __global const Triangle* triangles,
                          __global const TriangleShading* shading,
                          __global const Material* materials, __global const Light* lights,
                          __global const float4* env_texels, __global const float* env_marginal,
                          __global const float* env_conditional, __global const float* layer_albedo,
                          __global FilmPixel* film, __global uint* bad_samples, FrameParams frame,
                          __global const uint* texels, __global const TextureImage* texture_images,
                          __global const TextureView* texture_views, __global const TriangleTexcoords* texcoords,
                          __global const TriangleTangents* tangents, __global const TriangleColors* colors)
{
    EnvironmentBuffers env;
    env.texels = env_texels;
    env.marginal = env_marginal;
    env.conditional = env_conditional;
    TextureBuffers tex = texture_buffers(texels, texture_images, texture_views, texcoords, tangents, colors);
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
    float eta2_product = 1.0f; /* product of the eta^2 that beta holds the inverse of */
    float prev_bsdf_pdf = 0.0f;
    bool prev_delta = true;         /* camera rays see emission with full weight */
    bool prev_technique_bsdf = true; /* one-sample: the coin chose the BSDF technique */

    for (uint depth = 0;; ++depth) {
        Hit hit = bvh_trace(nodes, triangles, origin, dir, INFINITY, false);
#ifdef PATHCL_HAS_SPHERE_LIGHTS
        /* Sphere lights are outside the BVH: the nearer of the two hits wins. They emit
         * outwards only, and their surface does not reflect: the path ends there. */
        float t_sphere;
        bool sphere_from_outside;
        int sphere = closest_sphere_light(lights, frame.sphere_count, origin, dir, hit.t, &t_sphere,
                                          &sphere_from_outside);
        if (sphere >= 0) {
            if (sphere_from_outside) {
                Light light = lights[sphere];
                float w = prev_delta ? 1.0f
                                     : bsdf_hit_weight(frame.strategy, prev_technique_bsdf, prev_bsdf_pdf,
                                                       sphere_light_pdf(&light, origin));
                radiance += beta * light.radiance.xyz * w;
            }
            break;
        }
#endif
        if (hit.triangle < 0) {
#ifdef PATHCL_HAS_ENVIRONMENT
            /* Escaped: the environment, weighted against light sampling of it. */
            if (frame.environment >= 0) {
                Light e = lights[frame.environment];
                float w = prev_delta ? 1.0f
                                     : bsdf_hit_weight(frame.strategy, prev_technique_bsdf, prev_bsdf_pdf,
                                                       environment_pdf(&e, &env, dir));
                radiance += beta * environment_radiance(&e, &env, dir) * w;
            }
#endif
            break;
        }
        float3 wo = -dir;
        SurfacePoint sp = surface_point(triangles, shading, hit, wo);
        Material m = materials[sp.material];
#if defined(PATHCL_HAS_TEXTURES) || defined(PATHCL_HAS_VERTEX_COLORS)
        apply_material_inputs(&m, &sp, wo, hit, &tex);
#endif
        BsdfParams bp = bsdf_params(&m, &sp, wo, layer_albedo);

#ifdef PATHCL_HAS_AREA_LIGHTS
        /* Emission leaves the front face only. */
        if (sp.front_face && sp.emitter >= 0) {
            float3 le = m.emission.xyz;
            if (prev_delta) {
                radiance += beta * le;
            } else {
                Light light = lights[sp.emitter];
                float light_pdf = triangle_light_pdf(&light, hit.t, dot(sp.ng, wo));
                radiance += beta * le *
                            bsdf_hit_weight(frame.strategy, prev_technique_bsdf, prev_bsdf_pdf, light_pdf);
            }
        }
#endif
        if (depth >= frame.max_bounces)
            break;
        /* A single-sided opaque surface seen from behind is black but still blocks light.
         * A transmissive one is an interface from both sides: a solid's back face is its
         * inside, a thin sheet lets light through either way. */
        if (!sp.front_face && !(m.flags & MATERIAL_DOUBLE_SIDED) && !(m.transmission > 0.0f))
            break;

        uint dims = DIM_PATH_START + depth * DIMS_PER_BOUNCE;
        SamplerState sampler = frame_sampler(&frame, pixel, dims + DIM_TECHNIQUE);
        /* One-sample MIS's coin (its own dimension, drawn only by that strategy). */
        bool technique_light = frame.strategy == STRATEGY_ONE_SAMPLE && sampler_get_1d(&sampler) < 0.5f;

#ifdef PATHCL_HAS_LIGHTS
        /* Next event estimation: one shadow ray to a point on a light. */
        bool sample_light = frame.light_count > 0u && frame.strategy != STRATEGY_BSDF &&
                            (frame.strategy != STRATEGY_ONE_SAMPLE || technique_light) && !bsdf_is_delta(&bp);
        if (sample_light) {
            sampler.dimension = dims + DIM_LIGHT;
            /* From where reflected rays (shadow rays included) leave, so that the light's
             * pdf here and on BSDF hits, which is measured from there, agree. */
            LightSample ls = light_sample(lights, frame.light_count, &env, &tex, sp.lifted ? sp.p_smooth : sp.p, &sampler);
            if (ls.pdf > 0.0f) {
                BsdfEval e = bsdf_eval(&bp, &sp, wo, ls.wi);
                if (max_component(e.f_cos) > 0.0f) {
                    /* The shadow ray's segment: unbounded towards a directional light,
                     * else up to just short of the light point (offset off an area
                     * light's surface so the light itself never blocks). */
                    float3 from = spawn_ray_origin(&sp, ls.wi);
                    float3 shadow_dir = ls.wi;
                    float shadow_t_max = INFINITY;
                    if (!ls.at_infinity) {
                        float3 to = ls.delta ? ls.p : offset_ray_origin(ls.p, ls.p_error, ls.n, -ls.wi);
                        shadow_dir = to - from;
                        shadow_t_max = SHADOW_RAY_EXTENT;
                    }
                    bool blocked = bvh_trace(nodes, triangles, from, shadow_dir, shadow_t_max, true).triangle >= 0;
#ifdef PATHCL_HAS_SPHERE_LIGHTS
                    float t_sphere_shadow;
                    bool unused_side;
                    blocked = blocked || closest_sphere_light(lights, frame.sphere_count, from, shadow_dir, shadow_t_max,
                                                              &t_sphere_shadow, &unused_side) >= 0;
#endif
                    /* BSDF sampling never finds a delta light: its BSDF pdf is 0 there. */
                    float bsdf_pdf = ls.delta ? 0.0f : e.pdf;
                    if (!blocked)
                        radiance += beta * e.f_cos * ls.radiance *
                                    light_sample_factor(frame.strategy, technique_light, ls.pdf, bsdf_pdf);
                }
            }
        }
#endif

        /* Continue the path by sampling the BSDF. */
        sampler.dimension = dims + DIM_BSDF_LOBE;
        float u_lobe = sampler_get_1d(&sampler);
        sampler.dimension = dims + DIM_BSDF;
        BsdfSample bs = bsdf_sample(&bp, &sp, wo, u_lobe, sampler_get_2d(&sampler));
        if (!(bs.pdf > 0.0f))
            break;
        beta *= bs.weight;
        eta2_product *= bs.eta2;
        prev_bsdf_pdf = bs.pdf;
        prev_delta = bs.delta;
        prev_technique_bsdf = !technique_light;
        origin = spawn_ray_origin(&sp, bs.wi);
        dir = bs.wi;

        /* Russian roulette: survive with probability q, divide by q (unbiased). q follows
         * the energy the path carries, not its radiance: inside glass beta holds 1/eta^2,
         * which would otherwise kill paths that are about to leave it (as pbrt does). */
        if (depth + 1u >= RR_START_BOUNCE) {
            sampler.dimension = dims + DIM_RR;
            float q = fmin(1.0f, max_component(beta) * eta2_product);
            if (sampler_get_1d(&sampler) >= q)
                break;
            beta /= q;
        }
    }
    film_add_sample(film, bad_samples, pixel, radiance);
}
