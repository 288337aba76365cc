#include "support/reference_bsdf.h"

#include "tables/layer_albedo.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

namespace pathcl::test {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kAlphaDelta = 1e-3; // kernels/closure/ggx.h ALPHA_DELTA

double max3(const glm::dvec3& v)
{
    return std::max(v.x, std::max(v.y, v.z));
}

double mean3(const glm::dvec3& v)
{
    return (v.x + v.y + v.z) / 3.0;
}

// Heitz's distribution of visible normals: G1(wo) max(0, wo.m) D(m) / wo.z.
double visible_normal_pdf(const glm::dvec3& wo, const glm::dvec3& m, double ax, double ay)
{
    double c = glm::dot(wo, m);
    if (c <= 0.0 || wo.z <= 0.0)
        return 0.0;
    return ggx_g1(wo, ax, ay) * c * ggx_d(m, ax, ay) / wo.z;
}

double visible_normal_pdf(const glm::dvec3& wo, const glm::dvec3& m, double alpha)
{
    return visible_normal_pdf(wo, m, alpha, alpha);
}

} // namespace

double ggx_d(const glm::dvec3& m, double alpha)
{
    if (m.z <= 0.0)
        return 0.0;
    double cos2 = m.z * m.z, tan2 = (1.0 - cos2) / cos2, a2 = alpha * alpha;
    double k = a2 + tan2;
    return a2 / (kPi * cos2 * cos2 * k * k);
}

double ggx_g1(const glm::dvec3& w, double alpha)
{
    double cos2 = w.z * w.z;
    if (cos2 == 0.0)
        return 0.0;
    double tan2 = (1.0 - cos2) / cos2;
    double lambda = 0.5 * (std::sqrt(1.0 + alpha * alpha * tan2) - 1.0);
    return 1.0 / (1.0 + lambda);
}

// Heitz 2014: D = 1 / (pi ax ay cos^4 (1 + tan^2 (cos^2 phi / ax^2 + sin^2 phi / ay^2))^2),
// Lambda = (sqrt(1 + a(phi)^2 tan^2) - 1) / 2 with a(phi)^2 = ax^2 cos^2 phi + ay^2 sin^2 phi.
double ggx_d(const glm::dvec3& m, double ax, double ay)
{
    if (m.z <= 0.0)
        return 0.0;
    double cos2 = m.z * m.z, sin2 = std::max(0.0, 1.0 - cos2), tan2 = sin2 / cos2;
    double c2 = sin2 > 0.0 ? m.x * m.x / sin2 : 1.0, s2 = sin2 > 0.0 ? m.y * m.y / sin2 : 0.0;
    double k = 1.0 + tan2 * (c2 / (ax * ax) + s2 / (ay * ay));
    return 1.0 / (kPi * ax * ay * cos2 * cos2 * k * k);
}

double ggx_g1(const glm::dvec3& w, double ax, double ay)
{
    double cos2 = w.z * w.z;
    if (cos2 == 0.0)
        return 0.0;
    double sin2 = std::max(0.0, 1.0 - cos2), tan2 = sin2 / cos2;
    double c2 = sin2 > 0.0 ? w.x * w.x / sin2 : 1.0, s2 = sin2 > 0.0 ? w.y * w.y / sin2 : 0.0;
    double a2 = ax * ax * c2 + ay * ay * s2;
    double lambda = 0.5 * (std::sqrt(1.0 + a2 * tan2) - 1.0);
    return 1.0 / (1.0 + lambda);
}

ReferenceBsdf ReferenceBsdf::from_material(const Material& m, bool front_face)
{
    ReferenceBsdf r;
    r.base_color = {m.base_color.x, m.base_color.y, m.base_color.z};
    r.specular_color = {m.specular_color.x, m.specular_color.y, m.specular_color.z};
    r.specular = m.specular_color.w;
    r.metallic = m.metallic;
    r.alpha = r.alpha_t = r.alpha_b = static_cast<double>(m.roughness) * m.roughness;
    r.perceptual_roughness = m.roughness;
    if (m.anisotropy.x > 0.0f) {
        // KHR_materials_anisotropy on the conductor: mix(alpha, 1, strength^2) along the
        // direction; across it the material's alpha, at least kAlphaDelta when rough.
        double s = m.anisotropy.x;
        r.alpha_t = r.alpha + (1.0 - r.alpha) * s * s;
        r.alpha_b = r.alpha_t >= kAlphaDelta ? std::max(r.alpha, kAlphaDelta) : r.alpha_t;
    }
    r.transmission = m.transmission;
    r.thin = (m.flags & MATERIAL_THIN_WALLED) != 0;
    r.ior = m.ior;
    r.inside = !r.thin && !front_face && m.transmission > 0.0f;
    // The kernel's own float 1/ior: near the critical angle F depends on eta so steeply
    // that the double quotient alone moves it by a percent.
    r.eta = r.inside ? static_cast<double>(1.0f / m.ior) : m.ior;
    r.coat = m.clearcoat;
    r.coat_alpha = static_cast<double>(m.clearcoat_roughness) * m.clearcoat_roughness;
    r.sheen_color = {m.sheen.x, m.sheen.y, m.sheen.z};
    r.sheen_roughness = m.sheen.w;
    return r;
}

bool ReferenceBsdf::rough() const
{
    return layer_anisotropic() || alpha >= kAlphaDelta;
}

// The interface lobe's alphas along x and y: the conductor's where the layer is anisotropic.
static double interface_ax(const ReferenceBsdf& b)
{
    return b.layer_anisotropic() ? b.alpha_t : b.alpha;
}

static double interface_ay(const ReferenceBsdf& b)
{
    return b.layer_anisotropic() ? b.alpha_b : b.alpha;
}

bool ReferenceBsdf::conductor_rough() const
{
    return alpha_t >= kAlphaDelta;
}

// The dielectric layer: KHR_materials_specular's F0 colour and weight, with the exact
// Fresnel curve normalized to run from F0 (normal incidence) to 1 (grazing or TIR); ior
// 0 (specular-glossiness mode): F0 = 1 and Schlick's (1 - c)^5.
static glm::dvec3 layer_fresnel(const ReferenceBsdf& b, double cos_h)
{
    double r = (b.ior - 1.0) / (b.ior + 1.0), f0 = r * r;
    double s = f0 < 1.0 ? std::clamp((fresnel_dielectric(cos_h, b.eta) - f0) / (1.0 - f0), 0.0, 1.0) : 1.0;
    if (b.ior == 0.0)
        s = std::pow(1.0 - std::clamp(cos_h, 0.0, 1.0), 5.0);
    glm::dvec3 f0c = glm::min(f0 * b.specular_color, glm::dvec3(1.0));
    return b.specular * (f0c + (glm::dvec3(1.0) - f0c) * s);
}

static double base_weight(const ReferenceBsdf& b, const glm::dvec3& layer)
{
    return (1.0 - b.metallic) * (1.0 - max3(layer));
}

// Linear interpolation of the table at continuous grid coordinates, written out
// independently of the kernels' layer_bilinear.
static double table_at(const std::vector<float>& t, int offset, int cols, double row, int rows, double col)
{
    int r0 = std::min(static_cast<int>(row), rows - 2), c0 = std::min(static_cast<int>(col), cols - 2);
    double fr = row - r0, fc = col - c0;
    auto v = [&](int r, int c) { return static_cast<double>(t[static_cast<std::size_t>(offset + r * cols + c)]); };
    return (1 - fr) * ((1 - fc) * v(r0, c0) + fc * v(r0, c0 + 1)) +
           fr * ((1 - fc) * v(r0 + 1, c0) + fc * v(r0 + 1, c0 + 1));
}

// The tables' E_ss and B at roughness row `row` (continuous), ior coordinate x and column
// `col` (sqrt(cos theta) on the grid): a rough dielectric layer reflects f0 (E_ss - B) + B.
// Shared by the specular layer and the clear coat.
static std::pair<double, double> ess_and_b(double row, double x, double col)
{
    const std::vector<float>& t = layer_albedo_table();
    double e_ss = table_at(t, LAYER_TABLE_ESS, LAYER_MU_RES, row, LAYER_ROUGH_RES, col);
    int x0 = std::min(static_cast<int>(x), LAYER_ETA_RES - 2);
    const int block = LAYER_ROUGH_RES * LAYER_MU_RES;
    double b0 = table_at(t, LAYER_TABLE_B + x0 * block, LAYER_MU_RES, row, LAYER_ROUGH_RES, col);
    double b1 = table_at(t, LAYER_TABLE_B + (x0 + 1) * block, LAYER_MU_RES, row, LAYER_ROUGH_RES, col);
    return {e_ss, b0 + (x - x0) * (b1 - b0)};
}

static glm::dvec3 f0_colour(const ReferenceBsdf& b)
{
    double r = (b.ior - 1.0) / (b.ior + 1.0);
    return glm::min(r * r * b.specular_color, glm::dvec3(1.0));
}

// The anisotropic layer's ior coordinate: x = (ior - 1) / (ior + 1) on the grid
// LAYER_X_MAX (k / (LAYER_ANISO_ETA_RES - 1))^2.
static double aniso_ior_coordinate(const ReferenceBsdf& m)
{
    double r = (m.ior - 1.0) / (m.ior + 1.0);
    return std::sqrt(std::clamp(r / LAYER_X_MAX, 0.0, 1.0)) * (LAYER_ANISO_ETA_RES - 1);
}

glm::dvec3 ReferenceBsdf::layer_albedo(double mu) const
{
    glm::dvec3 f0c = f0_colour(*this);
    if (!rough()) {
        double s = ior == 0.0 ? std::pow(1.0 - std::clamp(mu, 0.0, 1.0), 5.0) : normalized_fresnel(mu, eta);
        return specular * (f0c + (glm::dvec3(1.0) - f0c) * s);
    }
    double roughness = std::sqrt(alpha), r = (ior - 1.0) / (ior + 1.0);
    double row = roughness * (LAYER_ROUGH_RES - 1), x = std::clamp(r / LAYER_X_MAX, 0.0, 1.0) * (LAYER_ETA_RES - 1);
    double col = std::sqrt(std::clamp(mu, 0.0, 1.0)) * (LAYER_MU_RES - 1);
    auto [e_ss, b] = ess_and_b(row, x, col);
    if (ior == 0.0) // the Schlick row after the ior grid
        b = table_at(layer_albedo_table(), LAYER_TABLE_B + LAYER_ETA_RES * LAYER_ROUGH_RES * LAYER_MU_RES, LAYER_MU_RES,
                     row, LAYER_ROUGH_RES, col);
    return specular * (f0c * (e_ss - b) + b);
}

glm::dvec3 ReferenceBsdf::layer_average() const
{
    glm::dvec3 f0c = f0_colour(*this);
    double e_ss, b;
    if (layer_anisotropic()) {
        if (specular <= 0.0)
            return glm::dvec3(0.0);
        double x = aniso_ior_coordinate(*this);
        int x0 = std::min(static_cast<int>(x), LAYER_ANISO_ETA_RES - 2);
        const int per_ior = LAYER_ANISO_T_RES * LAYER_ANISO_ROUGH_RES;
        auto avg = [&](int k) {
            return table_at(layer_albedo_table(), LAYER_TABLE_ANISO_B_AVG + k * per_ior, LAYER_ANISO_ROUGH_RES,
                            std::sqrt(alpha_t) * (LAYER_ANISO_T_RES - 1), LAYER_ANISO_T_RES,
                            perceptual_roughness * (LAYER_ANISO_ROUGH_RES - 1));
        };
        e_ss = conductor_albedo_average();
        b = avg(x0) + (x - x0) * (avg(x0 + 1) - avg(x0));
    } else if (!rough()) {
        e_ss = 1.0;
        b = smooth_layer_average(ior);
    } else {
        const std::vector<float>& t = layer_albedo_table();
        double roughness = std::sqrt(alpha), r = (ior - 1.0) / (ior + 1.0);
        double row = roughness * (LAYER_ROUGH_RES - 1), x = std::clamp(r / LAYER_X_MAX, 0.0, 1.0) * (LAYER_ETA_RES - 1);
        e_ss = table_at(t, LAYER_TABLE_ESS_AVG, LAYER_ROUGH_RES, 0.0, 2, row);
        b = table_at(t, LAYER_TABLE_B_AVG, LAYER_ROUGH_RES, x, LAYER_ETA_RES, row);
        if (ior == 0.0)
            b = table_at(t, LAYER_TABLE_B_AVG + LAYER_ETA_RES * LAYER_ROUGH_RES, LAYER_ROUGH_RES, 0.0, 2, row);
    }
    return specular * (f0c * (e_ss - b) + b);
}

// Continuous table coordinates of this material's roughness and ior.
static double rough_row(const ReferenceBsdf& b)
{
    return std::sqrt(b.alpha) * (LAYER_ROUGH_RES - 1);
}

static double mu_col(double mu)
{
    return std::sqrt(std::clamp(mu, 0.0, 1.0)) * (LAYER_MU_RES - 1);
}

double ReferenceBsdf::ess(double mu) const
{
    return table_at(layer_albedo_table(), LAYER_TABLE_ESS, LAYER_MU_RES, rough_row(*this), LAYER_ROUGH_RES, mu_col(mu));
}

double ReferenceBsdf::ess_average() const
{
    return table_at(layer_albedo_table(), LAYER_TABLE_ESS_AVG, LAYER_ROUGH_RES, 0.0, 2, rough_row(*this));
}

double ReferenceBsdf::interface_albedo(double mu) const
{
    double r = (ior - 1.0) / (ior + 1.0);
    double x = std::clamp(r / LAYER_X_MAX, 0.0, 1.0) * (LAYER_GLASS_ETA_RES - 1);
    int x0 = std::min(static_cast<int>(x), LAYER_GLASS_ETA_RES - 2);
    int base = inside ? LAYER_TABLE_GLASS_IN : LAYER_TABLE_GLASS_OUT;
    const int block = LAYER_ROUGH_RES * LAYER_MU_RES;
    const std::vector<float>& t = layer_albedo_table();
    double g0 = table_at(t, base + x0 * block, LAYER_MU_RES, rough_row(*this), LAYER_ROUGH_RES, mu_col(mu));
    double g1 = table_at(t, base + (x0 + 1) * block, LAYER_MU_RES, rough_row(*this), LAYER_ROUGH_RES, mu_col(mu));
    return g0 + (x - x0) * (g1 - g0);
}

double ReferenceBsdf::glass_scale(const glm::dvec3& wo) const
{
    bool exact_fresnel = specular == 1.0 && specular_color == glm::dvec3(1.0);
    if (!rough() || transmission <= 0.0 || !exact_fresnel)
        return 1.0;
    double cos_o = std::max(wo.z, 0.0);
    double g = thin ? (layer_anisotropic() ? conductor_albedo(glm::dvec3(wo.x, wo.y, cos_o)) : ess(cos_o))
                    : interface_albedo(cos_o);
    return g > 1e-3 ? 1.0 / g : 1.0;
}

// An anisotropic table (E_aniso, or B_aniso of one ior) as the kernels read it, written
// out independently: bilinear in (|cos phi|, cos theta^(1/4)) within each (sqrt(alpha_t),
// roughness) block, then linear in those.
static double aniso_table_at(const ReferenceBsdf& m, int table, const glm::dvec3& w)
{
    const std::vector<float>& t = layer_albedo_table();
    double xy2 = w.x * w.x + w.y * w.y, v = xy2 > 0.0 ? std::abs(w.x) / std::sqrt(xy2) : 1.0;
    double row = v * (LAYER_ANISO_V_RES - 1),
           col = std::pow(std::min(std::abs(w.z), 1.0), 0.25) * (LAYER_ANISO_MU_RES - 1);
    double ft = std::sqrt(m.alpha_t) * (LAYER_ANISO_T_RES - 1),
           fr = m.perceptual_roughness * (LAYER_ANISO_ROUGH_RES - 1);
    int t0 = std::min(static_cast<int>(ft), LAYER_ANISO_T_RES - 2);
    int r0 = std::min(static_cast<int>(fr), LAYER_ANISO_ROUGH_RES - 2);
    auto block = [&](int si, int ri) {
        int offset = table + (si * LAYER_ANISO_ROUGH_RES + ri) * LAYER_ANISO_BLOCK;
        return table_at(t, offset, LAYER_ANISO_MU_RES, row, LAYER_ANISO_V_RES, col);
    };
    double a = ft - t0, b = fr - r0;
    return (1 - a) * ((1 - b) * block(t0, r0) + b * block(t0, r0 + 1)) +
           a * ((1 - b) * block(t0 + 1, r0) + b * block(t0 + 1, r0 + 1));
}

double ReferenceBsdf::conductor_albedo(const glm::dvec3& w) const
{
    if (!anisotropic())
        return ess(std::max(w.z, 0.0));
    return aniso_table_at(*this, LAYER_TABLE_ANISO, w);
}

double ReferenceBsdf::conductor_albedo_average() const
{
    if (!anisotropic())
        return ess_average();
    return table_at(layer_albedo_table(), LAYER_TABLE_ANISO_AVG, LAYER_ANISO_ROUGH_RES,
                    std::sqrt(alpha_t) * (LAYER_ANISO_T_RES - 1), LAYER_ANISO_T_RES,
                    perceptual_roughness * (LAYER_ANISO_ROUGH_RES - 1));
}

glm::dvec3 ReferenceBsdf::layer_albedo(const glm::dvec3& w) const
{
    if (!layer_anisotropic())
        return layer_albedo(std::max(w.z, 0.0));
    if (specular <= 0.0)
        return glm::dvec3(0.0);
    double x = aniso_ior_coordinate(*this);
    int x0 = std::min(static_cast<int>(x), LAYER_ANISO_ETA_RES - 2);
    const int per_ior = LAYER_ANISO_T_RES * LAYER_ANISO_ROUGH_RES * LAYER_ANISO_BLOCK;
    double b0 = aniso_table_at(*this, LAYER_TABLE_ANISO_B + x0 * per_ior, w);
    double b1 = aniso_table_at(*this, LAYER_TABLE_ANISO_B + (x0 + 1) * per_ior, w);
    double b = b0 + (x - x0) * (b1 - b0), e_ss = conductor_albedo(w);
    return specular * (f0_colour(*this) * (e_ss - b) + b);
}

glm::dvec3 ReferenceBsdf::multiple_scattering_f_cos(const glm::dvec3& wo, const glm::dvec3& wi) const
{
    if (!conductor_rough() || metallic <= 0.0)
        return glm::dvec3(0.0);
    double e_avg = conductor_albedo_average();
    if (1.0 - e_avg <= 1e-4)
        return glm::dvec3(0.0);
    glm::dvec3 f_avg = base_color + (glm::dvec3(1.0) - base_color) / 21.0;
    glm::dvec3 f_ms = f_avg * f_avg * e_avg / (glm::dvec3(1.0) - f_avg * (1.0 - e_avg));
    glm::dvec3 wo_up(wo.x, wo.y, std::max(wo.z, 0.0));
    return metallic * f_ms *
           ((1.0 - conductor_albedo(wo_up)) * (1.0 - conductor_albedo(wi)) / (kPi * (1.0 - e_avg)) * wi.z);
}

glm::dvec3 ReferenceBsdf::specular_reflectance(double cos_h, const glm::dvec3& wo) const
{
    double m = std::clamp(1.0 - cos_h, 0.0, 1.0);
    glm::dvec3 schlick = base_color + (glm::dvec3(1.0) - base_color) * std::pow(m, 5.0);
    double layer_scale = (1.0 - transmission) + transmission * glass_scale(wo);
    return metallic * schlick + (1.0 - metallic) * layer_scale * layer_fresnel(*this, cos_h);
}

glm::dvec3 ReferenceBsdf::transmittance(double cos_h, const glm::dvec3& wo) const
{
    return base_color * (base_weight(*this, layer_fresnel(*this, cos_h)) * transmission * glass_scale(wo));
}

ReferenceBsdf::Lobes ReferenceBsdf::lobes(const glm::dvec3& wo) const
{
    if (wo == cached_wo_)
        return cached_lobes_;
    const double cos_o = std::max(wo.z, 0.0);
    glm::dvec3 layer = layer_fresnel(*this, cos_o);
    glm::dvec3 e_o = inside ? glm::dvec3(0.0) : layer_albedo(glm::dvec3(wo.x, wo.y, cos_o));
    glm::dvec3 schlick = base_color + (glm::dvec3(1.0) - base_color) * std::pow(1.0 - cos_o, 5.0);
    Lobes l{};
    l.diffuse = inside ? 0.0 : (1.0 - metallic) * (1.0 - transmission) * mean3(base_color * (glm::dvec3(1.0) - e_o));
    if (conductor_rough() && metallic > 0.0 && 1.0 - conductor_albedo_average() > 1e-4) { // multiple scattering
        glm::dvec3 f_avg = base_color + (glm::dvec3(1.0) - base_color) / 21.0;
        double e_avg = conductor_albedo_average();
        glm::dvec3 f_ms = f_avg * f_avg * e_avg / (glm::dvec3(1.0) - f_avg * (1.0 - e_avg));
        l.diffuse += mean3(metallic * f_ms * (1.0 - conductor_albedo(glm::dvec3(wo.x, wo.y, cos_o))));
    }
    l.conductor = metallic * mean3(schlick);
    double dielectric_coat = mean3(inside ? layer : e_o);
    double glass = mean3(layer) + (1.0 - max3(layer)) * mean3(base_color);
    l.interface = (1.0 - metallic) * ((1.0 - transmission) * dielectric_coat + transmission * glass);
    const double floor = 0.02; // kernels/closure/lobes.cl LOBE_ESTIMATE_FLOOR
    bool has_interface = (specular > 0.0 && eta != 1.0) || transmission > 0.0;
    if (conductor_rough())
        l.conductor = std::max(l.conductor, floor * metallic);
    if (rough() && has_interface)
        l.interface = std::max(l.interface, floor * (1.0 - metallic));
    // Under a sheen the base lobes see what it does not reflect from wo (its albedo capped
    // at 1); the sheen reflects only from outside.
    if (max3(sheen_color) > 0.0) {
        double e = std::min(sheen_albedo(cos_o), 1.0);
        l.diffuse *= 1.0 - max3(sheen_color) * e;
        l.conductor *= 1.0 - max3(sheen_color) * e;
        l.interface *= 1.0 - max3(sheen_color) * e;
        l.sheen = inside ? 0.0 : std::max(mean3(sheen_color) * e, floor * max3(sheen_color));
    }
    // Under a coat the base lobes and the sheen see what it does not reflect from wo; the
    // coat reflects only from outside.
    double coat_o = coat > 0.0 ? coat * coat_albedo(cos_o) : 0.0;
    l.diffuse *= 1.0 - coat_o;
    l.conductor *= 1.0 - coat_o;
    l.interface *= 1.0 - coat_o;
    l.sheen *= 1.0 - coat_o;
    l.coat = inside ? 0.0 : coat_o;
    if (!inside && coat > 0.0 && coat_alpha >= kAlphaDelta)
        l.coat = std::max(l.coat, floor * coat);
    double sum = l.diffuse + l.conductor + l.interface + l.coat + l.sheen;
    if (sum > 0.0) {
        l.diffuse /= sum;
        l.conductor /= sum;
        l.interface /= sum;
        l.coat /= sum;
        l.sheen /= sum;
    }
    cached_wo_ = wo;
    cached_lobes_ = l;
    return l;
}

double ReferenceBsdf::interface_split(double c, const glm::dvec3& wo) const
{
    glm::dvec3 layer = layer_fresnel(*this, c);
    double layer_scale = (1.0 - transmission) + transmission * glass_scale(wo);
    double r = layer_scale * mean3(layer);
    double t = transmission * glass_scale(wo) * (1.0 - max3(layer)) * mean3(base_color);
    return r + t > 0.0 ? r / (r + t) : 1.0;
}

double ReferenceBsdf::coat_albedo(double mu) const
{
    const double coat_ior = 1.5, r = (coat_ior - 1.0) / (coat_ior + 1.0), f0 = r * r;
    if (coat_alpha < kAlphaDelta)
        return fresnel_dielectric(mu, coat_ior);
    double row = std::sqrt(coat_alpha) * (LAYER_ROUGH_RES - 1);
    auto [e_ss, b] = ess_and_b(row, r / LAYER_X_MAX * (LAYER_ETA_RES - 1), mu_col(mu));
    return f0 * (e_ss - b) + b;
}

double ReferenceBsdf::coat_scale(double cos_o, double cos_i) const
{
    if (coat <= 0.0)
        return 1.0;
    return 1.0 - coat * std::max(coat_albedo(std::abs(cos_o)), coat_albedo(std::abs(cos_i)));
}

double ReferenceBsdf::sheen_albedo(double mu) const
{
    return table_at(layer_albedo_table(), LAYER_TABLE_SHEEN, LAYER_MU_RES, sheen_roughness * (LAYER_ROUGH_RES - 1),
                    LAYER_ROUGH_RES, mu_col(mu));
}

// KHR_materials_sheen's implementation notes: the "Charlie" distribution and visibility.
double ReferenceBsdf::sheen_lobe(const glm::dvec3& wo, const glm::dvec3& wi) const
{
    if (wo.z <= 0.0 || wi.z <= 0.0)
        return 0.0;
    double a_s = std::max(sheen_roughness * sheen_roughness, 1e-3); // SHEEN_ALPHA_MIN
    glm::dvec3 h = glm::normalize(wo + wi);
    double sin_h = std::sqrt(std::max(0.0, 1.0 - h.z * h.z));
    double d = (2.0 + 1.0 / a_s) * std::pow(sin_h, 1.0 / a_s) / (2.0 * kPi);
    auto l = [&](double x) {
        double t = (1.0 - a_s) * (1.0 - a_s);
        auto mix = [&](double a, double b) { return a + (b - a) * t; };
        return mix(21.5473, 25.3245) / (1.0 + mix(3.82987, 3.32435) * std::pow(x, mix(0.19823, 0.16801))) +
               mix(-1.97760, -1.27393) * x + mix(-4.32054, -4.85967);
    };
    auto lambda = [&](double c) { return c < 0.5 ? std::exp(l(c)) : std::exp(2.0 * l(0.5) - l(1.0 - c)); };
    double visibility = 1.0 / ((1.0 + lambda(wo.z) + lambda(wi.z)) * 4.0 * wo.z * wi.z);
    return d * visibility * wi.z;
}

glm::dvec3 ReferenceBsdf::f_cos(const glm::dvec3& wo, const glm::dvec3& wi) const
{
    glm::dvec3 f = base_f_cos(wo, wi);
    if (max3(sheen_color) > 0.0) {
        // The base keeps 1 - max3(colour) min(1, E), the lobe is divided by max(1, E), E the
        // larger of the two directions' sheen albedos.
        double e = std::max(sheen_albedo(std::abs(wo.z)), sheen_albedo(std::abs(wi.z)));
        f *= 1.0 - max3(sheen_color) * std::min(e, 1.0);
        if (!inside)
            f += sheen_color * (sheen_lobe(wo, wi) / std::max(e, 1.0));
    }
    f *= coat_scale(std::max(wo.z, 0.0), wi.z);
    if (coat > 0.0 && coat_alpha >= kAlphaDelta && !inside && wo.z > 0.0 && wi.z > 0.0) {
        glm::dvec3 h = glm::normalize(wo + wi);
        double c = glm::dot(wo, h);
        f += glm::dvec3(coat * fresnel_dielectric(c, 1.5) * ggx_d(h, coat_alpha) * ggx_g1(wo, coat_alpha) *
                        ggx_g1(wi, coat_alpha) / (4.0 * wo.z));
    }
    return f;
}

glm::dvec3 ReferenceBsdf::base_f_cos(const glm::dvec3& wo, const glm::dvec3& wi) const
{
    if (wi.z > 0.0) {
        glm::dvec3 h = glm::normalize(wo + wi);
        double c = std::abs(glm::dot(wo, h));
        glm::dvec3 f(0.0);
        if (!inside) {
            // Albedo-scaled diffuse base (Kelemen and Szirmay-Kalos 2001).
            glm::dvec3 norm = glm::dvec3(1.0) - layer_average();
            for (int ch = 0; ch < 3; ++ch)
                if (norm[ch] > 1e-6)
                    f[ch] = base_color[ch] * (1.0 - metallic) * (1.0 - transmission) / kPi *
                            (1.0 - layer_albedo(glm::dvec3(wo.x, wo.y, std::max(wo.z, 0.0)))[ch]) *
                            (1.0 - layer_albedo(wi)[ch]) / norm[ch] * wi.z;
        }
        f += multiple_scattering_f_cos(wo, wi);
        if (wo.z > 0.0 && anisotropic()) {
            // The conductor's anisotropic lobe, then the dielectric layer's (anisotropic alike
            // unless on a transmitting solid).
            glm::dvec3 schlick = base_color + (glm::dvec3(1.0) - base_color) * std::pow(1.0 - c, 5.0);
            f += metallic * schlick *
                 (ggx_d(h, alpha_t, alpha_b) * ggx_g1(wo, alpha_t, alpha_b) * ggx_g1(wi, alpha_t, alpha_b) /
                  (4.0 * wo.z));
            double ax = interface_ax(*this), ay = interface_ay(*this);
            if (rough())
                f += (specular_reflectance(c, wo) - metallic * schlick) *
                     (ggx_d(h, ax, ay) * ggx_g1(wo, ax, ay) * ggx_g1(wi, ax, ay) / (4.0 * wo.z));
        } else if (rough() && wo.z > 0.0) {
            f += specular_reflectance(c, wo) * (ggx_d(h, alpha) * ggx_g1(wo, alpha) * ggx_g1(wi, alpha) / (4.0 * wo.z));
        }
        return f;
    }
    if (wi.z == 0.0 || !rough() || wo.z <= 0.0 || transmission <= 0.0)
        return glm::dvec3(0.0);
    if (thin) {
        glm::dvec3 mirrored(wi.x, wi.y, -wi.z);
        glm::dvec3 m = glm::normalize(wo + mirrored);
        double c = glm::dot(wo, m);
        if (c <= 0.0)
            return glm::dvec3(0.0);
        double ax = interface_ax(*this), ay = interface_ay(*this);
        return transmittance(c, wo) * (ggx_d(m, ax, ay) * ggx_g1(wo, ax, ay) * ggx_g1(wi, ax, ay) / (4.0 * wo.z));
    }
    // Walter et al. 2007, radiance scaled by 1/eta^2 across the interface.
    glm::dvec3 m = glm::normalize(wi * eta + wo);
    if (m.z < 0.0)
        m = -m;
    double di = glm::dot(wi, m), dn = glm::dot(wo, m);
    if (dn <= 0.0 || di >= 0.0)
        return glm::dvec3(0.0);
    double denom = (di + dn / eta) * (di + dn / eta);
    double ft =
        ggx_d(m, alpha) * ggx_g1(wo, alpha) * ggx_g1(wi, alpha) * std::abs(di * dn) / (wo.z * denom * eta * eta);
    return transmittance(dn, wo) * ft;
}

double ReferenceBsdf::pdf(const glm::dvec3& wo, const glm::dvec3& wi) const
{
    Lobes l = lobes(wo);
    if (wi.z > 0.0) {
        double p = l.diffuse * wi.z / kPi; // diffuse and multiple-scattering lobes
        if (wo.z > 0.0)
            p += l.sheen / (2.0 * kPi); // the sheen, uniform over the hemisphere
        if (l.coat > 0.0 && coat_alpha >= kAlphaDelta && wo.z > 0.0) {
            glm::dvec3 h = glm::normalize(wo + wi);
            p += l.coat * visible_normal_pdf(wo, h, coat_alpha) / (4.0 * glm::dot(wo, h));
        }
        if (wo.z > 0.0 && anisotropic()) {
            glm::dvec3 h = glm::normalize(wo + wi);
            double c = std::abs(glm::dot(wo, h));
            p += l.conductor * visible_normal_pdf(wo, h, alpha_t, alpha_b) / (4.0 * c);
            if (rough())
                p += l.interface * interface_split(c, wo) *
                     visible_normal_pdf(wo, h, interface_ax(*this), interface_ay(*this)) / (4.0 * c);
        } else if (rough() && wo.z > 0.0) {
            glm::dvec3 h = glm::normalize(wo + wi);
            double c = std::abs(glm::dot(wo, h));
            double select = l.conductor + l.interface * interface_split(c, wo);
            p += select * visible_normal_pdf(wo, h, alpha) / (4.0 * c);
        }
        return p;
    }
    if (wi.z == 0.0 || !rough() || wo.z <= 0.0 || transmission <= 0.0)
        return 0.0;
    if (thin) {
        glm::dvec3 m = glm::normalize(wo + glm::dvec3(wi.x, wi.y, -wi.z));
        double c = glm::dot(wo, m);
        return c > 0.0 ? l.interface * (1.0 - interface_split(c, wo)) *
                             visible_normal_pdf(wo, m, interface_ax(*this), interface_ay(*this)) / (4.0 * c)
                       : 0.0;
    }
    glm::dvec3 m = glm::normalize(wi * eta + wo);
    if (m.z < 0.0)
        m = -m;
    double di = glm::dot(wi, m), dn = glm::dot(wo, m);
    if (dn <= 0.0 || di >= 0.0)
        return 0.0;
    double denom = (di + dn / eta) * (di + dn / eta);
    return l.interface * (1.0 - interface_split(dn, wo)) * visible_normal_pdf(wo, m, alpha) * std::abs(di) / denom;
}

} // namespace pathcl::test
