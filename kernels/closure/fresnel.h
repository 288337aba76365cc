/* Fresnel reflectance of a dielectric interface, written once for the kernels (float) and
 * the host's layer albedo tables (double, host/tables/layer_albedo.cpp). */
#ifndef PATHCL_CLOSURE_FRESNEL_H
#define PATHCL_CLOSURE_FRESNEL_H

#include "util/compat.h"

PATHCL_BEGIN

/* Unpolarized Fresnel reflectance of a dielectric interface; cos_i >= 0 on the incident
 * side, eta = ior of the far side / ior of the incident side. 1 under total internal
 * reflection. */
PATHCL_FN pcl_real fresnel_dielectric(pcl_real cos_i, pcl_real eta)
{
    cos_i = clamp(cos_i, PCL_REAL(0.0), PCL_REAL(1.0));
    pcl_real sin2_t = (PCL_REAL(1.0) - cos_i * cos_i) / (eta * eta);
    if (sin2_t >= PCL_REAL(1.0))
        return PCL_REAL(1.0);
    pcl_real cos_t = sqrt(PCL_REAL(1.0) - sin2_t);
    pcl_real r_parallel = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
    pcl_real r_perpendicular = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
    return PCL_REAL(0.5) * (r_parallel * r_parallel + r_perpendicular * r_perpendicular);
}

/* The normalized Fresnel curve s(c) = (F(c, eta) - F0) / (1 - F0), clamped to [0, 1]: 0 at
 * normal incidence, 1 at grazing incidence and under total internal reflection. The
 * KHR_materials_specular layer scales and tints it (closure/bsdf.cl). */
PATHCL_FN pcl_real normalized_fresnel(pcl_real cos_i, pcl_real eta)
{
    pcl_real r = (eta - PCL_REAL(1.0)) / (eta + PCL_REAL(1.0));
    pcl_real f0 = r * r;
    pcl_real s = f0 < PCL_REAL(1.0) ? (fresnel_dielectric(cos_i, eta) - f0) / (PCL_REAL(1.0) - f0) : PCL_REAL(1.0);
    return clamp(s, PCL_REAL(0.0), PCL_REAL(1.0));
}

/* Schlick's weight (1 - c)^5: the normalized Fresnel curve of KHR_materials_ior's ior 0
 * (specular-glossiness mode: F0(ior) = 1, so specularColor alone is the normal-incidence
 * reflectance, rising to 1 at grazing incidence as glTF's Fresnel term does). */
PATHCL_FN pcl_real schlick_weight(pcl_real cos_i)
{
    pcl_real m = clamp(PCL_REAL(1.0) - cos_i, PCL_REAL(0.0), PCL_REAL(1.0));
    pcl_real m2 = m * m;
    return m2 * m2 * m;
}

/* The dielectric layer's normalized curve for a material's ior: the exact Fresnel curve,
 * or Schlick's for ior 0. */
PATHCL_FN pcl_real layer_curve(pcl_real cos_i, pcl_real eta)
{
    return eta == PCL_REAL(0.0) ? schlick_weight(cos_i) : normalized_fresnel(cos_i, eta);
}

PATHCL_END

#endif
