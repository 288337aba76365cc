// An independent double-precision host implementation of the material model in
// kernels/closure/bsdf.cl (glTF metallic-roughness with KHR_materials_specular, _transmission,
// _ior and _volume), written from the formulas in that file's header comment rather than
// from its code. The BSDF tests compare the kernels' values and pdfs with it and use its
// pdf for the chi-square tests of the kernels' samplers.
//
// Local shading frame: the normal is +Z and wo.z > 0 is the side the ray came from.
#pragma once

#include <glm/vec3.hpp>

#include "closure/layer_table.h"
#include "types.h"

namespace pathcl::test {

// GGX (Trowbridge-Reitz) normal distribution D(m) and Smith's masking G1(w) for alpha,
// and anisotropic, for alpha ax along x and ay along y.
double ggx_d(const glm::dvec3& m, double alpha);
double ggx_g1(const glm::dvec3& w, double alpha);
double ggx_d(const glm::dvec3& m, double ax, double ay);
double ggx_g1(const glm::dvec3& w, double ax, double ay);

struct ReferenceBsdf {
    glm::dvec3 base_color{1.0}, specular_color{1.0};
    double specular = 1.0, metallic = 0.0, alpha = 1.0, transmission = 0.0;
    // KHR_materials_anisotropy: the conductor's alpha along x (the direction) and along y,
    // both alpha when isotropic; the roughness its albedo table is read at (with
    // sqrt(alpha_t)).
    double alpha_t = 1.0, alpha_b = 1.0, perceptual_roughness = 1.0;
    double eta = 1.5; // ior of the side wi refracts into over the ior of wo's side
    double ior = 1.5;
    bool thin = true;
    bool inside = false;                 // wo inside a solid: no diffuse base
    double coat = 0.0, coat_alpha = 0.0; // KHR_materials_clearcoat factor and GGX alpha
    glm::dvec3 sheen_color{0.0};         // KHR_materials_sheen colour (0: none) and roughness
    double sheen_roughness = 0.0;

    // The material as the kernel reads it, hit from the front (eta = ior) or the back.
    static ReferenceBsdf from_material(const Material& m, bool front_face);

    bool rough() const;           // false: the dielectric's specular lobes are delta functions
    bool conductor_rough() const; // false: the conductor is an ideal mirror
    bool anisotropic() const { return alpha_t != alpha_b; }
    // The dielectric layer shares the conductor's anisotropic alphas, except on a solid
    // that transmits and at ior 0.
    bool layer_anisotropic() const { return anisotropic() && !(transmission > 0.0 && !thin) && ior != 0.0; }

    // f(wo, wi) |cos theta_i| over the non-delta lobes.
    glm::dvec3 f_cos(const glm::dvec3& wo, const glm::dvec3& wi) const;
    // Solid-angle density with which the kernel's sampler returns wi (non-delta lobes).
    double pdf(const glm::dvec3& wo, const glm::dvec3& wi) const;

    // Lobe selection probabilities at cos theta_o (delta lobes included): the diffuse
    // base (with the conductor's multiple scattering), the conductor, the interface.
    struct Lobes {
        double diffuse, conductor, interface, coat, sheen;
    };
    Lobes lobes(const glm::dvec3& wo) const;
    // Probability that the interface reflects (not refracts) at a facet seen at cos c.
    double interface_split(double c, const glm::dvec3& wo) const;

private:
    // lobes() for the last wo asked (the chi-square integration asks millions of times).
    mutable glm::dvec3 cached_wo_{0.0, 0.0, -2.0};
    mutable Lobes cached_lobes_{};

public:
    // Reflectance of the specular reflection lobe and transmittance weight of the
    // transmission lobe (without the 1/eta^2 radiance scaling) at cos(wo, microfacet),
    // with the rough interface's energy compensation for wo.
    glm::dvec3 specular_reflectance(double cos_h, const glm::dvec3& wo) const;
    glm::dvec3 transmittance(double cos_h, const glm::dvec3& wo) const;

    // Multiple-scattering compensation (see kernels/closure/bsdf.cl): the GGX albedo with Fresnel
    // 1 and its average, the rough dielectric interface's energy albedo, the factor that
    // divides the interface's lobes, and the conductor's Kulla-Conty lobe.
    double ess(double cos_theta) const;
    double ess_average() const;
    double interface_albedo(double cos_theta) const;
    double glass_scale(const glm::dvec3& wo) const;
    // The conductor's: ess, or with anisotropy the E_aniso table at w's cos theta and
    // azimuth, and its average; the Kulla-Conty lobe they make.
    double conductor_albedo(const glm::dvec3& w) const;
    double conductor_albedo_average() const;
    glm::dvec3 multiple_scattering_f_cos(const glm::dvec3& wo, const glm::dvec3& wi) const;

    // The dielectric layer's directional albedo E(cos theta) and its cosine-weighted
    // average, as the kernels read them: interpolated from layer_albedo_table() for a
    // rough layer, exact for a smooth one; towards w, anisotropic or not.
    glm::dvec3 layer_albedo(double cos_theta) const;
    glm::dvec3 layer_albedo(const glm::dvec3& w) const;
    glm::dvec3 layer_average() const;

    // The clear coat: its directional albedo with factor 1 (ior 1.5; from the table when
    // rough, exact when smooth), and the factor 1 - coat max(E_c(|cos_o|), E_c(|cos_i|))
    // that scales every base lobe.
    double coat_albedo(double cos_theta) const;
    double coat_scale(double cos_o, double cos_i) const;

    // The sheen: its lobe's directional albedo with colour 1 (from the table, as the kernels
    // read it), and its lobe f cos with colour 1, D G / (4 cos_o), from the extension's
    // formulas (not divided by max(1, E)).
    double sheen_albedo(double cos_theta) const;
    double sheen_lobe(const glm::dvec3& wo, const glm::dvec3& wi) const;

private:
    // Everything but the coat (the base material's lobes, unscaled).
    glm::dvec3 base_f_cos(const glm::dvec3& wo, const glm::dvec3& wi) const;
};

} // namespace pathcl::test
