/* Next event estimation: one shadow ray to a point on a light picked in proportion to its
 * power, its contribution weighted against BSDF sampling of the same direction. */
#include "closure/bsdf.cl"
#include "features.h"
#include "geom/ray_offset.cl"
#include "integrator/absorption.cl"
#include "integrator/intersect_shadow.cl"
#include "integrator/mis.cl"
#include "integrator/path_state.cl"
#include "integrator/shade_surface.cl"
#include "kernel_data.cl"
#include "light/light_sample.cl"
#include "sample/dimensions.h"
#include "util/math.cl"

#ifdef PATHCL_HAS_LIGHTS

/* Whether the render samples lights at all (there are some, and the strategy is not BSDF
 * sampling alone). */
static inline bool frame_samples_lights(const FrameParams* frame)
{
    return frame->light_count > 0u && frame->strategy != STRATEGY_BSDF;
}

/* Whether the strategy samples a light at this vertex (never where every lobe is a delta
 * function: no light sample can land in one). */
static inline bool direct_light_wanted(const FrameParams* frame, const ShadingPoint* s, bool technique_light)
{
    return frame_samples_lights(frame) && (frame->strategy != STRATEGY_ONE_SAMPLE || technique_light) &&
           !bsdf_is_delta(&s->bsdf);
}

/* The light the bounce whose decisions start at sampler dimension `dims` samples (its
 * DIM_LIGHT decisions), for the shading point ref with normal n (which only the light
 * tree reads). */
static inline LightChoice direct_light_choose(const KernelData* kd, const FrameParams* frame, uint dims, float3 ref,
                                              float3 n, SamplerState* sampler)
{
    sampler->dimension = dims + DIM_LIGHT;
    return light_choose(kd, frame, ref, n, sampler);
}

/* Adds the contribution of a sample of the chosen light to the path's radiance. */
static inline void direct_light(const KernelData* kd, const FrameParams* frame, PathState* ps, const ShadingPoint* s,
                                float3 wo, bool technique_light, const LightChoice* choice)
{
    const SurfacePoint* sp = &s->sp;
    LightSample ls = light_sample_chosen(kd, choice, light_sample_origin(sp));
    if (!(ls.pdf > 0.0f))
        return;
    BsdfEval e = bsdf_eval(&s->bsdf, sp, wo, ls.wi);
    if (!(max3(e.f_cos) > 0.0f))
        return;
    /* The shadow ray's segment: unbounded towards a directional light, else up to just
     * short of the light point (offset off an area light's surface so the light itself
     * never blocks). */
    float3 from = spawn_ray_origin(sp, ls.wi);
    float3 shadow_dir = ls.wi;
    float shadow_t_max = INFINITY;
    if (!ls.at_infinity) {
        float3 to = ls.delta ? ls.p : offset_ray_origin(ls.p, ls.p_error, ls.n, -ls.wi);
        shadow_dir = to - from;
        shadow_t_max = SHADOW_RAY_EXTENT;
    }
    float visibility = shadow_ray_visibility(kd, frame, from, shadow_dir, shadow_t_max);
    if (!(visibility > 0.0f))
        return;
#ifdef PATHCL_HAS_ALPHA
    ls.radiance *= visibility; /* the light left behind alpha-blended surfaces */
#endif
#ifdef PATHCL_HAS_VOLUME_ABSORPTION
    /* Absorbed on the way when the shadow ray runs inside a solid. */
    ls.radiance *=
        medium_transmittance(kd, medium_after(ps->medium, s, ls.wi), ls.at_infinity ? INFINITY : length(shadow_dir));
#endif
    /* BSDF sampling never finds a delta light: its BSDF pdf is 0 there. */
    float bsdf_pdf = ls.delta ? 0.0f : e.pdf;
    ps->radiance +=
        ps->beta * e.f_cos * ls.radiance * light_sample_factor(frame->strategy, technique_light, ls.pdf, bsdf_pdf);
}

#endif /* PATHCL_HAS_LIGHTS */
