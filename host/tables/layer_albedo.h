// Directional albedo of the dielectric specular layer of the glTF material (GGX
// reflection with the normalized exact-Fresnel curve of kernels/closure/fresnel.h), tabulated over
// cos theta, roughness and ior for the kernels' albedo scaling of the diffuse base. The
// layout is defined in kernels/closure/layer_table.h (LAYER_*). The table is computed at build
// time by host/tables/make_layer_albedo_table.cpp, which calls compute_layer_albedo_table.
#pragma once

#include <vector>

#include "closure/fresnel.h"

namespace pathcl {

// The table the kernels read (LAYER_TABLE_SIZE floats), generated at build time.
const std::vector<float>& layer_albedo_table();

// Computes the table: each entry by integrate_layer_albedo with `panels` panels; the
// hemispherical averages integrate the piecewise-linear interpolant the kernels read, so
// the diffuse lobe's albedo is exactly 1 - E for the values the kernels use.
std::vector<float> compute_layer_albedo_table(int panels = 32);

// Albedo of the GGX reflection lobe (separable Smith G) from cos theta at the given
// roughness (alpha = roughness^2): with Fresnel 1 (the result) and with the normalized
// Fresnel curve of each eta in `etas` (into b; eta 0: Schlick's curve, see layer_curve).
// Gauss-Legendre over the visible-normal cap with the horizon located per azimuth:
// accurate to about 1e-4 at 16 panels.
double integrate_layer_albedo(double cos_theta, double roughness, const std::vector<double>& etas,
                              std::vector<double>& b, int panels = 16);

// Energy albedo (reflection plus refraction, no 1/eta^2 radiance factor) of a rough
// dielectric interface with the exact Fresnel factor, seen from the side wo is on; eta =
// far ior / near ior (< 1 from inside a solid). 1 for a smooth interface; below 1 by the
// energy that single-scattering microfacets lose to masking.
double integrate_dielectric_albedo(double cos_theta, double roughness, double eta, int panels = 16);

struct LayerAlbedo {
    double e_ss; // albedo with Fresnel 1
    double b;    // albedo with the normalized Fresnel curve s(c)
};
LayerAlbedo integrate_layer_albedo(double cos_theta, double roughness, double eta, int panels = 16);

// Directional albedo of the KHR_materials_sheen lobe with colour 1 (closure/sheen.h) from
// cos theta at sheenRoughness `roughness`, by Gauss-Legendre over the hemisphere.
double integrate_sheen_albedo(double cos_theta, double roughness, int panels = 16);

// The albedo with Fresnel 1 of the anisotropic GGX lobe of KHR_materials_anisotropy with
// alpha_t = along^2 along the direction and alpha_b = ggx_anisotropic_alpha_b(roughness^2,
// alpha_t) across it (closure/ggx.h), from the
// direction at cos theta whose azimuth phi from the anisotropy direction has cosine
// cos_phi, by the quadrature of integrate_layer_albedo over the whole cap of visible
// normals (1 for a mirror).
double integrate_anisotropic_albedo(double cos_theta, double cos_phi, double along, double roughness, int panels = 16);

// The same lobe's albedo with Fresnel 1 (the result) and with the normalized Fresnel
// curve of each eta in `etas` (into b): the dielectric layer of an anisotropic material.
double integrate_anisotropic_layer_albedo(double cos_theta, double cos_phi, double along, double roughness,
                                          const std::vector<double>& etas, std::vector<double>& b, int panels = 16);

// integrate_dielectric_albedo for the anisotropic lobe (alpha as above).
double integrate_anisotropic_dielectric_albedo(double cos_theta, double cos_phi, double along, double roughness,
                                               double eta, int panels = 16);

// 2 * integral of layer_curve(mu, eta) mu dmu: the smooth layer's hemispherical average
// of the normalized Fresnel curve (Schlick's for eta 0: 1/21), exact (the kernels use it
// below ALPHA_DELTA).
double smooth_layer_average(double eta);

// fresnel_dielectric and normalized_fresnel, the Fresnel curves the tables integrate, are
// the kernels' own (kernels/closure/fresnel.h, in double here).

} // namespace pathcl
