/* The KHR_materials_sheen lobe (Conty Estevez and Kulla 2017, "Production Friendly
 * Microfacet Sheen BRDF", as the extension writes it): the "Charlie" distribution of fibre
 * normals and its fitted masking term, written once for the kernels (float) and the host's
 * sheen albedo table (double, host/tables/layer_albedo.cpp). Local frame: z is the macro
 * normal. */
#ifndef PATHCL_CLOSURE_SHEEN_H
#define PATHCL_CLOSURE_SHEEN_H

#include "util/compat.h"

/* alpha = sheenRoughness^2, raised to this: at alpha 0 the distribution is 0 x infinity,
 * and below it the lobe reflects nothing but at exactly grazing angles. */
#define SHEEN_ALPHA_MIN 1.0e-3f

PATHCL_BEGIN

/* The Charlie distribution D(h) = (2 + 1/alpha) sin(theta_h)^(1/alpha) / (2 pi), from
 * sin^2 theta_h; normalized: the integral of D cos theta_h over the hemisphere is 1. */
PATHCL_FN pcl_real sheen_d(pcl_real sin2_h, pcl_real alpha)
{
    pcl_real inv = PCL_REAL(1.0) / alpha;
    return (PCL_REAL(2.0) + inv) * pow(fmax(sin2_h, PCL_REAL(0.0)), PCL_REAL(0.5) * inv) *
           PCL_REAL(0.159154943091895336);
}

/* The fit L(x) of the masking exponent, its five parameters interpolated in (1 - alpha)^2. */
PATHCL_FN pcl_real sheen_l(pcl_real x, pcl_real alpha)
{
    pcl_real t = (PCL_REAL(1.0) - alpha) * (PCL_REAL(1.0) - alpha);
    pcl_real a = PCL_REAL(21.5473) + (PCL_REAL(25.3245) - PCL_REAL(21.5473)) * t;
    pcl_real b = PCL_REAL(3.82987) + (PCL_REAL(3.32435) - PCL_REAL(3.82987)) * t;
    pcl_real c = PCL_REAL(0.19823) + (PCL_REAL(0.16801) - PCL_REAL(0.19823)) * t;
    pcl_real d = PCL_REAL(-1.97760) + (PCL_REAL(-1.27393) - PCL_REAL(-1.97760)) * t;
    pcl_real e = PCL_REAL(-4.32054) + (PCL_REAL(-4.85967) - PCL_REAL(-4.32054)) * t;
    return a / (PCL_REAL(1.0) + b * pow(x, c)) + d * x + e;
}

/* Lambda(cos theta): exp(L(cos)) below cos 0.5, exp(2 L(0.5) - L(1 - cos)) above. */
PATHCL_FN pcl_real sheen_lambda(pcl_real cos_theta, pcl_real alpha)
{
    pcl_real c = fabs(cos_theta);
    return c < PCL_REAL(0.5) ? exp(sheen_l(c, alpha))
                             : exp(PCL_REAL(2.0) * sheen_l(PCL_REAL(0.5), alpha) - sheen_l(PCL_REAL(1.0) - c, alpha));
}

/* f cos theta_i of the lobe with sheen colour 1: D G / (4 cos_o), G = 1 / (1 + Lambda(cos_o)
 * + Lambda(cos_i)); wo and wi above the surface. */
PATHCL_FN pcl_real sheen_f_cos(pcl_real3 wo, pcl_real3 wi, pcl_real alpha)
{
    pcl_real3 h = wo + wi;
    pcl_real len2 = h.x * h.x + h.y * h.y + h.z * h.z;
    if (!(len2 > PCL_REAL(0.0)) || !(wo.z > PCL_REAL(0.0)) || !(wi.z > PCL_REAL(0.0)))
        return PCL_REAL(0.0);
    pcl_real sin2_h = (h.x * h.x + h.y * h.y) / len2;
    pcl_real g = PCL_REAL(1.0) / (PCL_REAL(1.0) + sheen_lambda(wo.z, alpha) + sheen_lambda(wi.z, alpha));
    return sheen_d(sin2_h, alpha) * g / (PCL_REAL(4.0) * wo.z);
}

PATHCL_END

#endif
