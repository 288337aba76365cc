/* The material model: glTF's metallic-roughness BSDF at a shading point (bsdf_params),
 * evaluated by closure/bsdf_eval.cl and sampled by closure/bsdf_sample.cl, which dispatch
 * to one file per lobe: diffuse, conductor, specular (the GGX reflection the conductor and
 * the dielectric layer share), dielectric, sheen and coat.
 *
 * Directions are world-space unit vectors; wo points away from the surface, towards the
 * previous vertex. The shading point has ng and ns on wo's side. A direction is reflected
 * only if it lies above the shading surface and above the geometric one (or the point
 * is lifted onto the smooth surface, see above_surface in geom/ray_offset.cl), and transmitted
 * only if it lies below both: that keeps shading normals from leaking light through
 * geometry.
 *
 * The material model is glTF's metallic-roughness BSDF (glTF 2.0 appendix B) with
 * KHR_materials_specular, _transmission, _ior and _volume (and _clearcoat and _sheen, below):
 *
 *   f = metallic       * F_schlick(base_color, wo.h) * spec
 *     + (1 - metallic) * [ F_d(wo.h) * spec
 *                          + (1 - transmission) * base_color / pi * K(wo, wi)
 *                          + transmission * (1 - max(F_d(wo.h))) * base_color * btdf ]
 *
 * spec is the GGX microfacet reflection D G / (4 |cos_o| |cos_i|) with alpha = roughness^2
 * and separable Smith G = G1(wo) G1(wi); btdf is Walter et al.'s rough dielectric
 * transmission (a solid, KHR_materials_volume thickness > 0) or the reflection lobe
 * mirrored through the surface (thin-walled: light passes without bending). The
 * dielectric Fresnel term follows KHR_materials_specular, with the exact dielectric
 * Fresnel curve in place of Schlick's (1 - c)^5, so total internal reflection is exact:
 *
 *   F_d(c) = specular * (F0c + (1 - F0c) s(c)),  F0c = min(F0(ior) * specular_color, 1),
 *   s(c) = (F_exact(c, eta) - F0) / (1 - F0)   (0 at normal incidence, 1 at grazing/TIR)
 *
 * With specular_color 1 this is specular * F_exact; with specular 0 a dielectric is
 * exactly Lambertian. Below alpha ALPHA_DELTA the specular lobes are delta functions
 * (ideal mirror and glass): sampled, never evaluated, so no light sampling at such lobes.
 *
 * The diffuse base under the dielectric layer gets what the layer does not reflect, by
 * reciprocal albedo scaling (Kelemen and Szirmay-Kalos 2001):
 *
 *   K(wo, wi) = (1 - E(cos_o)) (1 - E(cos_i)) / (1 - E_avg)
 *
 * with E the layer's directional albedo (tabulated, see closure/layer_table.h; the
 * exact Fresnel curve for a smooth layer) and E_avg its cosine-weighted average. glTF's
 * own weight (1 - max(F_d(wo.h))) is not energy-conserving: a white rough plastic then
 * reflects up to 1.3 times the light it receives at grazing incidence. With K a white
 * plastic reflects exactly all of it (f is reciprocal, and the diffuse albedo from wo is
 * base_color (1 - E(cos_o))). Inside a solid there is no diffuse base.
 *
 * Multiple scattering between microfacets, which single-scattering GGX drops (a white
 * rough metal or glass would lose up to ~20 % of the light), is restored: conductors get
 * Kulla and Conty's (2017) reciprocal lobe F_ms (1 - E_ss(cos_o))(1 - E_ss(cos_i)) /
 * (pi (1 - E_ss_avg)); a rough dielectric interface with the exact Fresnel factor has its
 * reflection and refraction divided by its energy albedo G(cos_o) from the side of wo
 * (Turquin 2019; tabulated, LAYER_TABLE_GLASS_*). FEATURE_SINGLE_SCATTERING turns this
 * off (pbrt's and Mitsuba's model, for cross-checks).
 *
 * KHR_materials_clearcoat puts a dielectric coat of ior 1.5 over all of this: a GGX
 * reflection lobe with the exact Fresnel curve, its own roughness and its own normal (the
 * interpolated one, which the base's normal map does not bend, bent by the coat's own
 * clearcoatNormalTexture), weighted by clearcoatFactor c. The base keeps what the coat
 * does not reflect, as a reciprocal albedo scaling:
 *
 *   f = c F_c(wo.h_c) spec_c + (1 - c max(E_c(cos_o), E_c(|cos_i|))) f_base
 *
 * with E_c the coat's directional albedo (the B table at ior 1.5). The extension's own
 * weight 1 - c F(cos_o) is not reciprocal; with max the coat and base together reflect at
 * most what the base alone would, exactly so at the mirror direction, and a white
 * Lambertian base under a smooth full coat reflects 0.948 of the light at normal
 * incidence (the internal reflections that would return the rest are not modelled).
 * Inside a solid the coat reflects nothing but still scales the base, so transmission
 * stays reciprocal.
 *
 * KHR_materials_sheen puts a layer of fibres between the coat and the base: the "Charlie"
 * lobe of closure/sheen.h, coloured by sheen colour s, on the shading normal, with the
 * extension's reciprocal albedo scaling of the base:
 *
 *   f_under_coat = s sheen(wo, wi) / max(1, E_s(cos_o), E_s(|cos_i|))
 *                + (1 - max3(s) min(1, max(E_s(cos_o), E_s(|cos_i|)))) f_base
 *
 * with E_s the lobe's directional albedo (tabulated, LAYER_TABLE_SHEEN). As the extension
 * writes it the lobe reflects up to 8x what it receives at grazing angles for smooth
 * sheens (E_s > 1); the division keeps it reciprocal and its albedo at most 1, and is 1
 * wherever E_s <= 1. It reflects only from outside a solid but scales the base from both
 * sides, as the coat does.
 *
 * KHR_materials_anisotropy makes the GGX lobes anisotropic in the frame of bsdf_frame (x
 * along the direction texture/anisotropy.cl finds): alpha_t = mix(alpha, 1, strength^2)
 * along it, alpha_b = max(alpha, ALPHA_DELTA) across. The conductor's Kulla-Conty lobe
 * reads the anisotropic albedo E_aniso over cos theta x azimuth x both roughnesses
 * (LAYER_TABLE_ANISO), with which a white brushed metal reflects 0.995 to 1.002 of the
 * light (an isotropic table read at any one roughness gained up to 1.3 % at grazing
 * angles). The dielectric layer shares the anisotropic lobe (layer_anisotropic), and its
 * albedo E for the diffuse base's scaling is f0 (E_aniso - B_aniso) + B_aniso, B_aniso
 * over the ior as well (LAYER_TABLE_ANISO_B); a thin sheet's lobe pair is divided by
 * E_aniso. A white brushed plastic reflects 0.9987 to 1.0035 of the light. A solid that
 * transmits keeps the isotropic alpha on its whole interface: its refraction's
 * compensation would need the interface albedo over both roughnesses, the azimuth and the
 * ior from both sides, and no isotropic reading stands in for it.
 *
 * Sampling picks the diffuse base (with the multiple-scattering lobe), the conductor or
 * the interface with probabilities estimated from their albedos at the macro normal
 * (computed once per shading point by bsdf_params); the GGX lobes sample a visible
 * facet (Dupuy and Benyoub 2023), and the interface then reflects or refracts by that
 * facet's own energy split (as pbrt does), so refraction under the macro critical angle
 * is still sampled well. The weight is f cos / pdf with f and pdf summed over every
 * non-delta lobe: exactly what bsdf_eval returns, divided by its pdf.
 *
 * Scenes whose materials are all Lambertian compile only the Lambertian code (no
 * PATHCL_HAS_GLOSSY / PATHCL_HAS_TRANSMISSION): they pay nothing for the rest. */
#include "closure/bsdf_eval.cl"
#include "closure/bsdf_params.cl"
#include "closure/bsdf_sample.cl"
#include "closure/layer_albedo.cl"
#include "closure/layer_table.h"
#include "closure/lobes.cl"
#include "closure/sheen.h"
#include "features.h"
#include "geom/surface_point.cl"
#include "types.h"
#include "util/math.cl"

#ifdef PATHCL_FULL_BSDF

/* wo in the frame of bsdf_frame where the material is anisotropic (its (x, y) then read
 * the anisotropic tables); (0, 0, cos_o) otherwise. */
static inline float3 bsdf_wo_local(const BsdfParams* p, const SurfacePoint* sp, float3 wo)
{
#ifdef PATHCL_HAS_ANISOTROPY
    if (bsdf_anisotropic(p)) {
        float3 t, b;
        bsdf_frame(p, sp, &t, &b);
        return (float3)(dot(wo, t), dot(wo, b), p->cos_o);
    }
#endif
    return (float3)(0.0f, 0.0f, p->cos_o);
}

/* The last part of bsdf_params: the dielectric layer's albedo from wo (wo_l:
 * bsdf_wo_local), the diffuse base's scale under it and the lobe choice, from the fields
 * before them. */
static inline void bsdf_params_base(BsdfParams* p, const Material* m, float3 wo_l)
{
    float3 layer_avg;
#ifdef PATHCL_HAS_ANISOTROPY
    if (layer_anisotropic(p)) {
        p->layer_o = aniso_layer_albedo(p, wo_l); /* never inside: the layer is on no solid */
        layer_avg = aniso_layer_average(p);
    } else
#endif
    {
        p->layer_o = p->inside ? (float3)(0.0f) : layer_albedo(p, p->cos_o);
        layer_avg = layer_average(p, m);
    }
    float3 one_minus_avg = 1.0f - layer_avg;
    float w = p->inside ? 0.0f : (1.0f - p->metallic) * (1.0f - p->transmission) * INV_PI;
    /* A layer that reflects everything on average leaves the base nothing (and 0 / 0). */
    p->diffuse_scale =
        select((float3)(0.0f), p->base_color * w / one_minus_avg, isgreater(one_minus_avg, (float3)(1e-6f)));
    p->lobes = choose_lobes(p);
}

/* No clear coat and no sheen (their factor and colour 0): the base's lobes alone. */
static inline bool bsdf_no_coat_no_sheen(const BsdfParams* p)
{
    bool none = true;
#ifdef PATHCL_HAS_CLEARCOAT
    none = none && p->coat == 0.0f;
#endif
#ifdef PATHCL_HAS_SHEEN
    none = none && all(p->sheen == (float3)(0.0f));
#endif
    return none;
}

/* A choice among the base's lobes; the sheen and the coat are never chosen. */
static inline LobeChoice base_lobe_choice(float diffuse, float conductor, float interface)
{
    LobeChoice c;
    c.diffuse = diffuse;
    c.conductor = conductor;
    c.interface = interface;
#ifdef PATHCL_HAS_SHEEN
    c.sheen = 0.0f;
#endif
#ifdef PATHCL_HAS_CLEARCOAT
    c.coat = 0.0f;
#endif
    return c;
}

/* Whether bsdf_params_base_diffuse may stand in for bsdf_params_base: metal, transmission
 * and specular 0 (no layer: its albedo is 0 whether or not the material is anisotropic),
 * no coat, no sheen, and a base colour whose components are finite, not negative and not
 * all 0 (so that every lobe but the diffuse one is estimated +0 and the diffuse one d / d). */
static inline bool bsdf_params_diffuse_only(const BsdfParams* p)
{
    float d = mean3(p->base_color);
    bool diffuse_only = p->metallic == 0.0f && p->transmission == 0.0f && !(p->specular > 0.0f) &&
                        all(p->base_color >= (float3)(0.0f)) && d > 0.0f && isfinite(d);
    return diffuse_only && bsdf_no_coat_no_sheen(p);
}

/* bsdf_params_base where bsdf_params_diffuse_only holds: the values its general code
 * computes there, term for term (no layer, w = 1 x 1 x 1 / pi over 1 - 0, the diffuse lobe
 * chosen with probability 1; tested bit for bit), without its table lookups, Fresnel
 * estimates and divisions (a Lambertian wall in a program with glossy code). */
static inline void bsdf_params_base_diffuse(BsdfParams* p)
{
    p->layer_o = (float3)(0.0f);
    p->diffuse_scale = p->base_color * INV_PI;
    p->lobes = base_lobe_choice(1.0f, 0.0f, 0.0f);
}

/* Whether bsdf_params_base_ideal may stand in for bsdf_params_base: an ideal mirror
 * (metallic 1, transmission 0) or ideal glass, solid or thin (metallic 0, transmission 1),
 * whose lobes are all delta functions (bsdf_is_delta), with no coat and no sheen, and a base
 * colour finite and not negative; glass's base colour at most 1 and its mean at least
 * 2^-100. Then the general code's lobe estimates are +0 but the one lobe's: the mirror's
 * Schlick mean, and glass's mean(F) + (1 - max(F)) mean(base), F in [0, 1] (to a rounding),
 * which those bounds keep positive. */
static inline bool bsdf_params_ideal_only(const BsdfParams* p)
{
    float d = mean3(p->base_color);
    bool mirror = p->metallic == 1.0f && p->transmission == 0.0f;
    bool glass =
        p->metallic == 0.0f && p->transmission == 1.0f && all(p->base_color <= (float3)(1.0f)) && d >= 0x1.0p-100f;
    return (mirror || glass) && bsdf_is_delta(p) && all(p->base_color >= (float3)(0.0f)) && isfinite(d) &&
           bsdf_no_coat_no_sheen(p);
}

/* bsdf_params_base where bsdf_params_ideal_only holds: the lobe choice its general code
 * makes there, bit for bit (the one lobe's estimate over itself, the others +0 over it;
 * tested), without the layer's albedo, the Fresnel estimate of the interface and the
 * normalizing divisions (every hit on the glass and mirror box's sphere and block). The
 * layer's albedo and the diffuse scale are set to 0: only bsdf_eval reads them, and
 * next event estimation evaluates no BSDF whose lobes are all delta functions. */
static inline void bsdf_params_base_ideal(BsdfParams* p)
{
    p->layer_o = (float3)(0.0f);
    p->diffuse_scale = (float3)(0.0f);
    if (p->metallic == 1.0f) {
        float e = mean3(fresnel_schlick(p->base_color, p->cos_o)); /* 0 for black at normal incidence */
        p->lobes = base_lobe_choice(0.0f, e > 0.0f ? e / e : e, 0.0f);
    } else {
        p->lobes = base_lobe_choice(0.0f, 0.0f, 1.0f);
    }
}

#endif /* PATHCL_FULL_BSDF */

/* The BSDF at a shading point seen from wo. layer: the LAYER_* tables. */
static inline BsdfParams bsdf_params(const Material* m, const SurfacePoint* sp, float3 wo, __global const float* layer)
{
    BsdfParams p;
    p.base_color = m->base_color.xyz;
    p.specular_color = m->specular_color.xyz;
    p.specular = m->specular_color.w;
    p.metallic = m->metallic;
    p.alpha = m->roughness * m->roughness;
    p.transmission = m->transmission;
    p.thin = (m->flags & MATERIAL_THIN_WALLED) != 0u;
    /* A solid's geometric normal points out of it: a back-face hit is from inside. */
    p.inside = !p.thin && !sp->front_face && m->transmission > 0.0f;
    p.eta = p.inside ? 1.0f / m->ior : m->ior;
#ifdef PATHCL_FULL_BSDF
#ifdef PATHCL_HAS_ANISOTROPY
    p.alpha_t = p.alpha_b = p.alpha;
    p.layer_aniso = false;
    if (m->anisotropy.x > 0.0f) {
        /* KHR_materials_anisotropy: the conductor's alpha along the direction grows
         * towards 1; across it alpha_b (the material's own) is kept clear of 0 so that D
         * stays finite. */
        float s = m->anisotropy.x;
        p.alpha_t = mix(p.alpha, 1.0f, s * s);
        p.alpha_b = ggx_anisotropic_alpha_b(p.alpha, p.alpha_t);
        p.aniso_t = sqrt(p.alpha_t) * (float)(LAYER_ANISO_T_RES - 1);
        p.aniso_r = m->roughness * (float)(LAYER_ANISO_ROUGH_RES - 1);
        float3 t = sp->t_aniso - dot(sp->t_aniso, sp->ns) * sp->ns;
        float len = length(t);
        float3 b;
        if (len > 1.0e-6f)
            p.tangent = t / len;
        else
            make_basis(sp->ns, &p.tangent, &b); /* no tangent frame: some direction */
        /* The dielectric layer shares the anisotropic lobe, but not on a transmitting solid
         * (its refraction's compensation would need the interface albedo over both
         * roughnesses, the azimuth and the ior, from both sides) nor at ior 0 (Schlick's
         * curve has no anisotropic table). */
        p.layer_aniso = bsdf_anisotropic(&p) && !(p.transmission > 0.0f && !p.thin) && m->ior != 0.0f;
    }
#endif
    float r = (m->ior - 1.0f) / (m->ior + 1.0f);
    p.f0c = fmin(r * r * p.specular_color, (float3)(1.0f));
    p.layer = layer;
    p.layer_r = m->roughness * (float)(LAYER_ROUGH_RES - 1);
    p.layer_x = clamp(r / LAYER_X_MAX, 0.0f, 1.0f) * (float)(LAYER_ETA_RES - 1);
    p.cos_o = clamp(dot(wo, sp->ns), 0.0f, 1.0f);
    p.glass_scale = 1.0f;
    p.specular_lobes = p.metallic > 0.0f || p.transmission > 0.0f || p.specular > 0.0f;
    p.ms_scale = p.ms_albedo = (float3)(0.0f);
    p.ess_o = p.conductor_e_o = 1.0f;
    float3 wo_l = bsdf_wo_local(&p, sp, wo);
#ifdef PATHCL_HAS_ANISOTROPY
    if (bsdf_anisotropic(&p))
        p.aniso_x = sqrt(clamp(r / LAYER_X_MAX, 0.0f, 1.0f)) * (float)(LAYER_ANISO_ETA_RES - 1);
#endif
#ifndef PATHCL_SINGLE_SCATTERING
    /* Energy lost to masking, restored (multiple-scattering compensation). */
    if (p.alpha >= ALPHA_DELTA && p.specular_lobes)
        p.ess_o = ess_albedo(&p, p.cos_o);
    /* A rough interface with the exact Fresnel factor (specular 1, white specular colour)
     * loses 1 - G(cos_o); its lobes are divided by G, as Turquin (2019) does. A thin
     * sheet's lobe pair has the reflection lobe's albedo (E_ss, or the anisotropic one). */
    bool exact_fresnel = p.specular == 1.0f && all(p.specular_color == (float3)(1.0f));
    if (interface_rough(&p) && p.transmission > 0.0f && exact_fresnel) {
        float g = p.thin ? p.ess_o : interface_albedo(&p, p.cos_o);
#ifdef PATHCL_HAS_ANISOTROPY
        if (p.thin && layer_anisotropic(&p))
            g = aniso_albedo(&p, wo_l);
#endif
        p.glass_scale = g > 1e-3f ? 1.0f / g : 1.0f;
    }
    if (conductor_rough(&p) && p.metallic > 0.0f) {
        /* Kulla and Conty 2017 with Schlick's average F_avg = F0 + (1 - F0) / 21. */
        float e_avg;
#ifdef PATHCL_HAS_ANISOTROPY
        if (bsdf_anisotropic(&p)) {
            p.conductor_e_o = aniso_albedo(&p, wo_l);
            e_avg = aniso_albedo_average(&p);
        } else
#endif
        {
            p.conductor_e_o = p.ess_o;
            int r0 = min((int)p.layer_r, LAYER_ROUGH_RES - 2);
            e_avg = mix(layer[LAYER_TABLE_ESS_AVG + r0], layer[LAYER_TABLE_ESS_AVG + r0 + 1], p.layer_r - (float)r0);
        }
        float3 f_avg = p.base_color + (1.0f - p.base_color) * (1.0f / 21.0f);
        float3 f_ms = f_avg * f_avg * e_avg / (1.0f - f_avg * (1.0f - e_avg));
        if (1.0f - e_avg > 1e-4f) { /* else the loss is below 1e-4: nothing to restore */
            p.ms_scale = p.metallic * f_ms * INV_PI / (1.0f - e_avg);
            p.ms_albedo = p.metallic * f_ms * (1.0f - p.conductor_e_o);
        }
    }
#endif
#ifdef PATHCL_HAS_CLEARCOAT
    p.coat = m->clearcoat;
    p.coat_alpha = m->clearcoat_roughness * m->clearcoat_roughness;
    p.coat_r = m->clearcoat_roughness * (float)(LAYER_ROUGH_RES - 1);
    p.coat_n = sp->n_coat;
    p.coat_e_o = p.coat > 0.0f ? p.coat * coat_albedo(&p, clamp(dot(wo, p.coat_n), 0.0f, 1.0f)) : 0.0f;
#endif
#ifdef PATHCL_HAS_SHEEN
    p.sheen = m->sheen.xyz;
    p.sheen_max = max3(p.sheen);
    p.sheen_alpha = fmax(m->sheen.w * m->sheen.w, SHEEN_ALPHA_MIN);
    p.sheen_r = m->sheen.w * (float)(LAYER_ROUGH_RES - 1);
    p.sheen_e_o = p.sheen_max > 0.0f ? sheen_albedo(&p, p.cos_o) : 0.0f;
#endif
    if (bsdf_params_diffuse_only(&p))
        bsdf_params_base_diffuse(&p);
    else if (bsdf_params_ideal_only(&p))
        bsdf_params_base_ideal(&p);
    else
        bsdf_params_base(&p, m, wo_l);
#endif
    return p;
}
