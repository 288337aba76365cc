/* The BSDF at one shading point, for one wo (BsdfParams), and what sampling and
 * evaluation return. bsdf_params (closure/bsdf.cl) fills it from the Material once per
 * shading point, so lobe choices, layer albedos and multiple-scattering scales are
 * computed once, not per evaluation. */
#include "closure/ggx.h"
#include "features.h"
#include "geom/surface_point.cl"
#include "types.h"
#include "util/math.cl"

/* Smallest selection probability estimate of a rough specular or transmission lobe that
 * exists: the estimates come from the macro normal, the lobes from the microfacets. */
#define LOBE_ESTIMATE_FLOOR 0.02f

typedef struct {
    float3 wi;
    float3 weight; /* f cos / pdf */
    float pdf;     /* solid angle; 0: no sample. For a delta lobe: its selection probability */
    float eta2;    /* eta^2 when wi refracted into a solid (the weight holds 1/eta^2), else 1 */
    bool delta;
} BsdfSample;

/* No sample (pdf 0): what a sampler returns before it has one. */
static inline BsdfSample no_bsdf_sample(void)
{
    BsdfSample s;
    s.delta = false;
    s.pdf = 0.0f;
    s.eta2 = 1.0f;
    s.weight = (float3)(0.0f);
    return s;
}

typedef struct {
    float3 f_cos; /* f * |cos theta_i|, non-delta lobes only */
    float pdf;    /* of bsdf_sample producing wi */
} BsdfEval;

/* Lobe selection probabilities for sampling: the diffuse base (with the conductor's
 * multiple-scattering lobe), the conductor's GGX reflection, the dielectric interface
 * (its reflection and refraction, split per facet by interface_split), the sheen and the
 * clear coat. */
typedef struct {
    float diffuse, conductor, interface;
#ifdef PATHCL_HAS_SHEEN
    float sheen; /* the sheen's lobe, sampled uniformly over the hemisphere */
#endif
#ifdef PATHCL_HAS_CLEARCOAT
    float coat; /* the clear coat's reflection, sampled in its own frame */
#endif
} LobeChoice;

/* The material at one shading point, for one wo (textures, when present, are applied
 * here). */
typedef struct {
    float3 base_color;
    float3 specular_color; /* KHR_materials_specular colour */
    float specular;        /* KHR_materials_specular weight */
    float metallic;
    float alpha; /* GGX alpha = roughness^2 */
    float transmission;
    float eta;   /* ior of the side wi refracts into over ior of wo's side (thin: ior) */
    bool thin;   /* thin-walled: transmitted light does not bend */
    bool inside; /* wo is inside a solid: no diffuse base */
#ifdef PATHCL_FULL_BSDF
    float3 f0c;                  /* min(F0(ior) specular_color, 1) */
    float3 diffuse_scale;        /* (1 - metallic)(1 - transmission) base / (pi (1 - E_avg)) */
    float3 layer_o;              /* E(cos_o): the dielectric layer's albedo from wo */
    float cos_o;                 /* wo against the shading normal, >= 0 */
    __global const float* layer; /* LAYER_* tables */
    float layer_r, layer_x;      /* continuous table coordinates of roughness and ior */
    float ess_o;                 /* GGX albedo with Fresnel 1 from wo (rough lobes) */
    float conductor_e_o;         /* ... of the conductor's lobe (anisotropic or ess_o) */
    float3 ms_scale;             /* conductor multiple scattering: metallic F_ms / (pi (1 - E_avg)) */
    float3 ms_albedo;            /* ... and that lobe's albedo from wo, metallic F_ms (1 - ess_o) */
    float glass_scale;           /* 1 / interface albedo: rough refraction loses no energy */
    bool specular_lobes;         /* the GGX lobes can scatter: false for metallic 0,
                                  * transmission 0 and specular 0 (an exactly Lambertian base,
                                  * whose lobes evaluate to 0 and are skipped) */
#ifdef PATHCL_HAS_ANISOTROPY
    float alpha_t, alpha_b; /* the anisotropic lobes' GGX alpha along and across the anisotropy
                             * direction (both alpha when isotropic) */
    float3 tangent;         /* the frame's x axis: the anisotropy direction, in the shading plane */
    float aniso_t, aniso_r; /* continuous E_aniso table coordinates of the roughness along and across */
    bool layer_aniso;       /* the dielectric layer's lobe is anisotropic too (layer_anisotropic) */
    float aniso_x;          /* continuous B_aniso table coordinate of the ior */
#endif
#ifdef PATHCL_HAS_CLEARCOAT
    float coat;       /* clearcoatFactor (0: no coat) */
    float coat_alpha; /* the coat's GGX alpha = clearcoatRoughness^2 */
    float coat_r;     /* its continuous roughness table coordinate */
    float3 coat_n;    /* its normal (SurfacePoint.n_coat) */
    float coat_e_o;   /* coat x the coat's albedo E_c(cos_o): what it reflects from wo */
#endif
#ifdef PATHCL_HAS_SHEEN
    float3 sheen;      /* sheen colour (0: no sheen) */
    float sheen_max;   /* its largest channel, which scales the base */
    float sheen_alpha; /* max(sheenRoughness^2, SHEEN_ALPHA_MIN) */
    float sheen_r;     /* its continuous roughness table coordinate */
    float sheen_e_o;   /* the lobe's albedo E_s(cos_o) with colour 1 (above 1 near grazing) */
#endif
    LobeChoice lobes;
#endif
} BsdfParams;

/* Whether the conductor's GGX lobe is anisotropic (KHR_materials_anisotropy). */
static inline bool bsdf_anisotropic(const BsdfParams* p)
{
#ifdef PATHCL_HAS_ANISOTROPY
    return p->alpha_b != p->alpha_t;
#else
    return false;
#endif
}

/* Whether the conductor's lobe is rough (else an ideal mirror): anisotropy can make a
 * smooth conductor rough along one direction. */
static inline bool conductor_rough(const BsdfParams* p)
{
#ifdef PATHCL_HAS_ANISOTROPY
    return p->alpha_t >= ALPHA_DELTA;
#else
    return p->alpha >= ALPHA_DELTA;
#endif
}

/* Whether the dielectric layer's GGX lobe is anisotropic with the conductor's alphas: on
 * every anisotropic material but a solid that transmits (its interface, reflection and
 * refraction alike, keeps the isotropic alpha; see closure/bsdf.cl) and ior 0. */
static inline bool layer_anisotropic(const BsdfParams* p)
{
#ifdef PATHCL_HAS_ANISOTROPY
    return p->layer_aniso;
#else
    return false;
#endif
}

/* Whether the dielectric interface's lobes are rough (else delta functions). */
static inline bool interface_rough(const BsdfParams* p)
{
    return layer_anisotropic(p) || p->alpha >= ALPHA_DELTA;
}

/* Every lobe of the material is a delta function: light sampling cannot help there. */
static inline bool bsdf_is_delta(const BsdfParams* p)
{
#ifdef PATHCL_FULL_BSDF
    bool delta = p->alpha < ALPHA_DELTA && (1.0f - p->metallic) * (1.0f - p->transmission) == 0.0f;
#ifdef PATHCL_HAS_ANISOTROPY
    delta = delta && !(p->metallic > 0.0f && conductor_rough(p)) && !(p->metallic < 1.0f && layer_anisotropic(p));
#endif
#ifdef PATHCL_HAS_CLEARCOAT
    delta = delta && !(p->coat > 0.0f && p->coat_alpha >= ALPHA_DELTA);
#endif
#ifdef PATHCL_HAS_SHEEN
    delta = delta && !(p->sheen_max > 0.0f);
#endif
    return delta;
#else
    return false;
#endif
}

/* Whether the BSDF is its diffuse lobe alone, chosen with probability 1: an exactly
 * Lambertian material (no metal, no specular layer, no transmission; no coat, no sheen,
 * no anisotropic frame) whose base colour is not black. Evaluating and sampling it through
 * every lobe's code (closure/bsdf_eval.cl, bsdf_sample.cl) computes, term for term, the
 * diffuse lobe and zeros; the Lambertian shortcut there computes the same values. */
static inline bool bsdf_lambertian(const BsdfParams* p)
{
#ifdef PATHCL_FULL_BSDF
    bool lambertian = !p->specular_lobes && p->lobes.diffuse == 1.0f;
#ifdef PATHCL_HAS_ANISOTROPY
    lambertian = lambertian && !bsdf_anisotropic(p);
#endif
#ifdef PATHCL_HAS_CLEARCOAT
    lambertian = lambertian && !(p->coat > 0.0f);
#endif
#ifdef PATHCL_HAS_SHEEN
    lambertian = lambertian && !(p->sheen_max > 0.0f);
#endif
    return lambertian;
#else
    return true;
#endif
}

/* The shading frame of the base material's lobes around sp->ns: t along the anisotropy
 * direction for an anisotropic material, any other frame (make_basis) otherwise. */
static inline void bsdf_frame(const BsdfParams* p, const SurfacePoint* sp, float3* t, float3* b)
{
#ifdef PATHCL_HAS_ANISOTROPY
    if (bsdf_anisotropic(p)) {
        *t = p->tangent;
        *b = cross(sp->ns, p->tangent);
        return;
    }
#endif
    make_basis(sp->ns, t, b);
}
