/* A path's hit on a surface: the surface point, the material with its per-hit inputs,
 * the BSDF seen from wo, and the surface's own emission, weighted against light sampling
 * when a BSDF sample found it. */
#include "bvh/traversal.cl"
#include "closure/bsdf.cl"
#include "features.h"
#include "geom/surface_point.cl"
#include "integrator/mis.cl"
#include "integrator/path_state.cl"
#include "kernel_data.cl"
#include "light/light_sample.cl"
#include "light/triangle.cl"
#include "texture/anisotropy.cl"
#include "texture/material_inputs.cl"

/* Everything shading knows about a hit. */
typedef struct {
    SurfacePoint sp;
    Material material; /* the triangle's material with its textures and vertex colour applied */
    BsdfParams bsdf;
} ShadingPoint;

static inline ShadingPoint shade_surface_setup(const KernelData* kd, Hit hit, float3 wo)
{
    ShadingPoint s;
    s.sp = surface_point(kd, hit, wo);
    s.material = kd->materials[s.sp.material];
#ifdef PATHCL_HAS_MATERIAL_INPUTS
    apply_material_inputs(&s.material, &s.sp, wo, hit, kd);
#endif
#ifdef PATHCL_HAS_ANISOTROPY
    apply_anisotropy(&s.material, &s.sp, hit, kd);
#endif
    s.bsdf = bsdf_params(&s.material, &s.sp, wo, kd->layer_albedo);
    return s;
}

/* Emission leaves the front face only. */
static inline void shade_surface_emission(const KernelData* kd, const FrameParams* frame, PathState* ps,
                                          const ShadingPoint* s, Hit hit, float3 wo)
{
#ifdef PATHCL_HAS_AREA_LIGHTS
    if (s->sp.front_face && s->sp.emitter >= 0) {
        float3 le = s->material.emission.xyz;
        if (ps->prev_delta) {
            ps->radiance += ps->beta * le;
        } else {
            Light light = kd->lights[s->sp.emitter];
#ifdef PATHCL_LIGHT_TREE
            float pmf = light_pick_pmf(kd, frame, ps->prev_ref, ps->prev_n, s->sp.emitter);
#else
            float pmf = kd->light_distribution[s->sp.emitter].pmf;
#endif
#ifdef PATHCL_KEEPS_PREV_REF
            float light_pdf = triangle_light_pdf_from(&light, pmf, ps->prev_ref, hit.t, dot(s->sp.ng, wo));
#else
            float light_pdf = triangle_light_pdf(&light, pmf, hit.t, dot(s->sp.ng, wo));
#endif
            ps->radiance +=
                ps->beta * le * bsdf_hit_weight(frame->strategy, ps->prev_technique_bsdf, ps->prev_bsdf_pdf, light_pdf);
        }
    }
#endif
}

#ifdef PATHCL_HAS_UNLIT
/* KHR_materials_unlit: the base colour (with its texture and vertex colour) is radiance
 * that the camera sees, directly or through mirrors and smooth glass (a chain of delta
 * bounces); it lights nothing else (it is no light, and a path that reaches it after a
 * rough bounce gets nothing), scatters nothing, and blocks light like any surface. Only
 * its front face shows it, unless it is double-sided. True: the path ends here. */
static inline bool shade_unlit(PathState* ps, const ShadingPoint* s)
{
    if (!(s->material.flags & MATERIAL_UNLIT))
        return false;
    bool seen = s->sp.front_face || (s->material.flags & MATERIAL_DOUBLE_SIDED);
    if (ps->specular_chain && seen)
        ps->radiance += ps->beta * s->material.base_color.xyz;
    return true;
}
#endif

/* A single-sided opaque surface seen from behind is black but still blocks light. A
 * transmissive one is an interface from both sides: a solid's back face is its inside, a
 * thin sheet lets light through either way. */
static inline bool surface_scatters(const ShadingPoint* s)
{
    return s->sp.front_face || (s->material.flags & MATERIAL_DOUBLE_SIDED) || s->material.transmission > 0.0f;
}
