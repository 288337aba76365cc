/* The GGX (Trowbridge-Reitz) microfacet distribution and its Smith masking function,
 * written once for the kernels (float) and the host's layer albedo tables (double). Local
 * frame: z is the macro normal. */
#ifndef PATHCL_CLOSURE_GGX_H
#define PATHCL_CLOSURE_GGX_H

#include "util/compat.h"

/* GGX alpha below which a lobe is a delta function (pbrt-v4 uses the same). */
#define ALPHA_DELTA PCL_REAL(1.0e-3)

PATHCL_BEGIN

/* KHR_materials_anisotropy's alpha across the direction, for the material's alpha
 * (roughness^2) and alpha_t = mix(alpha, 1, strength^2) along it: the material's own, kept
 * clear of 0 (at least ALPHA_DELTA) so that D stays finite, unless the lobe is a delta
 * function along the direction too (alpha_t below ALPHA_DELTA: then alpha_t). */
PATHCL_FN pcl_real ggx_anisotropic_alpha_b(pcl_real alpha, pcl_real alpha_t)
{
    return alpha_t >= ALPHA_DELTA ? fmax(alpha, ALPHA_DELTA) : alpha_t;
}

/* GGX normal distribution D(wm) for alpha^2 = a2 (wm.z > 0). Written with sin^2 = x^2 + y^2
 * so that tiny alpha keeps its precision near the peak. */
PATHCL_FN pcl_real ggx_d(pcl_real3 wm, pcl_real a2)
{
    pcl_real d = wm.x * wm.x + wm.y * wm.y + wm.z * wm.z * a2;
    return a2 / (PCL_REAL(3.14159265358979324) * d * d);
}

/* Smith masking G1 = 1 / (1 + Lambda) = 2 |cos| / (|cos| + sqrt(cos^2 + a^2 sin^2)). */
PATHCL_FN pcl_real ggx_g1(pcl_real3 w, pcl_real a2)
{
    pcl_real c = fabs(w.z);
    return PCL_REAL(2.0) * c / (c + sqrt(w.z * w.z + a2 * (w.x * w.x + w.y * w.y)));
}

/* Anisotropic GGX: D(wm) with alpha ax along x and ay along y (KHR_materials_anisotropy;
 * ax = ay = alpha is ggx_d), and Smith's G1 = 2 |cos| / (|cos| + sqrt(cos^2 + ax^2 x^2 +
 * ay^2 y^2)). */
PATHCL_FN pcl_real ggx_d_aniso(pcl_real3 wm, pcl_real ax, pcl_real ay)
{
    pcl_real x = wm.x / ax, y = wm.y / ay;
    pcl_real d = x * x + y * y + wm.z * wm.z;
    return PCL_REAL(1.0) / (PCL_REAL(3.14159265358979324) * ax * ay * d * d);
}

PATHCL_FN pcl_real ggx_g1_aniso(pcl_real3 w, pcl_real ax, pcl_real ay)
{
    pcl_real c = fabs(w.z);
    return PCL_REAL(2.0) * c / (c + sqrt(w.z * w.z + ax * ax * w.x * w.x + ay * ay * w.y * w.y));
}

PATHCL_END

#endif
