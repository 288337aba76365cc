// What the BSDF tests share: the test programs over tests/kernels/bsdf_test_kernels.cl,
// material specs turned into the kernels' Material, and runners that sample and evaluate
// a BSDF on the device and estimate its directional albedo from the samples.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "cl/cl_runtime.h"
#include "types.h"

namespace pathcl::test {

// The program with every closure (glossy, transmission, ior 0, clear coat, sheen,
// anisotropy), built once.
const cl::Program& full_program();
// The program a scene of Lambertian materials only gets (no glossy or transmission code).
const cl::Program& lambertian_program();

struct MaterialSpec {
    glm::vec3 base{1.0f};
    float metallic = 0.0f, roughness = 1.0f, transmission = 0.0f, ior = 1.5f;
    bool thin = true;
    float specular = 1.0f;
    glm::vec3 specular_color{1.0f};
    float clearcoat = 0.0f, clearcoat_roughness = 0.0f;
    glm::vec3 sheen{0.0f}; // KHR_materials_sheen colour and roughness
    float sheen_roughness = 0.0f;
    float anisotropy = 0.0f; // KHR_materials_anisotropy strength, along the frame's x axis
};

Material make_material(const MaterialSpec& s);
MaterialSpec conductor(float roughness, glm::vec3 base = glm::vec3(1.0f));
MaterialSpec dielectric(float roughness, float ior = 1.5f, bool thin = false);
MaterialSpec lambertian(glm::vec3 base);
// Lambertian, rough conductors, plastics (plain and tinted specular), a part metal, a
// specular-glossiness (ior 0) material, three clear-coated ones, four with a sheen and
// five anisotropic ones: the reflective materials the eval and energy tests sweep.
std::vector<MaterialSpec> reflective_materials();

// wo at angle theta from +Z with cos theta = c, in the xz plane turned by 0.3 rad about Z
// (so nothing lines up with the chi-square grid's cell edges).
glm::dvec3 incident(double c);

// The layer albedo tables, uploaded once.
const cl::Buffer& layer_buffer();

struct Samples {
    std::vector<pcl_float4> dir_pdf, weight, eval;
};

// test_bsdf_sample from wo, n samples: (direction, pdf), weight and bsdf_eval (f_cos, pdf)
// of each. The shading point's normal is +Z and its anisotropy direction `tangent` (in
// the XY plane).
Samples sample_bsdf(const cl::Program& program, const Material& m, const glm::dvec3& wo, bool front_face, std::size_t n,
                    std::uint32_t seed = 17, glm::dvec3 tangent = {1, 0, 0});

// bsdf_eval (f_cos, pdf) for each pair, at a shading point with this normal and
// anisotropy direction (orthogonal unit vectors).
std::vector<pcl_float4> eval_bsdf(const cl::Program& program, const Material& m, bool front_face,
                                  const std::vector<glm::dvec3>& wo, const std::vector<glm::dvec3>& wi,
                                  glm::dvec3 normal = {0, 0, 1}, glm::dvec3 tangent = {1, 0, 0});

// test_bsdf_lambertian_shortcut for each (wo, wi) pair, at a shading point with normal +Z
// (the full program): four float4 per pair each way, from the Lambertian shortcut and
// from every lobe's code (see the kernel).
struct ShortcutRun {
    std::vector<pcl_float4> shortcut, lobes;
};
ShortcutRun lambertian_shortcut(const Material& m, bool front_face, const std::vector<glm::dvec3>& wo,
                                const std::vector<glm::dvec3>& wi);

// test_bsdf_params_shortcut for each wo, at a shading point with normal +Z (the full
// program), for the Lambertian shortcut (ideal false) or the ideal mirror and glass one:
// three float4 per wo each way (the fields bsdf_params_base sets) as bsdf_params left them,
// as the shortcut sets them and as bsdf_params_base computes them; whether the shortcut's
// predicate held (1 or 0); and bsdf_sample's (wi, pdf), (weight, +-eta2) with numbers
// drawn from `seed`, from the shortcut's fields and then from the general ones (four
// float4 per wo).
struct ParamsShortcutRun {
    std::vector<pcl_float4> params, shortcut, general, samples;
    std::vector<float> admitted;
};
ParamsShortcutRun params_shortcut(const Material& m, bool front_face, bool ideal, const std::vector<glm::dvec3>& wo,
                                  std::uint32_t seed = 25);

glm::dvec3 xyz(const pcl_float4& v);

// |a - b| <= rel * max(|a|, |b|) + abs_floor.
bool near_rel(double a, double b, double rel, double abs_floor = 0.0);

struct Albedo {
    glm::dvec3 mean{0.0}, stderr_{0.0};
    std::size_t not_finite = 0;
};

// Directional albedo E[weight] from wo. Radiance crossing into a denser medium is
// scaled by 1/eta^2 (and out of it by eta^2); `energy` undoes that so the result is the
// fraction of energy scattered, which must not exceed 1.
Albedo directional_albedo(const cl::Program& program, const MaterialSpec& spec, double cos_o, bool front_face,
                          bool energy, std::size_t n = 200000, glm::dvec3 tangent = {1, 0, 0});

} // namespace pathcl::test
