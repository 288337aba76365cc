/* BSDFs: evaluation, sampling and pdf. Needs: shared_types.h, samplers.cl, geometry.cl.
 *
 * Directions are world-space unit vectors; wo points away from the surface, towards the
 * previous vertex. The shading point has ng and ns on wo's side. A direction is reflected
 * only if it lies above the shading surface and above the geometric one (or the point
 * is lifted onto the smooth surface, see above_surface in geometry.cl), and transmitted
 * only if it lies below both: that keeps shading normals from leaking light through
 * geometry.
 *
 * The material model is glTF's metallic-roughness BSDF (glTF 2.0 appendix B) with
 * KHR_materials_specular, _transmission, _ior and _volume:
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
 * with E the layer's directional albedo (tabulated, see LAYER_* in shared_types.h; the
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
 * (Turquin 2019; tabulated, LAYER_TABLE_GLASS_*). -DPATHCL_SINGLE_SCATTERING turns this
 * off (pbrt's and Mitsuba's model, for cross-checks).
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

/* GGX alpha below which the specular lobes are delta functions (pbrt-v4 uses the same). */
#define ALPHA_DELTA 1.0e-3f
/* Smallest selection probability estimate of a rough specular or transmission lobe that
 * exists: the estimates come from the macro normal, the lobes from the microfacets. */
#define LOBE_ESTIMATE_FLOOR 0.02f

#if defined(PATHCL_HAS_GLOSSY) || defined(PATHCL_HAS_TRANSMISSION)
#define PATHCL_FULL_BSDF
#endif

typedef struct {
    float3 wi;
    float3 weight; /* f cos / pdf */
    float pdf;     /* solid angle; 0: no sample. For a delta lobe: its selection probability */
    float eta2;    /* eta^2 when wi refracted into a solid (the weight holds 1/eta^2), else 1 */
    bool delta;
} BsdfSample;

typedef struct {
    float3 f_cos; /* f * |cos theta_i|, non-delta lobes only */
    float pdf;    /* of bsdf_sample producing wi */
} BsdfEval;

/* Lobe selection probabilities for sampling: the diffuse base (with the conductor's
 * multiple-scattering lobe), the conductor's GGX reflection, and the dielectric interface
 * (its reflection and refraction, split per facet by interface_split). */
typedef struct {
    float diffuse, conductor, interface;
} LobeChoice;

/* The material at one shading point, for one wo (textures, when present, are applied
 * here). */
typedef struct {
    float3 base_color;
    float3 specular_color; /* KHR_materials_specular colour */
    float specular;        /* KHR_materials_specular weight */
    float metallic;
    float alpha;           /* GGX alpha = roughness^2 */
    float transmission;
    float eta;   /* ior of the side wi refracts into over ior of wo's side (thin: ior) */
    bool thin;   /* thin-walled: transmitted light does not bend */
    bool inside; /* wo is inside a solid: no diffuse base */
#ifdef PATHCL_FULL_BSDF
    float3 f0c;           /* min(F0(ior) specular_color, 1) */
    float3 diffuse_scale; /* (1 - metallic)(1 - transmission) base / (pi (1 - E_avg)) */
    float3 layer_o;       /* E(cos_o): the dielectric layer's albedo from wo */
    float cos_o;          /* wo against the shading normal, >= 0 */
    __global const float* layer; /* LAYER_* tables */
    float layer_r, layer_x;      /* continuous table coordinates of roughness and ior */
    float ess_o;                 /* GGX albedo with Fresnel 1 from wo (rough lobes) */
    float3 ms_scale;             /* conductor multiple scattering: metallic F_ms / (pi (1 - E_avg)) */
    float3 ms_albedo;            /* ... and that lobe's albedo from wo, metallic F_ms (1 - ess_o) */
    float glass_scale;           /* 1 / interface albedo: rough refraction loses no energy */
    LobeChoice lobes;
#endif
} BsdfParams;

/* Every lobe of the material is a delta function: light sampling cannot help there. */
static inline bool bsdf_is_delta(const BsdfParams* p)
{
#ifdef PATHCL_FULL_BSDF
    return p->alpha < ALPHA_DELTA && (1.0f - p->metallic) * (1.0f - p->transmission) == 0.0f;
#else
    return false;
#endif
}

/* Cosine-weighted hemisphere sampling via the concentric disk map. */
static inline float3 sample_cosine_hemisphere(float2 u)
{
    float2 d = sample_concentric_disk(u);
    return (float3)(d.x, d.y, sqrt(fmax(0.0f, 1.0f - d.x * d.x - d.y * d.y)));
}

static inline float3 to_local(float3 v, float3 t, float3 b, float3 n)
{
    return (float3)(dot(v, t), dot(v, b), dot(v, n));
}

static inline float3 to_world(float3 v, float3 t, float3 b, float3 n)
{
    return v.x * t + v.y * b + v.z * n;
}

#ifdef PATHCL_FULL_BSDF

static inline float mean3(float3 v)
{
    return (v.x + v.y + v.z) * (1.0f / 3.0f);
}

static inline float max3(float3 v)
{
    return fmax(v.x, fmax(v.y, v.z));
}

/* Unpolarized Fresnel reflectance of a dielectric interface; cos_i >= 0 on the incident
 * side, eta = ior of the far side / ior of the incident side. 1 under total internal
 * reflection. */
static inline float fresnel_dielectric(float cos_i, float eta)
{
    cos_i = clamp(cos_i, 0.0f, 1.0f);
    float sin2_t = (1.0f - cos_i * cos_i) / (eta * eta);
    if (sin2_t >= 1.0f)
        return 1.0f;
    float cos_t = sqrt(1.0f - sin2_t);
    float r_parallel = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
    float r_perpendicular = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
    return 0.5f * (r_parallel * r_parallel + r_perpendicular * r_perpendicular);
}

/* Schlick's approximation, as glTF defines the conductor Fresnel term. */
static inline float3 fresnel_schlick(float3 f0, float cos_i)
{
    float m = clamp(1.0f - cos_i, 0.0f, 1.0f);
    float m2 = m * m;
    return f0 + (1.0f - f0) * (m2 * m2 * m);
}

/* The dielectric layer's reflectance F_d (see the header comment). */
static inline float3 fresnel_specular_layer(const BsdfParams* p, float cos_i)
{
    float r = (p->eta - 1.0f) / (p->eta + 1.0f);
    float f0 = r * r;
    float s = f0 < 1.0f ? (fresnel_dielectric(cos_i, p->eta) - f0) / (1.0f - f0) : 1.0f;
    s = clamp(s, 0.0f, 1.0f);
    return p->specular * (p->f0c + (1.0f - p->f0c) * s);
}

/* Reflectance of the specular reflection lobe: conductor and dielectric layer mixed. The
 * transmissive share of the layer is the rough interface, whose energy is restored by
 * glass_scale (1 when smooth, or when there is none). */
static inline float3 fresnel_reflection(const BsdfParams* p, float cos_i, float3 f_layer)
{
    float layer_scale = (1.0f - p->transmission) + p->transmission * p->glass_scale;
    return p->metallic * fresnel_schlick(p->base_color, cos_i) + (1.0f - p->metallic) * layer_scale * f_layer;
}

/* What the dielectric layer lets through to the transmission lobe. */
static inline float base_weight(const BsdfParams* p, float3 f_layer)
{
    return (1.0f - p->metallic) * (1.0f - max3(f_layer));
}

/* Bilinear lookup in a rows x cols block of the layer table at continuous (row, col). */
static inline float layer_bilinear(__global const float* t, int offset, int cols, float row, int rows, float col)
{
    int r0 = min((int)row, rows - 2), c0 = min((int)col, cols - 2);
    float fr = row - (float)r0, fc = col - (float)c0;
    __global const float* a = t + offset + r0 * cols + c0;
    float top = mix(a[0], a[1], fc), bottom = mix(a[cols], a[cols + 1], fc);
    return mix(top, bottom, fr);
}

/* The GGX reflection lobe's albedo with Fresnel 1 from cos theta (rough lobes only). */
static inline float ess_albedo(const BsdfParams* p, float mu)
{
    float t = sqrt(clamp(mu, 0.0f, 1.0f)) * (float)(LAYER_MU_RES - 1);
    return layer_bilinear(p->layer, LAYER_TABLE_ESS, LAYER_MU_RES, p->layer_r, LAYER_ROUGH_RES, t);
}

/* The rough dielectric interface's energy albedo (reflection plus refraction) from cos
 * theta, outside or inside the solid. */
static inline float interface_albedo(const BsdfParams* p, float mu)
{
    float t = sqrt(clamp(mu, 0.0f, 1.0f)) * (float)(LAYER_MU_RES - 1);
    float x = p->layer_x * (float)(LAYER_GLASS_ETA_RES - 1) / (float)(LAYER_ETA_RES - 1);
    int x0 = min((int)x, LAYER_GLASS_ETA_RES - 2);
    const int block = LAYER_ROUGH_RES * LAYER_MU_RES;
    int base = p->inside ? LAYER_TABLE_GLASS_IN : LAYER_TABLE_GLASS_OUT;
    float g0 = layer_bilinear(p->layer, base + x0 * block, LAYER_MU_RES, p->layer_r, LAYER_ROUGH_RES, t);
    float g1 = layer_bilinear(p->layer, base + (x0 + 1) * block, LAYER_MU_RES, p->layer_r, LAYER_ROUGH_RES, t);
    return mix(g0, g1, x - (float)x0);
}

/* The dielectric layer's directional albedo E(cos theta), per channel: exact for a
 * smooth layer, else interpolated from the tables (linear in sqrt(cos), roughness, x). */
static inline float3 layer_albedo(const BsdfParams* p, float mu)
{
    if (!(p->specular > 0.0f))
        return (float3)(0.0f); /* no layer: the base is exactly Lambertian, no lookups */
    if (p->alpha < ALPHA_DELTA)
        return fresnel_specular_layer(p, mu);
    float t = sqrt(clamp(mu, 0.0f, 1.0f)) * (float)(LAYER_MU_RES - 1);
    float e_ss = layer_bilinear(p->layer, LAYER_TABLE_ESS, LAYER_MU_RES, p->layer_r, LAYER_ROUGH_RES, t);
    int x0 = min((int)p->layer_x, LAYER_ETA_RES - 2);
    float fx = p->layer_x - (float)x0;
    const int block = LAYER_ROUGH_RES * LAYER_MU_RES;
    float b0 = layer_bilinear(p->layer, LAYER_TABLE_B + x0 * block, LAYER_MU_RES, p->layer_r, LAYER_ROUGH_RES, t);
    float b1 = layer_bilinear(p->layer, LAYER_TABLE_B + (x0 + 1) * block, LAYER_MU_RES, p->layer_r, LAYER_ROUGH_RES, t);
    float b = mix(b0, b1, fx);
    return p->specular * (p->f0c * (e_ss - b) + b);
}

/* Its cosine-weighted hemispherical average E_avg. */
static inline float3 layer_average(const BsdfParams* p, const Material* m)
{
    float e_ss, b;
    if (!(p->specular > 0.0f))
        return (float3)(0.0f);
    if (p->alpha < ALPHA_DELTA) {
        e_ss = 1.0f;
        b = m->smooth_layer_average;
    } else {
        int r0 = min((int)p->layer_r, LAYER_ROUGH_RES - 2);
        float fr = p->layer_r - (float)r0;
        e_ss = mix(p->layer[LAYER_TABLE_ESS_AVG + r0], p->layer[LAYER_TABLE_ESS_AVG + r0 + 1], fr);
        b = layer_bilinear(p->layer, LAYER_TABLE_B_AVG, LAYER_ROUGH_RES, p->layer_x, LAYER_ETA_RES, p->layer_r);
    }
    return p->specular * (p->f0c * (e_ss - b) + b);
}

/* GGX normal distribution, local frame (wm.z > 0). Written with sin^2 = x^2 + y^2 so that
 * tiny alpha keeps its precision near the peak. */
static inline float ggx_d(float3 wm, float a2)
{
    float d = wm.x * wm.x + wm.y * wm.y + wm.z * wm.z * a2;
    return a2 / (PI_F * d * d);
}

/* Smith masking G1 = 1 / (1 + Lambda) = 2 |cos| / (|cos| + sqrt(cos^2 + a^2 sin^2)). */
static inline float ggx_g1(float3 w, float a2)
{
    float c = fabs(w.z);
    return 2.0f * c / (c + sqrt(w.z * w.z + a2 * (w.x * w.x + w.y * w.y)));
}

/* Density of visible normals wm as seen from wo (wo.z > 0). */
static inline float ggx_visible_pdf(float3 wo, float3 wm, float a2)
{
    float c = dot(wo, wm);
    if (!(c > 0.0f) || !(wm.z > 0.0f))
        return 0.0f;
    return ggx_g1(wo, a2) * c * ggx_d(wm, a2) / wo.z;
}

/* Visible-normal sampling by spherical caps (Dupuy and Benyoub 2023); wo.z > 0. */
static inline float3 ggx_sample_visible(float3 wo, float alpha, float2 u)
{
    float3 w = normalize((float3)(wo.x * alpha, wo.y * alpha, wo.z));
    float z = fma(1.0f - u.y, 1.0f + w.z, -w.z);
    float sin_theta = sqrt(clamp(1.0f - z * z, 0.0f, 1.0f));
    float cos_phi, sin_phi = sin_cos_turns(u.x, &cos_phi); /* phi = 2 pi u.x */
    float3 h = (float3)(sin_theta * cos_phi, sin_theta * sin_phi, z) + w;
    float3 wm = (float3)(h.x * alpha, h.y * alpha, fmax(h.z, 0.0f));
    float len = length(wm);
    return len > 0.0f ? wm / len : (float3)(0.0f, 0.0f, 1.0f);
}

/* Refraction of wo about n (wo on n's side), eta = far ior / near ior. False under TIR. */
static inline bool refract_dir(float3 wo, float3 n, float eta, float3* wt)
{
    float cos_i = dot(n, wo);
    float sin2_t = fmax(0.0f, 1.0f - cos_i * cos_i) / (eta * eta);
    if (sin2_t >= 1.0f)
        return false;
    float cos_t = sqrt(1.0f - sin2_t);
    *wt = -wo / eta + (cos_i / eta - cos_t) * n;
    return true;
}

/* Lobe probabilities from each lobe's albedo as seen from wo at the macro normal. A rough
 * lobe that exists gets at least LOBE_ESTIMATE_FLOOR of its weight, since its facets can
 * reflect where the macro surface barely does (a black conductor at normal incidence). */
static inline LobeChoice choose_lobes(const BsdfParams* p)
{
    bool rough = p->alpha >= ALPHA_DELTA;
    float3 f_layer = fresnel_specular_layer(p, p->cos_o);
    LobeChoice c;
    c.diffuse = p->inside ? 0.0f
                          : (1.0f - p->metallic) * (1.0f - p->transmission) * mean3(p->base_color * (1.0f - p->layer_o));
    c.diffuse += mean3(p->ms_albedo); /* the conductor's multiple scattering, sampled alike */
    c.conductor = p->metallic * mean3(fresnel_schlick(p->base_color, p->cos_o));
    /* The interface: the coat's reflection over the diffuse base, and the glass (whose
     * compensated albedo is reflection plus tinted refraction). */
    float coat = mean3(p->inside ? f_layer : p->layer_o);
    float glass = mean3(f_layer) + (1.0f - max3(f_layer)) * mean3(p->base_color);
    c.interface = (1.0f - p->metallic) * ((1.0f - p->transmission) * coat + p->transmission * glass);
    bool has_interface = (p->specular > 0.0f && p->eta != 1.0f) || p->transmission > 0.0f;
    if (rough) {
        c.conductor = fmax(c.conductor, LOBE_ESTIMATE_FLOOR * p->metallic);
        if (has_interface)
            c.interface = fmax(c.interface, LOBE_ESTIMATE_FLOOR * (1.0f - p->metallic));
    }
    float sum = c.diffuse + c.conductor + c.interface;
    if (sum > 0.0f) {
        c.diffuse /= sum;
        c.conductor /= sum;
        c.interface /= sum;
    }
    return c;
}

/* Probability that the interface reflects rather than refracts at a facet seen at cos c
 * from wo: its share of the facet's reflected and transmitted energy (pbrt's per-facet
 * choice; for a white dielectric this is the Fresnel factor itself). */
static inline float interface_split(const BsdfParams* p, float c)
{
    float3 f_layer = fresnel_specular_layer(p, c);
    float layer_scale = (1.0f - p->transmission) + p->transmission * p->glass_scale;
    float r = layer_scale * mean3(f_layer);
    float t = p->transmission * p->glass_scale * (1.0f - max3(f_layer)) * mean3(p->base_color);
    return r + t > 0.0f ? r / (r + t) : 1.0f;
}

/* Local-frame evaluation of the non-delta lobes; wo.z > 0 is not required (shading
 * normals), the rough lobes vanish where it fails. */
static inline BsdfEval bsdf_eval_local(const BsdfParams* p, float3 wo, float3 wi, bool reflect)
{
    BsdfEval e;
    e.f_cos = (float3)(0.0f);
    e.pdf = 0.0f;
    bool rough = p->alpha >= ALPHA_DELTA;
    float a2 = p->alpha * p->alpha;
    if (reflect) {
        e.pdf = p->lobes.diffuse * wi.z * INV_PI; /* the diffuse and multiple-scattering lobes */
        if (!p->inside) {
            float3 k = (1.0f - p->layer_o) * (1.0f - layer_albedo(p, wi.z));
            e.f_cos = p->diffuse_scale * k * wi.z;
#ifdef PATHCL_FAULT_GLTF_DIFFUSE_WEIGHT
            /* A deliberate bug for the energy test: glTF's (1 - max F_d(wo.h)) weight. */
            float3 hf = normalize(wo + wi);
            e.f_cos = p->base_color * ((1.0f - p->metallic) * (1.0f - p->transmission) *
                                       (1.0f - max3(fresnel_specular_layer(p, fabs(dot(wo, hf))))) * INV_PI * wi.z);
#endif
        }
        if (rough && p->metallic > 0.0f) {
            /* Kulla and Conty's multiple-scattering lobe: reciprocal, and with it a white
             * rough conductor reflects everything. Sampled with the diffuse lobe. */
            e.f_cos += p->ms_scale * ((1.0f - p->ess_o) * (1.0f - ess_albedo(p, wi.z)) * wi.z);
        }
        if (rough && wo.z > 0.0f) {
            float3 h = wo + wi;
            float len = length(h);
            if (!(len > 0.0f))
                return e;
            h /= len;
            float cos_h = fabs(dot(wo, h));
            float3 fr = fresnel_reflection(p, cos_h, fresnel_specular_layer(p, cos_h));
            e.f_cos += fr * (ggx_d(h, a2) * ggx_g1(wo, a2) * ggx_g1(wi, a2) / (4.0f * wo.z));
            float select = p->lobes.conductor + p->lobes.interface * interface_split(p, cos_h);
            e.pdf += select * ggx_visible_pdf(wo, h, a2) / (4.0f * cos_h);
        }
        return e;
    }
    if (!rough || !(wo.z > 0.0f) || p->transmission <= 0.0f)
        return e;
    float3 wm;
    float dwm_dwi; /* Jacobian of the half vector map */
    float btdf;    /* f cos / (base colour x transmission weight) */
    if (p->thin) {
        /* Thin-walled: the reflection lobe mirrored through the surface. */
        float3 wr = (float3)(wi.x, wi.y, -wi.z);
        wm = normalize(wo + wr);
        float c = dot(wo, wm);
        if (!(c > 0.0f))
            return e;
        dwm_dwi = 1.0f / (4.0f * c);
        btdf = ggx_d(wm, a2) * ggx_g1(wo, a2) * ggx_g1(wi, a2) / (4.0f * wo.z);
    } else {
        /* Walter et al. 2007; radiance is divided by eta^2 as it crosses. */
        wm = normalize(wi * p->eta + wo);
        if (wm.z < 0.0f)
            wm = -wm;
        float dot_i = dot(wi, wm), dot_o = dot(wo, wm);
        if (!(dot_o > 0.0f) || !(dot_i < 0.0f))
            return e;
        float denom = dot_i + dot_o / p->eta;
        denom *= denom;
        dwm_dwi = -dot_i / denom;
        btdf = ggx_d(wm, a2) * ggx_g1(wo, a2) * ggx_g1(wi, a2) * fabs(dot_i * dot_o) /
               (wo.z * denom * p->eta * p->eta);
    }
    float c = dot(wo, wm);
    float3 f_layer = fresnel_specular_layer(p, c);
    float t = base_weight(p, f_layer) * p->transmission * p->glass_scale;
    e.f_cos = p->base_color * (t * btdf);
    e.pdf = p->lobes.interface * (1.0f - interface_split(p, c)) * ggx_visible_pdf(wo, wm, a2) * dwm_dwi;
    return e;
}

#endif /* PATHCL_FULL_BSDF */

/* The BSDF at a shading point seen from wo. layer: the LAYER_* tables. */
static inline BsdfParams bsdf_params(const Material* m, const SurfacePoint* sp, float3 wo,
                                     __global const float* layer)
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
    float r = (m->ior - 1.0f) / (m->ior + 1.0f);
    p.f0c = fmin(r * r * p.specular_color, (float3)(1.0f));
    p.layer = layer;
    p.layer_r = m->roughness * (float)(LAYER_ROUGH_RES - 1);
    p.layer_x = clamp(r / LAYER_X_MAX, 0.0f, 1.0f) * (float)(LAYER_ETA_RES - 1);
    p.cos_o = clamp(dot(wo, sp->ns), 0.0f, 1.0f);
    p.glass_scale = 1.0f;
    p.ms_scale = p.ms_albedo = (float3)(0.0f);
    p.ess_o = 1.0f;
#ifndef PATHCL_SINGLE_SCATTERING
    if (p.alpha >= ALPHA_DELTA) {
        /* Energy lost to masking, restored (multiple-scattering compensation). */
        p.ess_o = ess_albedo(&p, p.cos_o);
        if (p.metallic > 0.0f) {
            /* Kulla and Conty 2017 with Schlick's average F_avg = F0 + (1 - F0) / 21. */
            int r0 = min((int)p.layer_r, LAYER_ROUGH_RES - 2);
            float e_avg = mix(layer[LAYER_TABLE_ESS_AVG + r0], layer[LAYER_TABLE_ESS_AVG + r0 + 1], p.layer_r - (float)r0);
            float3 f_avg = p.base_color + (1.0f - p.base_color) * (1.0f / 21.0f);
            float3 f_ms = f_avg * f_avg * e_avg / (1.0f - f_avg * (1.0f - e_avg));
            if (1.0f - e_avg > 1e-4f) { /* else the loss is below 1e-4: nothing to restore */
                p.ms_scale = p.metallic * f_ms * INV_PI / (1.0f - e_avg);
                p.ms_albedo = p.metallic * f_ms * (1.0f - p.ess_o);
            }
        }
        /* A rough interface with the exact Fresnel factor (specular 1, white specular
         * colour) loses 1 - G(cos_o); its lobes are divided by G, as Turquin (2019) does.
         * A thin sheet's lobe pair has the reflection lobe's albedo E_ss. */
        bool exact_fresnel = p.specular == 1.0f && all(p.specular_color == (float3)(1.0f));
        if (p.transmission > 0.0f && exact_fresnel) {
            float g = p.thin ? p.ess_o : interface_albedo(&p, p.cos_o);
            p.glass_scale = g > 1e-3f ? 1.0f / g : 1.0f;
        }
    }
#endif
    p.layer_o = p.inside ? (float3)(0.0f) : layer_albedo(&p, p.cos_o);
    float3 one_minus_avg = 1.0f - layer_average(&p, m);
    float w = p.inside ? 0.0f : (1.0f - p.metallic) * (1.0f - p.transmission) * INV_PI;
    /* A layer that reflects everything on average leaves the base nothing (and 0 / 0). */
    p.diffuse_scale = select((float3)(0.0f), p.base_color * w / one_minus_avg, isgreater(one_minus_avg, (float3)(1e-6f)));
    p.lobes = choose_lobes(&p);
#endif
    return p;
}

static inline BsdfEval bsdf_eval(const BsdfParams* p, const SurfacePoint* sp, float3 wo, float3 wi)
{
    BsdfEval e;
    e.f_cos = (float3)(0.0f);
    e.pdf = 0.0f;
    float cos_i = dot(wi, sp->ns), cos_ig = dot(wi, sp->ng);
#ifndef PATHCL_FULL_BSDF
    /* Lambertian with albedo = base colour. */
    if (cos_i <= 0.0f || !above_surface(sp, cos_ig))
        return e;
    e.f_cos = p->base_color * (INV_PI * cos_i);
#ifdef PATHCL_FAULT_LAMBERT_NO_COSINE
    /* A deliberate bug, compiled only by the test proving the render tests can fail. */
    e.f_cos = p->base_color * INV_PI;
#endif
    e.pdf = cos_i * INV_PI;
    return e;
#else
    bool reflect = cos_i > 0.0f && above_surface(sp, cos_ig);
    bool transmit = cos_i < 0.0f && cos_ig < 0.0f;
    if (!reflect && !transmit)
        return e;
    float3 t, b;
    make_basis(sp->ns, &t, &b);
    return bsdf_eval_local(p, to_local(wo, t, b, sp->ns), to_local(wi, t, b, sp->ns), reflect);
#endif
}

/* u_lobe picks the lobe, u samples it. */
static inline BsdfSample bsdf_sample(const BsdfParams* p, const SurfacePoint* sp, float3 wo, float u_lobe,
                                     float2 u)
{
    BsdfSample s;
    s.delta = false;
    s.pdf = 0.0f;
    s.eta2 = 1.0f;
    s.weight = (float3)(0.0f);
    float3 t, b;
    make_basis(sp->ns, &t, &b);
#ifndef PATHCL_FULL_BSDF
    float3 wi = sample_cosine_hemisphere(u);
    s.wi = to_world(wi, t, b, sp->ns);
    if (wi.z <= 0.0f || !above_surface(sp, dot(s.wi, sp->ng)))
        return s;
    s.pdf = wi.z * INV_PI;
    s.weight = p->base_color; /* (albedo / pi) cos / (cos / pi) */
    return s;
#else
    float3 wo_l = to_local(wo, t, b, sp->ns);
    const LobeChoice lobes = p->lobes;
    bool rough = p->alpha >= ALPHA_DELTA;
    float3 wi;
    bool reflect = true;
    if (u_lobe < lobes.diffuse) {
        wi = sample_cosine_hemisphere(u);
    } else if (u_lobe < lobes.diffuse + lobes.conductor) {
        if (!rough) {
            /* Ideal mirror: weight F / (selection probability). */
            wi = (float3)(-wo_l.x, -wo_l.y, wo_l.z);
            s.wi = to_world(wi, t, b, sp->ns);
            if (!(wi.z > 0.0f) || !above_surface(sp, dot(s.wi, sp->ng)))
                return s;
            s.delta = true;
            s.pdf = lobes.conductor;
            s.weight = p->metallic * fresnel_schlick(p->base_color, p->cos_o) / lobes.conductor;
            return s;
        }
        if (!(wo_l.z > 0.0f))
            return s;
        float3 wm = ggx_sample_visible(wo_l, p->alpha, u);
        wi = 2.0f * dot(wo_l, wm) * wm - wo_l;
    } else {
        /* The interface: a visible facet, then reflection or refraction by its own split;
         * the rest of u_lobe's interval is the uniform number for that choice. */
        if (!(wo_l.z > 0.0f) || !(lobes.interface > 0.0f))
            return s;
        float3 wm = rough ? ggx_sample_visible(wo_l, p->alpha, u) : (float3)(0.0f, 0.0f, 1.0f);
        float c = dot(wo_l, wm);
        float split = interface_split(p, c);
        float u_split = (u_lobe - lobes.diffuse - lobes.conductor) / lobes.interface;
        reflect = u_split < split;
        if (reflect) {
            wi = 2.0f * c * wm - wo_l;
        } else if (p->thin) {
            wi = 2.0f * c * wm - wo_l;
            wi.z = -wi.z;
        } else if (!refract_dir(wo_l, wm, p->eta, &wi)) {
            return s; /* not reached: total internal reflection makes the split 1 */
        }
        if (!rough) {
            /* Ideal coat, glass or thin sheet: weight (F or T) / (selection probability);
             * radiance is scaled by 1/eta^2 when it crosses into a solid. */
            s.wi = to_world(wi, t, b, sp->ns);
            float cos_ig = dot(s.wi, sp->ng);
            if (reflect ? (!(wi.z > 0.0f) || !above_surface(sp, cos_ig)) : (!(wi.z < 0.0f) || !(cos_ig < 0.0f)))
                return s;
            float3 f_layer = fresnel_specular_layer(p, c);
            s.delta = true;
            if (reflect) {
                s.pdf = lobes.interface * split;
                s.weight = (1.0f - p->metallic) * f_layer / s.pdf;
            } else {
                float tw = base_weight(p, f_layer) * p->transmission;
                if (!p->thin) {
                    s.eta2 = p->eta * p->eta;
                    tw /= s.eta2;
                }
                s.pdf = lobes.interface * (1.0f - split);
                s.weight = p->base_color * (tw / s.pdf);
            }
            return s;
        }
    }
    s.wi = to_world(wi, t, b, sp->ns);
    float cos_ig = dot(s.wi, sp->ng);
    if (reflect ? (!(wi.z > 0.0f) || !above_surface(sp, cos_ig)) : (!(wi.z < 0.0f) || !(cos_ig < 0.0f)))
        return s;
    BsdfEval e = bsdf_eval_local(p, wo_l, wi, reflect);
    if (!(e.pdf > 0.0f))
        return s;
    s.pdf = e.pdf;
    s.weight = e.f_cos / e.pdf;
    if (!reflect && !p->thin)
        s.eta2 = p->eta * p->eta;
    return s;
#endif
}
