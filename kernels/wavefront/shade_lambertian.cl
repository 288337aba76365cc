/* The wavefront's surface stage for programs whose every material is Lambertian (no
 * PATHCL_FULL_BSDF), lit by emissive triangles, LANES paths per work-item
 * (wavefront/lanes.cl). It does what one iteration of integrator/megakernel.cl's loop does
 * after the traversal: the emission found by the previous bounce (MIS-weighted), next
 * event estimation up to its shadow ray (the shadow stage traces it and adds the
 * contribution if nothing blocks it), the cosine-weighted bounce and Russian roulette,
 * with the numbers the extend stage drew at the same sampler dimensions. */
#include "features.h"
#include "integrator/surface_bounce.cl"
#include "kernel_data.cl"
#include "util/sincos.cl"
#include "wavefront/state_access.cl"
#include "wavefront/surface_lanes.cl"

/* integrator/mis.cl's power heuristic, per lane. */
PATHCL_ALWAYS_INLINE static inline LaneF lane_power_heuristic(LaneF pdf_a, LaneF pdf_b)
{
    LaneF a = pdf_a * pdf_a, b = pdf_b * pdf_b;
    LaneF w = select(lane_splat(0.0f), a / (a + b), a + b > 0.0f);
    return select(w, lane_splat(1.0f), isinf(a));
}

/* integrator/mis.cl's bsdf_hit_weight and light_sample_factor, per lane (the strategy is
 * the same for every lane). */
PATHCL_ALWAYS_INLINE static inline LaneF lane_bsdf_hit_weight(uint strategy, LaneI technique_was_bsdf, LaneF bsdf_pdf,
                                                              LaneF light_pdf)
{
    if (strategy == STRATEGY_BSDF)
        return lane_splat(1.0f);
    if (strategy == STRATEGY_NEE)
        return select(lane_splat(1.0f), lane_splat(0.0f), light_pdf > 0.0f);
    if (strategy == STRATEGY_ONE_SAMPLE)
        return select(lane_splat(0.0f), bsdf_pdf / (0.5f * (bsdf_pdf + light_pdf)), technique_was_bsdf);
    return lane_power_heuristic(bsdf_pdf, light_pdf);
}

PATHCL_ALWAYS_INLINE static inline LaneF lane_light_sample_factor(uint strategy, LaneI technique_is_light,
                                                                  LaneF light_pdf, LaneF bsdf_pdf)
{
    if (strategy == STRATEGY_BSDF)
        return lane_splat(0.0f);
    if (strategy == STRATEGY_NEE)
        return 1.0f / light_pdf;
    if (strategy == STRATEGY_ONE_SAMPLE)
        return select(lane_splat(0.0f), 1.0f / (0.5f * (light_pdf + bsdf_pdf)), technique_is_light);
    return lane_power_heuristic(light_pdf, bsdf_pdf) / light_pdf;
}

/* util/sincos.cl's sin_cos_small, per lane. */
PATHCL_ALWAYS_INLINE static inline LaneF lane_sin_cos_small(LaneF x, LaneF* c)
{
    LaneF x2 = x * x;
    *c = fma(fma(fma(fma(2.443315711809948e-5f, x2, -1.388731625493765e-3f), x2, 4.166664568298827e-2f), x2, -0.5f), x2,
             1.0f);
    return fma(fma(fma(-1.9515295891e-4f, x2, 8.3321608736e-3f), x2, -1.6666654611e-1f), x2 * x, x);
}

/* sample/warp.cl's concentric disk and cosine-weighted hemisphere. */
PATHCL_ALWAYS_INLINE static inline Lane3 lane_cosine_hemisphere(LaneF u0, LaneF u1)
{
    LaneF ox = 2.0f * u0 - 1.0f, oy = 2.0f * u1 - 1.0f;
    LaneI wide = fabs(ox) > fabs(oy); /* theta = pi/4 (y/x), else pi/2 - pi/4 (x/y) */
    LaneF c, s = lane_sin_cos_small((PI_F / 4.0f) * select(ox / oy, oy / ox, wide), &c);
    LaneF r = select(oy, ox, wide);
    LaneF dx = r * select(s, c, wide), dy = r * select(c, s, wide);
    LaneI centre = (ox == 0.0f) & (oy == 0.0f);
    dx = select(dx, lane_splat(0.0f), centre);
    dy = select(dy, lane_splat(0.0f), centre);
    return lane3(dx, dy, sqrt(fmax(0.0f, 1.0f - dx * dx - dy * dy)));
}

/* util/math.cl's make_basis (Duff et al.) and to_world: the local direction l around n. */
PATHCL_ALWAYS_INLINE static inline Lane3 lane_to_world(Lane3 l, Lane3 n)
{
    LaneF sign = copysign(lane_splat(1.0f), n.z);
    LaneF a = -1.0f / (sign + n.z);
    LaneF c = n.x * n.y * a;
    Lane3 t = lane3(1.0f + sign * n.x * n.x * a, sign * c, -sign * n.x);
    Lane3 b = lane3(c, sign + n.y * n.y * a, -n.y);
    return lane3(l.x * t.x + l.y * b.x + l.z * n.x, l.x * t.y + l.y * b.y + l.z * n.y,
                 l.x * t.z + l.y * b.z + l.z * n.z);
}

#if defined(PATHCL_HAS_AREA_LIGHTS) && !defined(PATHCL_FULL_BSDF)

/* A uniform point on each lane's triangle light (light/triangle.cl), seen from ref: the
 * point with its rounding bound, the light's normal, the direction and its solid-angle
 * pdf (the pick included). The returned mask: the lanes with a sample. */
PATHCL_ALWAYS_INLINE static inline LaneI lane_sample_triangle_light(const KernelData* kd, LaneI light, LaneF pmf,
                                                                    Lane3 ref, LaneF u0, LaneF u1, Lane3* p,
                                                                    Lane3* p_error, Lane3* n, Lane3* wi, LaneF* pdf)
{
    LaneF su = sqrt(u0);
    LaneF b1 = 1.0f - su;
    LaneF b2 = u1 * su;
    Lane3 v0 = LANE3_GATHER(kd->lights, data.triangle.v0, light),
          v1 = LANE3_GATHER(kd->lights, data.triangle.v1, light),
          v2 = LANE3_GATHER(kd->lights, data.triangle.v2, light);
    *p = lane_barycentric_point(v0, v1, v2, b1, b2, p_error);
    Lane3 c = lane3_cross(lane3_sub(v1, v0), lane3_sub(v2, v0));
    *n = lane3_div(c, lane3_length(c));
    Lane3 to_light = lane3_sub(*p, ref);
    LaneF dist = lane3_length(to_light);
    *wi = lane3_div(to_light, dist);
    LaneF cos_light = -lane3_dot(*wi, *n);
    LaneF area = lane_gather(LANE_FIELD(kd->lights, data.triangle.area), light, LANE_STRIDE(kd->lights));
    *pdf = pmf * dist * dist / (area * cos_light);
    return (dist > 0.0f) & (cos_light > 0.0f) & (*pdf > 0.0f);
}

/* A field of the state per lane: the LANES consecutive slots from `base`. */
#define LANES_F(s, name) LANE_LOAD((s).words + WAVEFRONT_##name * (s).capacity + base)
#define LANES_I(s, name) LANE_LOAD((__global const int*)(s).words + WAVEFRONT_##name * (s).capacity + base)
#define LANES_SET_F(s, name, v) LANE_STORE((v), (s).words + WAVEFRONT_##name * (s).capacity + base)
#define LANES_SET_I(s, name, v) LANE_STORE((v), (__global int*)(s).words + WAVEFRONT_##name * (s).capacity + base)

PATHCL_KERNEL void wavefront_shade(PATHCL_KERNEL_PARAMS FrameParams frame, __global float* state_words, uint capacity,
                                   uint depth)
{
    PATHCL_KERNEL_DATA;
    uint base = (uint)get_global_id(0) * LANES;
    if (base >= capacity)
        return;
    WavefrontState s = {state_words, capacity};
    LANES_SET_F(s, shadow_t_max, lane_splat(-1.0f));
    LaneI triangle = LANES_I(s, hit_triangle);
    /* The lanes whose path goes on to a surface; paths that miss leave (these programs
     * have no environment). */
    LaneI m = (LANES_I(s, alive) != 0) & (triangle >= 0);
    LANES_SET_I(s, alive, lane_splat_i(0));
    if (!LANE_ANY(m))
        return;
    Lane3 beta = lane3(LANES_F(s, beta_r), LANES_F(s, beta_g), LANES_F(s, beta_b));
    Lane3 wo = lane3_neg(lane3(LANES_F(s, ray_dx), LANES_F(s, ray_dy), LANES_F(s, ray_dz)));
    LaneI flags = LANES_I(s, flags);
    LaneSurfacePoint sp = lane_surface_point(&kd, m, triangle, LANES_F(s, hit_b1), LANES_F(s, hit_b2), wo);
    LaneI material = select(lane_splat_i(0), sp.material, m);
    Lane3 base_color = LANE3_GATHER(kd.materials, base_color, material);

    /* Emission leaves the front face only (integrator/shade_surface.cl). */
    LaneI emits = m & sp.front_face & (sp.emitter >= 0);
    if (LANE_ANY(emits)) {
        LaneI emitter = select(lane_splat_i(0), sp.emitter, emits);
        Lane3 le = LANE3_GATHER(kd.materials, emission, material);
        LaneF t = LANES_F(s, hit_t);
        LaneF pmf = lane_gather(LANE_FIELD(kd.light_distribution, pmf), emitter, LANE_STRIDE(kd.light_distribution));
        LaneF area = lane_gather(LANE_FIELD(kd.lights, data.triangle.area), emitter, LANE_STRIDE(kd.lights));
        LaneF cos_light = lane3_dot(sp.ng, wo);
        LaneF light_pdf = select(pmf * t * t / (area * cos_light), lane_splat(0.0f), cos_light <= 0.0f);
        LaneF w = lane_bsdf_hit_weight(frame.strategy, (flags & WAVEFRONT_PREV_TECHNIQUE_BSDF) != 0,
                                       LANES_F(s, prev_bsdf_pdf), light_pdf);
        w = select(w, lane_splat(1.0f), (flags & WAVEFRONT_PREV_DELTA) != 0);
        Lane3 radiance = lane3(LANES_F(s, radiance_r), LANES_F(s, radiance_g), LANES_F(s, radiance_b));
        radiance = lane3_select(emits, lane3_add(radiance, lane3_scale(lane3_mul(beta, le), w)), radiance);
        LANES_SET_F(s, radiance_r, radiance.x);
        LANES_SET_F(s, radiance_g, radiance.y);
        LANES_SET_F(s, radiance_b, radiance.z);
    }
    LaneI double_sided = (lane_gather_i(LANE_FIELD_I(kd.materials, flags), material, LANE_STRIDE(kd.materials)) &
                          MATERIAL_DOUBLE_SIDED) != 0;
    LaneF transmission = lane_gather(LANE_FIELD(kd.materials, transmission), material, LANE_STRIDE(kd.materials));
    m &= sp.front_face | double_sided | (transmission > 0.0f);
    if (depth >= frame.max_bounces || !LANE_ANY(m))
        return;

    LaneI technique_light = lane_splat_i(0);
    if (frame.strategy == STRATEGY_ONE_SAMPLE)
        technique_light = LANES_F(s, u_technique) < 0.5f;
    /* Next event estimation (integrator/direct_light.cl) up to the shadow ray. */
    if (frame.light_count > 0u && frame.strategy != STRATEGY_BSDF) {
        LaneI nee = m;
        if (frame.strategy == STRATEGY_ONE_SAMPLE)
            nee &= technique_light;
        LaneI light = select(lane_splat_i(0), LANES_I(s, light), nee);
        LaneF pmf = lane_gather(LANE_FIELD(kd.light_distribution, pmf), light, LANE_STRIDE(kd.light_distribution));
        Lane3 ref = lane3_select(sp.lifted, sp.p_smooth, sp.p);
        Lane3 lp, lp_error, ln, wi;
        LaneF light_pdf;
        nee &= lane_sample_triangle_light(&kd, light, pmf, ref, LANES_F(s, light_u0), LANES_F(s, light_u1), &lp,
                                          &lp_error, &ln, &wi, &light_pdf);
        LaneF cos_i = lane3_dot(wi, sp.ns);
        Lane3 f_cos = lane3_scale(base_color, INV_PI * cos_i);
        nee &= (cos_i > 0.0f) & lane_above_surface(&sp, lane3_dot(wi, sp.ng)) & (lane3_max(f_cos) > 0.0f);
        if (LANE_ANY(nee)) {
            Lane3 from = lane_spawn_ray_origin(&sp, wi);
            Lane3 to = lane_offset_ray_origin(lp, lp_error, ln, lane3_neg(wi));
            Lane3 dir = lane3_sub(to, from);
            Lane3 le = LANE3_GATHER(kd.lights, radiance, light);
            Lane3 contribution =
                lane3_scale(lane3_mul(lane3_mul(beta, f_cos), le),
                            lane_light_sample_factor(frame.strategy, technique_light, light_pdf, cos_i * INV_PI));
            LANES_SET_F(s, shadow_ox, from.x);
            LANES_SET_F(s, shadow_oy, from.y);
            LANES_SET_F(s, shadow_oz, from.z);
            LANES_SET_F(s, shadow_dx, dir.x);
            LANES_SET_F(s, shadow_dy, dir.y);
            LANES_SET_F(s, shadow_dz, dir.z);
            LANES_SET_F(s, shadow_t_max, select(lane_splat(-1.0f), lane_splat(SHADOW_RAY_EXTENT), nee));
            LANES_SET_F(s, shadow_r, contribution.x);
            LANES_SET_F(s, shadow_g, contribution.y);
            LANES_SET_F(s, shadow_b, contribution.z);
        }
    }

    /* The cosine-weighted bounce (closure/diffuse.cl's Lambertian case). */
    Lane3 wi_local = lane_cosine_hemisphere(LANES_F(s, u_bsdf0), LANES_F(s, u_bsdf1));
    Lane3 wi = lane_to_world(wi_local, sp.ns);
    LaneF bsdf_pdf = wi_local.z * INV_PI;
    m &= (wi_local.z > 0.0f) & lane_above_surface(&sp, lane3_dot(wi, sp.ng)) & (bsdf_pdf > 0.0f);
    beta = lane3_mul(beta, base_color);
    /* Russian roulette (integrator/surface_bounce.cl); no transmission, so eta2 is 1. */
    if (depth + 1u >= RR_START_BOUNCE) {
        LaneF q = fmin(1.0f, lane3_max(beta));
        m &= LANES_F(s, u_rr) < q;
        beta = lane3_div(beta, q);
    }
    if (!LANE_ANY(m))
        return;
    Lane3 origin = lane_spawn_ray_origin(&sp, wi);
    LANES_SET_F(s, beta_r, beta.x);
    LANES_SET_F(s, beta_g, beta.y);
    LANES_SET_F(s, beta_b, beta.z);
    LANES_SET_F(s, prev_bsdf_pdf, bsdf_pdf);
    LANES_SET_I(s, flags, select(lane_splat_i(WAVEFRONT_PREV_TECHNIQUE_BSDF), lane_splat_i(0), technique_light));
    LANES_SET_F(s, ray_ox, origin.x);
    LANES_SET_F(s, ray_oy, origin.y);
    LANES_SET_F(s, ray_oz, origin.z);
    LANES_SET_F(s, ray_dx, wi.x);
    LANES_SET_F(s, ray_dy, wi.y);
    LANES_SET_F(s, ray_dz, wi.z);
    LANES_SET_I(s, alive, select(lane_splat_i(0), lane_splat_i(1), m));
}

#endif
