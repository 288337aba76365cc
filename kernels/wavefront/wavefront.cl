/* The wavefront integrator: the path tracer of integrator/megakernel.cl split into one
 * kernel per stage, with the paths' state in a structure of arrays between them
 * (wavefront/path_state.h), one slot per pixel of the device's band. The host
 * (host/render/wavefront.cpp) launches, per pass of one sample per pixel:
 *   generate_camera_rays     the camera (camera/camera.cl), as for the megakernel
 *   wavefront_start          a path per pixel, along its camera ray
 *   per bounce d = 0 .. max_bounces:
 *     wavefront_extend       the bounce's sampler numbers and light pick; the closest hit
 *     wavefront_shade        the surface: emission, next event estimation, the bounce,
 *                            LANES paths per work-item (wavefront/shade_lambertian.cl)
 *     wavefront_shadow       the shadow rays (not after the last bounce)
 *   wavefront_film           each path's radiance into its pixel
 * Every decision draws the numbers of the same sampler dimension as in the megakernel, so
 * the two integrators render the same image (to rounding where their arithmetic
 * differs). A slot whose path has ended stays in the arrays with alive 0; the stages skip
 * it (a shading work-item whose LANES paths have all ended returns at once). */
#include "bvh/traversal.cl"
#include "features.h"
#include "film/film.cl"
#include "film/pixel.cl"
#include "integrator/direct_light.cl"
#include "integrator/intersect_shadow.cl"
#include "integrator/surface_bounce.cl"
#include "kernel_data.cl"
#include "sample/dimensions.h"
#include "sample/sampler.cl"
#include "wavefront/shade_lambertian.cl"
#include "wavefront/state_access.cl"

/* The path of slot p (pixel first_row * width + p) along its camera ray (kd.rays); slots
 * past the band's pixels, up to the capacity (a multiple of LANES), start ended. */
PATHCL_KERNEL void wavefront_start(PATHCL_KERNEL_PARAMS FrameParams frame, __global float* state_words, uint capacity,
                                   uint paths)
{
    PATHCL_KERNEL_DATA;
    uint p = get_global_id(0);
    if (p >= capacity)
        return;
    WavefrontState s = {state_words, capacity};
    uint pixel = frame.first_row * frame.width + p;
    bool alive = p < paths && pixel_active(&frame, kd.active, pixel);
    STATE_SET_I(s, alive, p, alive ? 1 : 0);
    STATE_SET_I(s, pixel, p, (int)pixel);
    STATE_SET_F(s, radiance_r, p, 0.0f);
    STATE_SET_F(s, radiance_g, p, 0.0f);
    STATE_SET_F(s, radiance_b, p, 0.0f);
    STATE_SET_F(s, shadow_t_max, p, -1.0f);
    if (!alive)
        return;
    __global const float* ray = (__global const float*)&kd.rays[pixel];
    STATE_SET_F(s, ray_ox, p, ray[0]);
    STATE_SET_F(s, ray_oy, p, ray[1]);
    STATE_SET_F(s, ray_oz, p, ray[2]);
    STATE_SET_F(s, ray_dx, p, ray[4]);
    STATE_SET_F(s, ray_dy, p, ray[5]);
    STATE_SET_F(s, ray_dz, p, ray[6]);
    STATE_SET_F(s, beta_r, p, 1.0f);
    STATE_SET_F(s, beta_g, p, 1.0f);
    STATE_SET_F(s, beta_b, p, 1.0f);
    STATE_SET_F(s, prev_bsdf_pdf, p, 0.0f);
    STATE_SET_I(s, flags, p, WAVEFRONT_PREV_DELTA | WAVEFRONT_PREV_TECHNIQUE_BSDF);
}

/* The bounce's sampler numbers and light pick (sample/, light/light_pick.cl), drawn here
 * beside the traversal as the megakernel draws them before it, then the closest hit. */
PATHCL_KERNEL void wavefront_extend(PATHCL_KERNEL_PARAMS FrameParams frame, __global float* state_words, uint capacity,
                                    uint depth)
{
    PATHCL_KERNEL_DATA;
    uint p = get_global_id(0);
    if (p >= capacity)
        return;
    WavefrontState s = {state_words, capacity};
    if (STATE_I(s, alive, p) == 0)
        return;
    uint pixel = (uint)STATE_I(s, pixel, p);
    const SamplerState path_sampler = frame_sampler(&frame, pixel, DIM_PATH_START);
    uint dims = DIM_PATH_START + depth * DIMS_PER_BOUNCE;
    SamplerState sampler = sampler_bounce(&path_sampler, dims);
#ifdef PATHCL_HAS_LIGHTS
    if (frame_samples_lights(&frame)) {
        LightChoice choice = direct_light_choose(&kd, &frame, dims, (float3)(0.0f), (float3)(0.0f), &sampler);
        STATE_SET_I(s, light, p, choice.light);
        STATE_SET_F(s, light_u0, p, choice.u.x);
        STATE_SET_F(s, light_u1, p, choice.u.y);
    }
#endif
    sampler.dimension = dims + DIM_BSDF;
    float2 u = sampler_get_2d(&sampler);
    STATE_SET_F(s, u_bsdf0, p, u.x);
    STATE_SET_F(s, u_bsdf1, p, u.y);
    if (depth + 1u >= RR_START_BOUNCE) {
        sampler.dimension = dims + DIM_RR;
        STATE_SET_F(s, u_rr, p, sampler_get_1d(&sampler));
    }
    if (frame.strategy == STRATEGY_ONE_SAMPLE) {
        sampler.dimension = dims + DIM_TECHNIQUE;
        STATE_SET_F(s, u_technique, p, sampler_get_1d(&sampler));
    }
    float3 origin = (float3)(STATE_F(s, ray_ox, p), STATE_F(s, ray_oy, p), STATE_F(s, ray_oz, p));
    float3 dir = (float3)(STATE_F(s, ray_dx, p), STATE_F(s, ray_dy, p), STATE_F(s, ray_dz, p));
    Hit hit = bvh_closest_hit(&kd, origin, dir, INFINITY);
    STATE_SET_F(s, hit_t, p, hit.t);
    STATE_SET_I(s, hit_triangle, p, hit.triangle);
    STATE_SET_F(s, hit_b1, p, hit.b1);
    STATE_SET_F(s, hit_b2, p, hit.b2);
}

/* The bounce's shadow rays: a contribution whose segment nothing blocks joins its path's
 * radiance. */
PATHCL_KERNEL void wavefront_shadow(PATHCL_KERNEL_PARAMS FrameParams frame, __global float* state_words, uint capacity)
{
    PATHCL_KERNEL_DATA;
    uint p = get_global_id(0);
    if (p >= capacity)
        return;
    WavefrontState s = {state_words, capacity};
    float t_max = STATE_F(s, shadow_t_max, p);
    if (!(t_max >= 0.0f))
        return;
    float3 from = (float3)(STATE_F(s, shadow_ox, p), STATE_F(s, shadow_oy, p), STATE_F(s, shadow_oz, p));
    float3 dir = (float3)(STATE_F(s, shadow_dx, p), STATE_F(s, shadow_dy, p), STATE_F(s, shadow_dz, p));
    if (shadow_ray_visibility(&kd, &frame, from, dir, t_max) > 0.0f) {
        STATE_SET_F(s, radiance_r, p, STATE_F(s, radiance_r, p) + STATE_F(s, shadow_r, p));
        STATE_SET_F(s, radiance_g, p, STATE_F(s, radiance_g, p) + STATE_F(s, shadow_g, p));
        STATE_SET_F(s, radiance_b, p, STATE_F(s, radiance_b, p) + STATE_F(s, shadow_b, p));
    }
}

/* Each path's radiance into its pixel (film/film.cl). */
PATHCL_KERNEL void wavefront_film(PATHCL_KERNEL_PARAMS FrameParams frame, __global float* state_words, uint capacity,
                                  uint paths)
{
    PATHCL_KERNEL_DATA;
    uint p = get_global_id(0);
    if (p >= paths)
        return;
    WavefrontState s = {state_words, capacity};
    uint pixel = (uint)STATE_I(s, pixel, p);
    if (!pixel_active(&frame, kd.active, pixel))
        return;
    float3 radiance = (float3)(STATE_F(s, radiance_r, p), STATE_F(s, radiance_g, p), STATE_F(s, radiance_b, p));
    film_add_sample(kd.film, kd.bad_samples, pixel, radiance);
}
