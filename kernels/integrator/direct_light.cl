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
#include "light/light_record_warm.cl"
#include "light/light_sample.cl"
#include "sample/dimensions.h"
#include "util/math.cl"
#include "util/prefetch.cl"

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

/* Adds to *radiance the contribution of a sample of the chosen light, seen from the
 * vertex s with throughput beta, inside `medium` (-1 where the scene has no absorption). */
static inline void direct_light_add(const KernelData* kd, const FrameParams* frame, float3 beta, int medium,
                                    const ShadingPoint* s, float3 wo, bool technique_light, const LightChoice* choice,
                                    float3* radiance)
{
    const SurfacePoint* sp = &s->sp;
    if (choice->light >= 0 && frame->light_count >= LIGHT_SHADOW_LEAF_WARM_MIN_LIGHTS)
        light_shadow_leaf_warm(kd, choice->light); /* read at the shadow ray's end */
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
        medium_transmittance(kd, medium_after(medium, s, ls.wi), ls.at_infinity ? INFINITY : length(shadow_dir));
#endif
    /* BSDF sampling never finds a delta light: its BSDF pdf is 0 there. */
    float bsdf_pdf = ls.delta ? 0.0f : e.pdf;
    *radiance += beta * e.f_cos * ls.radiance * light_sample_factor(frame->strategy, technique_light, ls.pdf, bsdf_pdf);
}

#ifdef PATHCL_HAS_VOLUME_ABSORPTION
#define PATH_MEDIUM(ps) ((ps)->medium)
#else
#define PATH_MEDIUM(ps) (-1)
#endif

/* Adds the contribution of a sample of the chosen light to the path's radiance. */
static inline void direct_light(const KernelData* kd, const FrameParams* frame, PathState* ps, const ShadingPoint* s,
                                float3 wo, bool technique_light, const LightChoice* choice)
{
    direct_light_add(kd, frame, ps->beta, PATH_MEDIUM(ps), s, wo, technique_light, choice, &ps->radiance);
}

/* With the light tree, which picks at the hit (it weighs the lights as seen from there),
 * and where the compiler can prefetch, the megakernel takes the light's sample one
 * traversal later: it picks, prefetches the picked light's record and traces the path's
 * next ray, and only then samples the light and traces its shadow ray, so that the record,
 * rarely cached among many lights, arrives during the traversal. The sample is added to
 * the radiance right after that traversal, before anything the next vertex adds: the sum,
 * and so the image, stay the same bit for bit. The power table's pick at the hit (where
 * lobes are not all Lambertian) is not deferred: on the committed scenes, whose few
 * records stay cached, copying the vertex cost more than it saved. */
#if defined(PATHCL_LIGHT_TREE) && defined(PATHCL_PREFETCH)
#define PATHCL_DEFERRED_LIGHT_SAMPLE

/* A vertex's light sample waiting for the next traversal: what direct_light reads of the
 * vertex and the path there. */
typedef struct {
    ShadingPoint s;
    float3 wo, beta;
    int medium;
    bool technique_light;
    LightChoice choice;
} DeferredLightSample;

static inline void direct_light_defer(const KernelData* kd, const PathState* ps, const ShadingPoint* s, float3 wo,
                                      bool technique_light, const LightChoice* choice, DeferredLightSample* deferred)
{
    if (choice->light >= 0)
        light_record_warm(kd, choice->light);
    deferred->s = *s;
    deferred->wo = wo;
    deferred->beta = ps->beta;
    deferred->medium = PATH_MEDIUM(ps);
    deferred->technique_light = technique_light;
    deferred->choice = *choice;
}

static inline void direct_light_deferred(const KernelData* kd, const FrameParams* frame,
                                         const DeferredLightSample* deferred, PathState* ps)
{
    direct_light_add(kd, frame, deferred->beta, deferred->medium, &deferred->s, deferred->wo, deferred->technique_light,
                     &deferred->choice, &ps->radiance);
}
#endif

#endif /* PATHCL_HAS_LIGHTS */
