/* BSDFs: evaluation, sampling and pdf. Needs: shared_types.h, samplers.cl, geometry.cl.
 *
 * Directions are world-space unit vectors; wo points away from the surface, towards the
 * previous vertex. The shading point has ng and ns on wo's side. A direction is reflected
 * only if it lies above both the geometric and the shading surface, and transmitted only
 * if it lies below both: that keeps shading normals from leaking light through geometry.
 *
 * The material model is glTF's metallic-roughness BSDF (glTF 2.0 appendix B) with
 * KHR_materials_specular, _transmission, _ior and _volume:
 *
 *   f = metallic        * F_schlick(base_color, wo.h) * spec
 *     + (1 - metallic)  * [ F_d(wo.h) * spec
 *                           + (1 - max(F_d(wo.h))) * ( (1 - transmission) * base_color / pi
 *                                                     + transmission * base_color * btdf ) ]
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
 * Sampling picks one lobe with probabilities from the Fresnel terms at the macro normal,
 * samples it (cosine hemisphere, or the GGX visible normals of Dupuy and Benyoub 2023),
 * and returns f cos / pdf with f and pdf summed over every non-delta lobe: the weight is
 * exactly what bsdf_eval returns, divided by what bsdf_pdf returns.
 *
 * Scenes whose materials are all Lambertian compile only the Lambertian code (no
 * PATHCL_HAS_GLOSSY / PATHCL_HAS_TRANSMISSION): they pay nothing for the rest. */

/* GGX alpha below which the specular lobes are delta functions (pbrt-v4 uses the same). */
#define ALPHA_DELTA 1.0e-3f

#if defined(PATHCL_HAS_GLOSSY) || defined(PATHCL_HAS_TRANSMISSION)
#define PATHCL_FULL_BSDF
#endif

typedef struct {
    float3 wi;
    float3 weight; /* f cos / pdf */
    float pdf;     /* solid angle; 0: no sample. For a delta lobe: its selection probability */
    bool delta;
} BsdfSample;

typedef struct {
    float3 f_cos; /* f * |cos theta_i|, non-delta lobes only */
    float pdf;    /* of bsdf_sample producing wi */
} BsdfEval;

/* The material at one shading point (textures, when present, are applied here). */
typedef struct {
    float3 base_color;
    float3 specular_color; /* KHR_materials_specular colour */
    float specular;        /* KHR_materials_specular weight */
    float metallic;
    float alpha;           /* GGX alpha = roughness^2 */
    float transmission;
    float eta;  /* solid: ior of the side wi refracts into over ior of wo's side; thin: ior */
    bool thin;  /* thin-walled: transmitted light does not bend */
} BsdfParams;

static inline BsdfParams bsdf_params(const Material* m, const SurfacePoint* sp)
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
    p.eta = (p.thin || sp->front_face) ? m->ior : 1.0f / m->ior;
    return p;
}

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
    float3 f0c = fmin(f0 * p->specular_color, (float3)(1.0f));
    return p->specular * (f0c + (1.0f - f0c) * s);
}

/* Reflectance of the specular reflection lobe: conductor and dielectric layer mixed. */
static inline float3 fresnel_reflection(const BsdfParams* p, float cos_i, float3 f_layer)
{
    return p->metallic * fresnel_schlick(p->base_color, cos_i) + (1.0f - p->metallic) * f_layer;
}

/* What the dielectric layer lets through to the diffuse and transmission lobes. */
static inline float base_weight(const BsdfParams* p, float3 f_layer)
{
    return (1.0f - p->metallic) * (1.0f - max3(f_layer));
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
    float phi = 2.0f * PI_F * u.x;
    float z = fma(1.0f - u.y, 1.0f + w.z, -w.z);
    float sin_theta = sqrt(clamp(1.0f - z * z, 0.0f, 1.0f));
    float3 h = (float3)(sin_theta * cos(phi), sin_theta * sin(phi), z) + w;
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

/* Lobe probabilities for sampling, from the Fresnel terms at the macro normal. */
typedef struct {
    float diffuse, specular, transmission;
} LobeChoice;

static inline LobeChoice choose_lobes(const BsdfParams* p, float cos_o)
{
    float3 f_layer = fresnel_specular_layer(p, cos_o);
    float base = base_weight(p, f_layer) * mean3(p->base_color);
    LobeChoice c;
    c.specular = mean3(fresnel_reflection(p, cos_o, f_layer));
    c.diffuse = base * (1.0f - p->transmission);
    c.transmission = base * p->transmission;
    float sum = c.specular + c.diffuse + c.transmission;
    if (sum > 0.0f) {
        c.specular /= sum;
        c.diffuse /= sum;
        c.transmission /= sum;
    }
    return c;
}

/* Local-frame evaluation of the non-delta lobes; wo.z > 0 is not required (shading
 * normals), the rough lobes vanish where it fails. */
static inline BsdfEval bsdf_eval_local(const BsdfParams* p, float3 wo, float3 wi, bool reflect)
{
    BsdfEval e;
    e.f_cos = (float3)(0.0f);
    e.pdf = 0.0f;
    LobeChoice lobes = choose_lobes(p, fmax(wo.z, 0.0f));
    bool rough = p->alpha >= ALPHA_DELTA;
    float a2 = p->alpha * p->alpha;
    if (reflect) {
        float3 h = wo + wi;
        float len = length(h);
        if (!(len > 0.0f))
            return e;
        h /= len;
        float cos_h = fabs(dot(wo, h));
        float3 f_layer = fresnel_specular_layer(p, cos_h);
        float diffuse = base_weight(p, f_layer) * (1.0f - p->transmission);
        e.f_cos = p->base_color * (diffuse * INV_PI * wi.z);
        e.pdf = lobes.diffuse * wi.z * INV_PI;
        if (rough && wo.z > 0.0f) {
            float3 fr = fresnel_reflection(p, cos_h, f_layer);
            e.f_cos += fr * (ggx_d(h, a2) * ggx_g1(wo, a2) * ggx_g1(wi, a2) / (4.0f * wo.z));
            e.pdf += lobes.specular * ggx_visible_pdf(wo, h, a2) / (4.0f * cos_h);
        }
        return e;
    }
    if (!rough || !(wo.z > 0.0f) || p->transmission <= 0.0f)
        return e;
    float3 wm;
    float dwm_dwi; /* Jacobian of the half vector map */
    float btdf;    /* f / (base colour x transmission weight), without the Fresnel factor */
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
    float3 f_layer = fresnel_specular_layer(p, dot(wo, wm));
    float t = base_weight(p, f_layer) * p->transmission;
    e.f_cos = p->base_color * (t * btdf);
    e.pdf = lobes.transmission * ggx_visible_pdf(wo, wm, a2) * dwm_dwi;
    return e;
}

#endif /* PATHCL_FULL_BSDF */

static inline BsdfEval bsdf_eval(const BsdfParams* p, const SurfacePoint* sp, float3 wo, float3 wi)
{
    BsdfEval e;
    e.f_cos = (float3)(0.0f);
    e.pdf = 0.0f;
    float cos_i = dot(wi, sp->ns), cos_ig = dot(wi, sp->ng);
#ifndef PATHCL_FULL_BSDF
    /* Lambertian with albedo = base colour. */
    if (cos_i <= 0.0f || cos_ig <= 0.0f)
        return e;
    e.f_cos = p->base_color * (INV_PI * cos_i);
#ifdef PATHCL_FAULT_LAMBERT_NO_COSINE
    /* A deliberate bug, compiled only by the test proving the render tests can fail. */
    e.f_cos = p->base_color * INV_PI;
#endif
    e.pdf = cos_i * INV_PI;
    return e;
#else
    bool reflect = cos_i > 0.0f && cos_ig > 0.0f;
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
    s.weight = (float3)(0.0f);
    float3 t, b;
    make_basis(sp->ns, &t, &b);
#ifndef PATHCL_FULL_BSDF
    float3 wi = sample_cosine_hemisphere(u);
    s.wi = to_world(wi, t, b, sp->ns);
    if (wi.z <= 0.0f || dot(s.wi, sp->ng) <= 0.0f)
        return s;
    s.pdf = wi.z * INV_PI;
    s.weight = p->base_color; /* (albedo / pi) cos / (cos / pi) */
    return s;
#else
    float3 wo_l = to_local(wo, t, b, sp->ns);
    float cos_o = fmax(wo_l.z, 0.0f);
    LobeChoice lobes = choose_lobes(p, cos_o);
    bool rough = p->alpha >= ALPHA_DELTA;
    float3 wi;
    bool reflect;
    if (u_lobe < lobes.diffuse) {
        wi = sample_cosine_hemisphere(u);
        reflect = true;
    } else if (u_lobe < lobes.diffuse + lobes.specular) {
        reflect = true;
        if (!rough) {
            /* Ideal mirror: weight F / (selection probability). */
            wi = (float3)(-wo_l.x, -wo_l.y, wo_l.z);
            s.wi = to_world(wi, t, b, sp->ns);
            if (!(wi.z > 0.0f) || dot(s.wi, sp->ng) <= 0.0f)
                return s;
            s.delta = true;
            s.pdf = lobes.specular;
            s.weight = fresnel_reflection(p, cos_o, fresnel_specular_layer(p, cos_o)) / lobes.specular;
            return s;
        }
        if (!(wo_l.z > 0.0f))
            return s;
        float3 wm = ggx_sample_visible(wo_l, p->alpha, u);
        wi = 2.0f * dot(wo_l, wm) * wm - wo_l;
    } else {
        reflect = false;
        if (!(lobes.transmission > 0.0f) || !(wo_l.z > 0.0f))
            return s;
        float3 wm = rough ? ggx_sample_visible(wo_l, p->alpha, u) : (float3)(0.0f, 0.0f, 1.0f);
        if (p->thin) {
            wi = 2.0f * dot(wo_l, wm) * wm - wo_l;
            wi.z = -wi.z;
        } else if (!refract_dir(wo_l, wm, p->eta, &wi)) {
            return s; /* total internal reflection at this microfacet: the reflection lobe's job */
        }
        if (!rough) {
            /* Ideal glass (or a thin sheet): weight T / (selection probability), radiance
             * scaled by 1/eta^2 when it crosses into a solid. */
            s.wi = to_world(wi, t, b, sp->ns);
            if (!(wi.z < 0.0f) || dot(s.wi, sp->ng) >= 0.0f)
                return s;
            float3 f_layer = fresnel_specular_layer(p, cos_o);
            float tw = base_weight(p, f_layer) * p->transmission;
            if (!p->thin)
                tw /= p->eta * p->eta;
            s.delta = true;
            s.pdf = lobes.transmission;
            s.weight = p->base_color * (tw / lobes.transmission);
            return s;
        }
    }
    s.wi = to_world(wi, t, b, sp->ns);
    float cos_ig = dot(s.wi, sp->ng);
    if (reflect ? (!(wi.z > 0.0f) || !(cos_ig > 0.0f)) : (!(wi.z < 0.0f) || !(cos_ig < 0.0f)))
        return s;
    BsdfEval e = bsdf_eval_local(p, wo_l, wi, reflect);
    if (!(e.pdf > 0.0f))
        return s;
    s.pdf = e.pdf;
    s.weight = e.f_cos / e.pdf;
    return s;
#endif
}
