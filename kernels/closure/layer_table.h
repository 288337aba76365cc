/* The layout of the dielectric layer's albedo tables, which host/tables/layer_albedo.cpp
 * computes at build time and kernels/closure/layer_albedo.cl reads. They weight the diffuse
 * base under the layer (albedo scaling) and restore the energy rough microfacets lose.
 * One float array over sqrt(cos theta), roughness r = sqrt(alpha) and x = (eta-1)/(eta+1),
 * each uniform on its grid and interpolated linearly:
 *   E_ss[r][mu]     albedo of the GGX reflection lobe with Fresnel 1
 *   B[x][r][mu]     albedo with the normalized Fresnel curve s(c) (closure/fresnel.h) for 1;
 *                   one more row x = LAYER_ETA_RES with Schlick's curve (ior 0)
 *   E_ss_avg[r], B_avg[x][r]   their cosine-weighted hemispherical averages 2 int E mu dmu
 *   G_out[x'][r][mu], G_in[x'][r][mu]   energy albedo (reflection + refraction) of a rough
 *                   dielectric interface seen from outside (eta = ior) and inside (1/ior),
 *                   x' on a 16-point grid
 *   E_sheen[r][mu]  albedo of the KHR_materials_sheen lobe with colour 1 (closure/sheen.h),
 *                   r = sheenRoughness; above 1 at grazing angles for smooth sheens
 *   E_aniso[t][r][c][mu]   albedo with Fresnel 1 of the anisotropic GGX lobe of
 *                   KHR_materials_anisotropy (alpha t^2 along the direction, max(r^2,
 *                   1e-3) across it: t = sqrt(alpha_t) and r the roughnesses along and
 *                   across) from a direction at cos theta = mu^4 (grazing angles, where
 *                   it bends, get more points) whose azimuth phi from the direction has
 *                   |cos phi| = c; its own grid (LAYER_ANISO_*), 524,288 bytes
 *   E_aniso_avg[t][r]  its cosine-weighted average over the hemisphere (all azimuths)
 *   B_aniso[x"][t][r][c][mu]  the same lobe's albedo with the normalized Fresnel curve
 *                   s(c) (the dielectric layer of an anisotropic material), x" on a grid
 *                   of its own, x = LAYER_X_MAX (k / (LAYER_ANISO_ETA_RES - 1))^2 (B
 *                   bends fastest near ior 1)
 *   B_aniso_avg[x"][t][r]  its cosine-weighted average over the hemisphere
 * Row r = 0 holds the smooth interface (E_ss = 1, B = s(mu), G = 1). 7,147,776 bytes; a
 * program without anisotropy gets the first 278,784 (up to LAYER_TABLE_ANISO). */
#ifndef PATHCL_CLOSURE_LAYER_TABLE_H
#define PATHCL_CLOSURE_LAYER_TABLE_H

#define LAYER_MU_RES 32
#define LAYER_ROUGH_RES 32
#define LAYER_ETA_RES 32 /* x in [0, 0.5]: eta in [1, 3] (clamped beyond) */
#define LAYER_X_MAX 0.5f
#define LAYER_TABLE_ESS 0
#define LAYER_TABLE_B (LAYER_TABLE_ESS + LAYER_ROUGH_RES * LAYER_MU_RES)
#define LAYER_B_ROWS (LAYER_ETA_RES + 1) /* the ior grid, then Schlick's curve */
#define LAYER_TABLE_ESS_AVG (LAYER_TABLE_B + LAYER_B_ROWS * LAYER_ROUGH_RES * LAYER_MU_RES)
#define LAYER_TABLE_B_AVG (LAYER_TABLE_ESS_AVG + LAYER_ROUGH_RES)
#define LAYER_GLASS_ETA_RES 16 /* x in [0, 0.5] for the dielectric interface tables */
#define LAYER_TABLE_GLASS_OUT (LAYER_TABLE_B_AVG + LAYER_B_ROWS * LAYER_ROUGH_RES)
#define LAYER_TABLE_GLASS_IN (LAYER_TABLE_GLASS_OUT + LAYER_GLASS_ETA_RES * LAYER_ROUGH_RES * LAYER_MU_RES)
#define LAYER_TABLE_SHEEN (LAYER_TABLE_GLASS_IN + LAYER_GLASS_ETA_RES * LAYER_ROUGH_RES * LAYER_MU_RES)
#define LAYER_ANISO_MU_RES 16
#define LAYER_ANISO_V_RES 8
#define LAYER_ANISO_ROUGH_RES 32
#define LAYER_ANISO_T_RES 32
#define LAYER_ANISO_BLOCK (LAYER_ANISO_V_RES * LAYER_ANISO_MU_RES) /* one (t, r) pair's table */
#define LAYER_TABLE_ANISO (LAYER_TABLE_SHEEN + LAYER_ROUGH_RES * LAYER_MU_RES)
#define LAYER_TABLE_ANISO_AVG (LAYER_TABLE_ANISO + LAYER_ANISO_T_RES * LAYER_ANISO_ROUGH_RES * LAYER_ANISO_BLOCK)
#define LAYER_ANISO_ETA_RES 12 /* x = LAYER_X_MAX (k / 11)^2 */
#define LAYER_TABLE_ANISO_B (LAYER_TABLE_ANISO_AVG + LAYER_ANISO_T_RES * LAYER_ANISO_ROUGH_RES)
#define LAYER_TABLE_ANISO_B_AVG                                                                                        \
    (LAYER_TABLE_ANISO_B + LAYER_ANISO_ETA_RES * LAYER_ANISO_T_RES * LAYER_ANISO_ROUGH_RES * LAYER_ANISO_BLOCK)
#define LAYER_TABLE_SIZE (LAYER_TABLE_ANISO_B_AVG + LAYER_ANISO_ETA_RES * LAYER_ANISO_T_RES * LAYER_ANISO_ROUGH_RES)

#endif
