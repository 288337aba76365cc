#include "tables/layer_albedo.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <thread>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "closure/fresnel.h"
#include "closure/ggx.h"
#include "closure/layer_table.h"
#include "closure/sheen.h"

namespace pathcl {
namespace {

constexpr double kPi = std::numbers::pi;

// Smith G1 of the kernels (closure/ggx.h), for alpha.
double smith_g1(const glm::dvec3& w, double alpha)
{
    return ggx_g1(w, alpha * alpha);
}

// Grid values: sqrt(cos theta) (finer towards grazing, where the Fresnel curve bends),
// roughness and x = (eta - 1) / (eta + 1), each uniform.
double grid_mu(int i)
{
    double t = static_cast<double>(i) / (LAYER_MU_RES - 1);
    // mu = 0 exactly is a grazing ray that sees no microfacet; the albedo's limit is
    // taken just above it.
    return std::max(t * t, 1e-6);
}

// The anisotropy table's grids: cos theta^(1/4), |cos phi| and the two roughnesses
// (sqrt(alpha_t) and the material's), each uniform.
double aniso_grid_mu(int i)
{
    double t = static_cast<double>(i) / (LAYER_ANISO_MU_RES - 1);
    return std::max(t * t * t * t, 1e-6); // cos theta^(1/4): grazing angles, where E bends, get more points
}

double aniso_grid(int k, int n)
{
    return static_cast<double>(k) / (n - 1);
}

// The weights w_k of the average over phi in [0, pi/2] of a function linear in c =
// cos phi between the grid points c_k: the average of each hat function, in closed form.
std::vector<double> azimuth_weights()
{
    const int n = LAYER_ANISO_V_RES;
    std::vector<double> w(n, 0.0);
    for (int k = 0; k + 1 < n; ++k) {
        double c0 = aniso_grid(k, n), c1 = aniso_grid(k + 1, n);
        double p_hi = std::acos(c0), p_lo = std::acos(c1); // c grows as phi falls
        double span = p_hi - p_lo, cos_integral = std::sin(p_hi) - std::sin(p_lo);
        // f = f_k (c1 - c) / dc + f_k+1 (c - c0) / dc, integrated over phi.
        w[k] += (c1 * span - cos_integral) / (c1 - c0);
        w[k + 1] += (cos_integral - c0 * span) / (c1 - c0);
    }
    for (double& x : w)
        x /= kPi / 2.0;
    return w;
}

// The anisotropic layer's ior grid: x = LAYER_X_MAX (k / (n - 1))^2, denser towards
// ior 1, where B changes fastest with x (the normalized curve steps up at grazing angles
// for any ior above 1 and is 0 at ior 1).
double aniso_grid_eta(int k)
{
    double u = static_cast<double>(k) / (LAYER_ANISO_ETA_RES - 1);
    double x = static_cast<double>(LAYER_X_MAX) * u * u;
    return (1.0 + x) / (1.0 - x);
}

double grid_roughness(int j)
{
    return static_cast<double>(j) / (LAYER_ROUGH_RES - 1);
}

double grid_eta(int k)
{
    double x = static_cast<double>(LAYER_X_MAX) * k / (LAYER_ETA_RES - 1);
    return (1.0 + x) / (1.0 - x);
}

// 2 * integral over mu in [0, 1] of mu times the interpolant the kernels read: linear in
// t = sqrt(mu) between grid points, so 2 mu dmu = 4 t^3 dt.
double cosine_average(const float* f)
{
    double h = 1.0 / (LAYER_MU_RES - 1), sum = 0.0;
    for (int i = 0; i + 1 < LAYER_MU_RES; ++i) {
        double t0 = i * h, t1 = (i + 1) * h;
        double p4 = std::pow(t1, 4) - std::pow(t0, 4), p5 = std::pow(t1, 5) - std::pow(t0, 5);
        // f = (f_i (t1 - t) + f_i+1 (t - t0)) / h
        sum += (f[i] * (t1 * p4 - 0.8 * p5) + f[i + 1] * (0.8 * p5 - t0 * p4)) / h;
    }
    return sum;
}

// The same for the anisotropy table's interpolant, linear in t = cos theta^(1/4) between
// its LAYER_ANISO_MU_RES points: 2 mu dmu = 8 t^7 dt.
double quartic_cosine_average(const float* f)
{
    double h = 1.0 / (LAYER_ANISO_MU_RES - 1), sum = 0.0;
    for (int i = 0; i + 1 < LAYER_ANISO_MU_RES; ++i) {
        double t0 = i * h, t1 = (i + 1) * h;
        double p8 = std::pow(t1, 8) - std::pow(t0, 8), p9 = std::pow(t1, 9) - std::pow(t0, 9);
        // f = (f_i (t1 - t) + f_i+1 (t - t0)) / h, times 8 t^7, integrated.
        sum += (f[i] * (t1 * p8 - 8.0 / 9.0 * p9) + f[i + 1] * (8.0 / 9.0 * p9 - t0 * p8)) / h;
    }
    return sum;
}

} // namespace

std::vector<float> compute_layer_albedo_table(int panels)
{
    std::vector<float> t(LAYER_TABLE_SIZE, 0.0f);
    auto ess = [&](int j, int i) -> float& { return t[LAYER_TABLE_ESS + j * LAYER_MU_RES + i]; };
    auto b = [&](int k, int j, int i) -> float& {
        return t[LAYER_TABLE_B + (k * LAYER_ROUGH_RES + j) * LAYER_MU_RES + i];
    };
    // The ior grid, then eta 0: ior 0's Schlick curve (layer_curve).
    std::vector<double> etas(LAYER_B_ROWS, 0.0), bs;
    for (int k = 0; k < LAYER_ETA_RES; ++k)
        etas[k] = grid_eta(k);
    for (int j = 0; j < LAYER_ROUGH_RES; ++j)
        for (int i = 0; i < LAYER_MU_RES; ++i) {
            if (j == 0) { // the smooth interface: a mirror with the Fresnel curve itself
                ess(j, i) = 1.0f;
                for (int k = 0; k < LAYER_B_ROWS; ++k)
                    b(k, j, i) = static_cast<float>(layer_curve(grid_mu(i), etas[k]));
                continue;
            }
            ess(j, i) = static_cast<float>(integrate_layer_albedo(grid_mu(i), grid_roughness(j), etas, bs, panels));
            for (int k = 0; k < LAYER_B_ROWS; ++k)
                b(k, j, i) = static_cast<float>(bs[k]);
        }
    for (int j = 0; j < LAYER_ROUGH_RES; ++j) {
        t[LAYER_TABLE_ESS_AVG + j] = static_cast<float>(cosine_average(&ess(j, 0)));
        for (int k = 0; k < LAYER_B_ROWS; ++k)
            t[LAYER_TABLE_B_AVG + k * LAYER_ROUGH_RES + j] = static_cast<float>(cosine_average(&b(k, j, 0)));
    }
    // Rough dielectric interfaces, from outside (eta = ior) and inside (eta = 1 / ior);
    // the smooth row loses nothing. Rows are independent: two threads share them.
    const int glass_block = LAYER_ROUGH_RES * LAYER_MU_RES;
    auto glass_rows = [&](int first, int step) {
        for (int row = first; row < 2 * LAYER_GLASS_ETA_RES * LAYER_ROUGH_RES; row += step) {
            int side = row / (LAYER_GLASS_ETA_RES * LAYER_ROUGH_RES), k = row / LAYER_ROUGH_RES % LAYER_GLASS_ETA_RES,
                j = row % LAYER_ROUGH_RES;
            double x = static_cast<double>(LAYER_X_MAX) * k / (LAYER_GLASS_ETA_RES - 1), ior = (1.0 + x) / (1.0 - x);
            int offset =
                (side == 0 ? LAYER_TABLE_GLASS_OUT : LAYER_TABLE_GLASS_IN) + k * glass_block + j * LAYER_MU_RES;
            for (int i = 0; i < LAYER_MU_RES; ++i)
                t[offset + i] = j == 0 ? 1.0f
                                       : static_cast<float>(integrate_dielectric_albedo(
                                             grid_mu(i), grid_roughness(j), side == 0 ? ior : 1.0 / ior, panels / 2));
        }
    };
    std::thread helper(glass_rows, 1, 2);
    glass_rows(0, 2);
    helper.join();
    for (int j = 0; j < LAYER_ROUGH_RES; ++j)
        for (int i = 0; i < LAYER_MU_RES; ++i)
            t[LAYER_TABLE_SHEEN + j * LAYER_MU_RES + i] =
                static_cast<float>(integrate_sheen_albedo(grid_mu(i), grid_roughness(j), panels / 4));
    // The anisotropic lobe, (sqrt(alpha_t), roughness) blocks shared by two threads, with
    // Fresnel 1 and with the normalized Fresnel curves of its own ior grid; then each
    // block's average over the hemisphere of the interpolant the kernels read (bilinear
    // in cos theta^(1/4) and |cos phi|).
    std::vector<double> aniso_etas(LAYER_ANISO_ETA_RES);
    for (int k = 0; k < LAYER_ANISO_ETA_RES; ++k)
        aniso_etas[static_cast<std::size_t>(k)] = aniso_grid_eta(k);
    const int aniso_blocks_n = LAYER_ANISO_T_RES * LAYER_ANISO_ROUGH_RES;
    auto aniso_b = [&](int k, int sr) { return LAYER_TABLE_ANISO_B + (k * aniso_blocks_n + sr) * LAYER_ANISO_BLOCK; };
    auto aniso_blocks = [&](int first, int step) {
        std::vector<double> b_row;
        for (int sr = first; sr < aniso_blocks_n; sr += step) {
            double along = aniso_grid(sr / LAYER_ANISO_ROUGH_RES, LAYER_ANISO_T_RES);
            double roughness = aniso_grid(sr % LAYER_ANISO_ROUGH_RES, LAYER_ANISO_ROUGH_RES);
            for (int c = 0; c < LAYER_ANISO_V_RES; ++c)
                for (int i = 0; i < LAYER_ANISO_MU_RES; ++i) {
                    int at = c * LAYER_ANISO_MU_RES + i;
                    t[LAYER_TABLE_ANISO + sr * LAYER_ANISO_BLOCK + at] = static_cast<float>(
                        integrate_anisotropic_layer_albedo(aniso_grid_mu(i), aniso_grid(c, LAYER_ANISO_V_RES), along,
                                                           roughness, aniso_etas, b_row, panels / 4));
                    for (int k = 0; k < LAYER_ANISO_ETA_RES; ++k)
                        t[aniso_b(k, sr) + at] = static_cast<float>(b_row[static_cast<std::size_t>(k)]);
                }
        }
    };
    std::thread aniso_helper(aniso_blocks, 1, 2);
    aniso_blocks(0, 2);
    aniso_helper.join();
    const std::vector<double> w = azimuth_weights();
    auto block_average = [&](int offset) {
        double avg = 0.0;
        for (int c = 0; c < LAYER_ANISO_V_RES; ++c)
            avg += w[static_cast<std::size_t>(c)] * quartic_cosine_average(&t[offset + c * LAYER_ANISO_MU_RES]);
        return static_cast<float>(avg);
    };
    for (int sr = 0; sr < aniso_blocks_n; ++sr) {
        t[LAYER_TABLE_ANISO_AVG + sr] = block_average(LAYER_TABLE_ANISO + sr * LAYER_ANISO_BLOCK);
        for (int k = 0; k < LAYER_ANISO_ETA_RES; ++k)
            t[LAYER_TABLE_ANISO_B_AVG + k * aniso_blocks_n + sr] = block_average(aniso_b(k, sr));
    }
    return t;
}

namespace {

// Integrates over the microfacet normals visible from wo, weighted by their density: a
// uniform point (phi, z) on the spherical cap of Dupuy and Benyoub maps to a normal m,
// and `accumulate(m, wo, weight)` is called at Gauss-Legendre points whose weights sum
// to 1. The integrands (G1 of a reflected or refracted direction, times Fresnel) jump
// where a direction crosses the horizon or refraction turns into total internal
// reflection; `label(m, wo)` names those cases, and for each phi the z where it changes
// are located by bisection so each smooth piece is integrated on its own. Accurate to
// ~1e-4 at 16 panels (1e-7 away from grazing), not the ~1e-3 of a stratified mean. wo
// lies in the xz plane, so the integrand is even in phi and [0, pi] suffices.
// Anisotropic: alpha ax along x and ay along y, wo anywhere; the whole cap is integrated
// unless `half_cap` (wo in the xz plane, ax = ay).
template <class Label, class Accumulate>
void integrate_visible_normals(const glm::dvec3& wo, double ax, double ay, bool half_cap, int panels,
                               const Label& label, const Accumulate& accumulate)
{
    static constexpr double gx[8] = {-0.9602898564975363, -0.7966664774136267, -0.5255324099163290, -0.1834346424956498,
                                     0.1834346424956498,  0.5255324099163290,  0.7966664774136267,  0.9602898564975363};
    static constexpr double gw[8] = {0.1012285362903763, 0.2223810344533745, 0.3137066278921548, 0.3626837833783620,
                                     0.3626837833783620, 0.3137066278921548, 0.2223810344533745, 0.1012285362903763};
    const glm::dvec3 w = glm::normalize(glm::dvec3(wo.x * ax, wo.y * ay, wo.z));
    const double turn = half_cap ? kPi : 2.0 * kPi;
    const double z_lo = -w.z, cap_area = turn * (1.0 - z_lo); // the cap, or half of it: phi in [0, turn]
    const int sign_steps = 32;
    for (int panel = 0; panel < panels; ++panel) {
        double p0 = turn * panel / panels, p1 = turn * (panel + 1) / panels;
        for (int gp = 0; gp < 8; ++gp) {
            double phi = 0.5 * (p0 + p1) + 0.5 * (p1 - p0) * gx[gp], wphi = 0.5 * (p1 - p0) * gw[gp];
            double cp = std::cos(phi), sp = std::sin(phi);
            auto normal = [&](double z) {
                double st = std::sqrt(std::max(0.0, 1.0 - z * z));
                glm::dvec3 h = glm::dvec3(st * cp, st * sp, z) + w;
                return glm::normalize(glm::dvec3(h.x * ax, h.y * ay, std::max(h.z, 0.0)));
            };
            auto piece = [&](double a, double b) {
                for (int half = 0; half < 2; ++half) { // two Gauss panels per piece
                    double a0 = a + (b - a) * half / 2.0, a1 = a + (b - a) * (half + 1) / 2.0;
                    for (int k = 0; k < 8; ++k) {
                        double z = 0.5 * (a0 + a1) + 0.5 * (a1 - a0) * gx[k];
                        accumulate(normal(z), wo, 0.5 * (a1 - a0) * gw[k] * wphi / cap_area);
                    }
                }
            };
            double z_prev = z_lo, start = z_lo;
            int label_prev = label(normal(z_lo), wo);
            for (int k = 1; k <= sign_steps; ++k) {
                double z = z_lo + (1.0 - z_lo) * k / sign_steps;
                int l = label(normal(z), wo);
                if (l != label_prev) {
                    double lo = z_prev, hi = z; // bisect to the change
                    for (int it = 0; it < 60; ++it) {
                        double mid = 0.5 * (lo + hi);
                        (label(normal(mid), wo) == label_prev ? lo : hi) = mid;
                    }
                    double change = 0.5 * (lo + hi);
                    piece(start, change);
                    start = change;
                    label_prev = l;
                }
                z_prev = z;
            }
            piece(start, 1.0);
        }
    }
}

// The isotropic case: wo at cos_theta in the xz plane, half the cap.
template <class Label, class Accumulate>
void integrate_visible_normals(double cos_theta, double alpha, int panels, const Label& label,
                               const Accumulate& accumulate)
{
    const glm::dvec3 wo(std::sqrt(std::max(0.0, 1.0 - cos_theta * cos_theta)), 0.0, cos_theta);
    integrate_visible_normals(wo, alpha, alpha, true, panels, label, accumulate);
}

glm::dvec3 reflect(const glm::dvec3& wo, const glm::dvec3& m)
{
    return 2.0 * glm::dot(wo, m) * m - wo;
}

// Refraction of wo through the facet m (eta = far ior / near ior); false under TIR.
bool refract(const glm::dvec3& wo, const glm::dvec3& m, double eta, glm::dvec3& wt)
{
    double c = glm::dot(wo, m), sin2_t = (1.0 - c * c) / (eta * eta);
    if (sin2_t >= 1.0)
        return false;
    wt = -wo / eta + (c / eta - std::sqrt(1.0 - sin2_t)) * m;
    return true;
}

} // namespace

double integrate_layer_albedo(double cos_theta, double roughness, const std::vector<double>& etas,
                              std::vector<double>& b_out, int panels)
{
    // With visible-normal sampling the reflection lobe's f cos / pdf is G1(wi) times the
    // Fresnel factor, so each albedo is the mean of that over the visible normals.
    const double alpha = std::max(roughness * roughness, 1e-7);
    double e = 0.0;
    b_out.assign(etas.size(), 0.0);
    integrate_visible_normals(
        cos_theta, alpha, panels, [](const glm::dvec3& m, const glm::dvec3& wo) { return reflect(wo, m).z > 0.0; },
        [&](const glm::dvec3& m, const glm::dvec3& wo, double weight) {
            glm::dvec3 wi = reflect(wo, m);
            if (!(wi.z > 0.0))
                return;
            double g = smith_g1(wi, alpha) * weight, c = glm::dot(wo, m);
            e += g;
            for (std::size_t k = 0; k < etas.size(); ++k)
                b_out[k] += g * layer_curve(c, etas[k]);
        });
    return e;
}

double integrate_dielectric_albedo(double cos_theta, double roughness, double eta, int panels)
{
    // Reflection with probability F and refraction with 1 - F at each visible facet;
    // f cos / pdf is then G1 of the outgoing direction (energy: no 1/eta^2 radiance factor).
    const double alpha = std::max(roughness * roughness, 1e-7);
    double e = 0.0;
    auto label = [&](const glm::dvec3& m, const glm::dvec3& wo) {
        glm::dvec3 wt;
        bool refracts = refract(wo, m, eta, wt);
        return (reflect(wo, m).z > 0.0 ? 1 : 0) | (refracts ? 2 : 0) | (refracts && wt.z < 0.0 ? 4 : 0);
    };
    integrate_visible_normals(cos_theta, alpha, panels, label,
                              [&](const glm::dvec3& m, const glm::dvec3& wo, double weight) {
                                  double f = fresnel_dielectric(glm::dot(wo, m), eta);
                                  glm::dvec3 wr = reflect(wo, m), wt;
                                  if (wr.z > 0.0)
                                      e += weight * f * smith_g1(wr, alpha);
                                  if (refract(wo, m, eta, wt) && wt.z < 0.0)
                                      e += weight * (1.0 - f) * smith_g1(wt, alpha);
                              });
    return e;
}

namespace {

// A direction at cos theta whose azimuth from x has cosine cos_phi (y >= 0).
glm::dvec3 direction_at(double cos_theta, double cos_phi)
{
    const double sin_theta = std::sqrt(std::max(0.0, 1.0 - cos_theta * cos_theta));
    return {sin_theta * cos_phi, sin_theta * std::sqrt(std::max(0.0, 1.0 - cos_phi * cos_phi)), cos_theta};
}

} // namespace

double integrate_anisotropic_layer_albedo(double cos_theta, double cos_phi, double along, double roughness,
                                          const std::vector<double>& etas, std::vector<double>& b_out, int panels)
{
    double ax = along * along, ay = ggx_anisotropic_alpha_b(roughness * roughness, ax);
    b_out.assign(etas.size(), 0.0);
    if (ax < ALPHA_DELTA) { // a mirror (the kernels' delta lobe): the Fresnel curves themselves
        for (std::size_t k = 0; k < etas.size(); ++k)
            b_out[k] = layer_curve(cos_theta, etas[k]);
        return 1.0;
    }
    double e = 0.0;
    integrate_visible_normals(
        direction_at(cos_theta, cos_phi), ax, ay, false, panels,
        [](const glm::dvec3& m, const glm::dvec3& w) { return reflect(w, m).z > 0.0; },
        [&](const glm::dvec3& m, const glm::dvec3& w, double weight) {
            glm::dvec3 wi = reflect(w, m);
            if (!(wi.z > 0.0))
                return;
            double g = weight * ggx_g1_aniso(wi, ax, ay), c = glm::dot(w, m);
            e += g;
            for (std::size_t k = 0; k < etas.size(); ++k)
                b_out[k] += g * layer_curve(c, etas[k]);
        });
    return e;
}

double integrate_anisotropic_albedo(double cos_theta, double cos_phi, double along, double roughness, int panels)
{
    std::vector<double> b;
    return integrate_anisotropic_layer_albedo(cos_theta, cos_phi, along, roughness, {}, b, panels);
}

double integrate_anisotropic_dielectric_albedo(double cos_theta, double cos_phi, double along, double roughness,
                                               double eta, int panels)
{
    double ax = along * along, ay = ggx_anisotropic_alpha_b(roughness * roughness, ax);
    if (ax < ALPHA_DELTA)
        return 1.0;
    double e = 0.0;
    auto label = [&](const glm::dvec3& m, const glm::dvec3& wo) {
        glm::dvec3 wt;
        bool refracts = refract(wo, m, eta, wt);
        return (reflect(wo, m).z > 0.0 ? 1 : 0) | (refracts ? 2 : 0) | (refracts && wt.z < 0.0 ? 4 : 0);
    };
    integrate_visible_normals(direction_at(cos_theta, cos_phi), ax, ay, false, panels, label,
                              [&](const glm::dvec3& m, const glm::dvec3& wo, double weight) {
                                  double f = fresnel_dielectric(glm::dot(wo, m), eta);
                                  glm::dvec3 wr = reflect(wo, m), wt;
                                  if (wr.z > 0.0)
                                      e += weight * f * ggx_g1_aniso(wr, ax, ay);
                                  if (refract(wo, m, eta, wt) && wt.z < 0.0)
                                      e += weight * (1.0 - f) * ggx_g1_aniso(wt, ax, ay);
                              });
    return e;
}

LayerAlbedo integrate_layer_albedo(double cos_theta, double roughness, double eta, int panels)
{
    std::vector<double> b;
    double e = integrate_layer_albedo(cos_theta, roughness, std::vector<double>{eta}, b, panels);
    return {e, b[0]};
}

double integrate_sheen_albedo(double cos_theta, double roughness, int panels)
{
    // Gauss-Legendre over wi in (v, phi) with cos theta_i = v^2 (the lobe and its masking
    // change fastest at grazing angles), phi in [0, pi] doubled (wo lies in the xz plane).
    static constexpr double gx[8] = {-0.9602898564975363, -0.7966664774136267, -0.5255324099163290, -0.1834346424956498,
                                     0.1834346424956498,  0.5255324099163290,  0.7966664774136267,  0.9602898564975363};
    static constexpr double gw[8] = {0.1012285362903763, 0.2223810344533745, 0.3137066278921548, 0.3626837833783620,
                                     0.3626837833783620, 0.3137066278921548, 0.2223810344533745, 0.1012285362903763};
    const double alpha = std::max(roughness * roughness, static_cast<double>(SHEEN_ALPHA_MIN));
    const glm::dvec3 wo(std::sqrt(std::max(0.0, 1.0 - cos_theta * cos_theta)), 0.0, cos_theta);
    const int n = 8 * panels;
    std::vector<double> v(n), wv(n), phi(n), wphi(n);
    for (int p = 0; p < panels; ++p)
        for (int k = 0; k < 8; ++k) {
            double a = static_cast<double>(p) / panels, b = static_cast<double>(p + 1) / panels;
            v[8 * p + k] = 0.5 * (a + b) + 0.5 * (b - a) * gx[k];
            wv[8 * p + k] = 0.5 * (b - a) * gw[k];
            phi[8 * p + k] = kPi * v[8 * p + k];
            wphi[8 * p + k] = kPi * wv[8 * p + k];
        }
    double sum = 0.0;
    for (int a = 0; a < n; ++a) {
        double u = v[a] * v[a], s = std::sqrt(std::max(0.0, 1.0 - u * u)), row = 0.0;
        for (int b = 0; b < n; ++b) {
            glm::dvec3 wi(s * std::cos(phi[b]), s * std::sin(phi[b]), u);
            row += wphi[b] * sheen_f_cos(wo, wi, alpha);
        }
        sum += row * wv[a] * 2.0 * v[a]; // d omega = du dphi, du = 2 v dv
    }
    return 2.0 * sum;
}

double smooth_layer_average(double eta)
{
    // Gauss-Legendre on panels in t = sqrt(mu) (the curve is steep at grazing and has a
    // kink at the critical angle only for eta < 1, which materials never use here).
    static constexpr double x[5] = {-0.9061798459386640, -0.5384693101056831, 0.0, 0.5384693101056831,
                                    0.9061798459386640};
    static constexpr double w[5] = {0.2369268850561891, 0.4786286704993665, 0.5688888888888889, 0.4786286704993665,
                                    0.2369268850561891};
    const int panels = 256;
    double sum = 0.0;
    for (int k = 0; k < panels; ++k) {
        double a = static_cast<double>(k) / panels, b = static_cast<double>(k + 1) / panels;
        for (int i = 0; i < 5; ++i) {
            double t = 0.5 * (a + b) + 0.5 * (b - a) * x[i];
            sum += 0.5 * (b - a) * w[i] * 4.0 * t * t * t * layer_curve(t * t, eta);
        }
    }
    return sum;
}

} // namespace pathcl
