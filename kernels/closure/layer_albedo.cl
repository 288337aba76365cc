/* Lookups in the layer albedo tables (closure/layer_table.h): the GGX lobe's albedo, the
 * rough dielectric interface's energy albedo, and the dielectric layer's directional
 * albedo E and its average, linear in sqrt(cos theta), roughness and ior; with
 * anisotropy, the anisotropic lobe's albedo and the anisotropic layer's E, linear in cos
 * theta^(1/4), |cos phi|, both roughnesses (and the ior). */
#include "closure/bsdf_params.cl"
#include "closure/fresnel.h"
#include "closure/fresnel_layer.cl"
#include "closure/layer_table.h"
#include "features.h"
#include "util/compat.h"

#ifdef PATHCL_FULL_BSDF

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

/* The B term of a rough dielectric layer (E = f0 (E_ss - B) + B) at roughness row r and
 * ior coordinate x (continuous), from the table column t = sqrt(cos theta) (MU_RES - 1):
 * shared by the specular layer and the clear coat. */
static inline float layer_b(__global const float* table, float r, float x, float t)
{
    const int block = LAYER_ROUGH_RES * LAYER_MU_RES;
    int x0 = min((int)x, LAYER_ETA_RES - 2);
    float b0 = layer_bilinear(table, LAYER_TABLE_B + x0 * block, LAYER_MU_RES, r, LAYER_ROUGH_RES, t);
    float b1 = layer_bilinear(table, LAYER_TABLE_B + (x0 + 1) * block, LAYER_MU_RES, r, LAYER_ROUGH_RES, t);
    return mix(b0, b1, x - (float)x0);
}

/* The dielectric layer's directional albedo E(cos theta), per channel: exact for a
 * smooth layer, else interpolated from the tables (linear in sqrt(cos), roughness, x). */
PATHCL_ALWAYS_INLINE static inline float3 layer_albedo(const BsdfParams* p, float mu)
{
    if (!(p->specular > 0.0f))
        return (float3)(0.0f); /* no layer: the base is exactly Lambertian, no lookups */
    if (p->alpha < ALPHA_DELTA)
        return fresnel_specular_layer(p, mu);
    float t = sqrt(clamp(mu, 0.0f, 1.0f)) * (float)(LAYER_MU_RES - 1);
    float e_ss = layer_bilinear(p->layer, LAYER_TABLE_ESS, LAYER_MU_RES, p->layer_r, LAYER_ROUGH_RES, t);
#ifdef PATHCL_HAS_SCHLICK_LAYER
    if (p->eta == 0.0f) { /* ior 0: the Schlick row, after the ior grid */
        const int block = LAYER_ROUGH_RES * LAYER_MU_RES;
        float b = layer_bilinear(p->layer, LAYER_TABLE_B + LAYER_ETA_RES * block, LAYER_MU_RES, p->layer_r,
                                 LAYER_ROUGH_RES, t);
        return p->specular * (p->f0c * (e_ss - b) + b);
    }
#endif
    float b = layer_b(p->layer, p->layer_r, p->layer_x, t);
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
#ifdef PATHCL_HAS_SCHLICK_LAYER
        if (p->eta == 0.0f) { /* ior 0: the Schlick row */
            __global const float* row = p->layer + LAYER_TABLE_B_AVG + LAYER_ETA_RES * LAYER_ROUGH_RES;
            b = mix(row[r0], row[r0 + 1], fr);
        }
#endif
    }
    return p->specular * (p->f0c * (e_ss - b) + b);
}

#ifdef PATHCL_HAS_ANISOTROPY

/* Where a direction w in the frame of bsdf_frame reads the anisotropic tables: the
 * continuous (|cos phi|, cos theta^(1/4)) coordinates within a (t, r) block, and the
 * block pair's corner and weights (roughness along and across). */
typedef struct {
    float c, mu;
    int t0, r0;
    float ft, fr;
} AnisoCoords;

static inline AnisoCoords aniso_coords(const BsdfParams* p, float3 w)
{
    AnisoCoords a;
    a.mu = sqrt(sqrt(clamp(fabs(w.z), 0.0f, 1.0f))) * (float)(LAYER_ANISO_MU_RES - 1);
    float xy2 = w.x * w.x + w.y * w.y;
    a.c = (xy2 > 0.0f ? clamp(fabs(w.x) / sqrt(xy2), 0.0f, 1.0f) : 1.0f) * (float)(LAYER_ANISO_V_RES - 1);
    a.t0 = min((int)p->aniso_t, LAYER_ANISO_T_RES - 2);
    a.r0 = min((int)p->aniso_r, LAYER_ANISO_ROUGH_RES - 2);
    a.fr = p->aniso_r - (float)a.r0;
    a.ft = p->aniso_t - (float)a.t0;
    return a;
}

/* One anisotropic table (E_aniso, or one ior's B_aniso) at offset, interpolated at a. */
static inline float aniso_lookup(const BsdfParams* p, int offset, const AnisoCoords* a)
{
    float e[4];
    for (int k = 0; k < 4; ++k) {
        int block = (a->t0 + (k >> 1)) * LAYER_ANISO_ROUGH_RES + a->r0 + (k & 1);
        e[k] = layer_bilinear(p->layer, offset + block * LAYER_ANISO_BLOCK, LAYER_ANISO_MU_RES, a->c, LAYER_ANISO_V_RES,
                              a->mu);
    }
    return mix(mix(e[0], e[1], a->fr), mix(e[2], e[3], a->fr), a->ft);
}

/* The anisotropic GGX albedo with Fresnel 1 (the E_aniso table) from the direction w in
 * the frame of bsdf_frame: linear in cos theta^(1/4), in |cos| of w's azimuth from the
 * direction (1 along the normal, where every azimuth agrees), and in the roughnesses along
 * and across the direction (p->aniso_t, p->aniso_r, continuous coordinates). */
static inline float aniso_albedo(const BsdfParams* p, float3 w)
{
    AnisoCoords a = aniso_coords(p, w);
    return aniso_lookup(p, LAYER_TABLE_ANISO, &a);
}

/* Its cosine-weighted average over the hemisphere. */
static inline float aniso_albedo_average(const BsdfParams* p)
{
    return layer_bilinear(p->layer, LAYER_TABLE_ANISO_AVG, LAYER_ANISO_ROUGH_RES, p->aniso_t, LAYER_ANISO_T_RES,
                          p->aniso_r);
}

/* The anisotropic dielectric layer's directional albedo E(w) per channel, from E_aniso
 * and B_aniso (linear in its ior coordinate p->aniso_x as well), E = f0 (E_ss - B) + B. */
static inline float3 aniso_layer_albedo(const BsdfParams* p, float3 w)
{
    if (!(p->specular > 0.0f))
        return (float3)(0.0f);
    AnisoCoords a = aniso_coords(p, w);
    float e_ss = aniso_lookup(p, LAYER_TABLE_ANISO, &a);
    const int per_ior = LAYER_ANISO_T_RES * LAYER_ANISO_ROUGH_RES * LAYER_ANISO_BLOCK;
    int x0 = min((int)p->aniso_x, LAYER_ANISO_ETA_RES - 2);
    float b0 = aniso_lookup(p, LAYER_TABLE_ANISO_B + x0 * per_ior, &a);
    float b1 = aniso_lookup(p, LAYER_TABLE_ANISO_B + (x0 + 1) * per_ior, &a);
    float b = mix(b0, b1, p->aniso_x - (float)x0);
    return p->specular * (p->f0c * (e_ss - b) + b);
}

/* Its cosine-weighted average over the hemisphere (all azimuths). */
static inline float3 aniso_layer_average(const BsdfParams* p)
{
    if (!(p->specular > 0.0f))
        return (float3)(0.0f);
    const int per_ior = LAYER_ANISO_T_RES * LAYER_ANISO_ROUGH_RES;
    int x0 = min((int)p->aniso_x, LAYER_ANISO_ETA_RES - 2);
    float b0 = layer_bilinear(p->layer, LAYER_TABLE_ANISO_B_AVG + x0 * per_ior, LAYER_ANISO_ROUGH_RES, p->aniso_t,
                              LAYER_ANISO_T_RES, p->aniso_r);
    float b1 = layer_bilinear(p->layer, LAYER_TABLE_ANISO_B_AVG + (x0 + 1) * per_ior, LAYER_ANISO_ROUGH_RES, p->aniso_t,
                              LAYER_ANISO_T_RES, p->aniso_r);
    float b = mix(b0, b1, p->aniso_x - (float)x0);
    float e_ss = aniso_albedo_average(p);
    return p->specular * (p->f0c * (e_ss - b) + b);
}

#endif /* PATHCL_HAS_ANISOTROPY */

/* The GGX albedo with Fresnel 1 of the conductor's lobe from the direction w in the frame
 * of bsdf_frame (its multiple-scattering compensation's E). */
static inline float conductor_albedo(const BsdfParams* p, float3 w)
{
#ifdef PATHCL_HAS_ANISOTROPY
    if (bsdf_anisotropic(p))
        return aniso_albedo(p, w);
#endif
    return ess_albedo(p, w.z);
}

/* The dielectric layer's directional albedo towards w (in the frame of bsdf_frame, w.z
 * = cos theta): layer_albedo, or the anisotropic layer's. */
static inline float3 layer_albedo_towards(const BsdfParams* p, float3 w)
{
#ifdef PATHCL_HAS_ANISOTROPY
    if (layer_anisotropic(p))
        return aniso_layer_albedo(p, w);
#endif
    return layer_albedo(p, w.z);
}

#ifdef PATHCL_HAS_CLEARCOAT

/* The clear coat is a dielectric layer of ior 1.5 (KHR_materials_clearcoat), F0 = 0.04. */
#define COAT_IOR 1.5f
#define COAT_F0 0.04f

/* The coat's directional albedo E_c(cos theta) with factor 1: its GGX reflection with the
 * exact Fresnel curve of ior 1.5, exact when smooth, else from the B table at x = 0.2. */
static inline float coat_albedo(const BsdfParams* p, float mu)
{
    if (p->coat_alpha < ALPHA_DELTA)
        return fresnel_dielectric(mu, COAT_IOR);
    float t = sqrt(clamp(mu, 0.0f, 1.0f)) * (float)(LAYER_MU_RES - 1);
    float e_ss = layer_bilinear(p->layer, LAYER_TABLE_ESS, LAYER_MU_RES, p->coat_r, LAYER_ROUGH_RES, t);
    const float x = (0.2f / LAYER_X_MAX) * (float)(LAYER_ETA_RES - 1); /* (ior - 1) / (ior + 1) = 0.2 */
    float b = layer_b(p->layer, p->coat_r, x, t);
    return COAT_F0 * (e_ss - b) + b;
}

/* What the coat leaves the base lobes between wo and wi: 1 - coat max(E_c(cos_o),
 * E_c(|cos_i|)). Reciprocal, and never more than 1 - coat E_c(cos_o), so the coat and the
 * base together reflect at most what the base alone would. */
static inline float coat_base_scale(const BsdfParams* p, float3 wi)
{
    return 1.0f - fmax(p->coat_e_o, p->coat * coat_albedo(p, fabs(dot(wi, p->coat_n))));
}

#endif /* PATHCL_HAS_CLEARCOAT */

#ifdef PATHCL_HAS_SHEEN

/* The sheen lobe's albedo E_s(cos theta) with colour 1 (closure/sheen.h), from the table. */
static inline float sheen_albedo(const BsdfParams* p, float mu)
{
    float t = sqrt(clamp(mu, 0.0f, 1.0f)) * (float)(LAYER_MU_RES - 1);
    return layer_bilinear(p->layer, LAYER_TABLE_SHEEN, LAYER_MU_RES, p->sheen_r, LAYER_ROUGH_RES, t);
}

/* What the sheen leaves the base lobes between wo and wi: 1 - max3(sheen) min(1,
 * max(E_s(cos_o), E_s(|cos_i|))), the extension's reciprocal albedo scaling with the albedo
 * capped at 1 (the lobe itself is divided by max(1, ...), see closure/sheen.cl). */
static inline float sheen_base_scale(const BsdfParams* p, float e_i)
{
    return 1.0f - p->sheen_max * fmin(fmax(p->sheen_e_o, e_i), 1.0f);
}

#endif /* PATHCL_HAS_SHEEN */

#endif /* PATHCL_FULL_BSDF */
