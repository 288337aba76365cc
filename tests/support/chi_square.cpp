#include "support/chi_square.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <numeric>
#include <stdexcept>

#include <glm/geometric.hpp>

namespace pathcl::test {
namespace {

constexpr double pi = std::numbers::pi;

// Cells with fewer expected samples are pooled: Pearson's statistic is only close to
// chi-square distributed when every expected count is at least about 5.
constexpr double min_expected = 5.0;
// How close to a cell edge a sample in a zero-pdf cell may lie and still be moved across.
constexpr double edge_tolerance = 1e-5;
constexpr int max_depth = 10;

struct Grid {
    int theta_res, phi_res;
    double dtheta() const { return pi / theta_res; }
    double dphi() const { return 2.0 * pi / phi_res; }
    int cells() const { return theta_res * phi_res; }
};

// 5-point Gauss-Legendre on [a, b]. An open rule: a pdf whose support ends exactly on a
// cell edge (the horizon, with theta_res even) is never evaluated there, so the cell
// beyond gets exactly 0 rather than a sliver of quadrature error.
template <class F>
double gauss5(const F& f, double a, double b)
{
    static constexpr double x[5] = {-0.9061798459386640, -0.5384693101056831, 0.0, 0.5384693101056831,
                                    0.9061798459386640};
    static constexpr double w[5] = {0.2369268850561891, 0.4786286704993665, 0.5688888888888889, 0.4786286704993665,
                                    0.2369268850561891};
    double c = 0.5 * (a + b), h = 0.5 * (b - a), s = 0.0;
    for (int i = 0; i < 5; ++i)
        s += w[i] * f(c + h * x[i]);
    return s * h;
}

// Bisects where the halves disagree with the whole: smooth pdfs stop at once, pdfs with a
// step (a light's silhouette) refine along the step only.
template <class F>
double adaptive(const F& f, double a, double b, double whole, double tol, int depth)
{
    double m = 0.5 * (a + b), left = gauss5(f, a, m), right = gauss5(f, m, b);
    if (depth == 0 || std::abs(left + right - whole) <= tol)
        return left + right;
    return adaptive(f, a, m, left, 0.5 * tol, depth - 1) + adaptive(f, m, b, right, 0.5 * tol, depth - 1);
}

// Starts from a few panels so that a lobe narrower than the cell is less likely to fall
// between the first nodes and be missed.
constexpr int first_panels = 4;
// A cell whose first integral is 0 but that a sample fell in is integrated again from this
// many panels: a sliver of a light's silhouette across its corner can fall between the
// first nodes.
constexpr int sliver_panels = 64;

template <class F>
double integrate(const F& f, double a, double b, double tol, int panels)
{
    double s = 0.0;
    for (int k = 0; k < panels; ++k) {
        double pa = a + (b - a) * k / panels, pb = k + 1 == panels ? b : a + (b - a) * (k + 1) / panels;
        s += adaptive(f, pa, pb, gauss5(f, pa, pb), tol / panels, max_depth);
    }
    return s;
}

// Integral of the pdf over one cell, in (cos theta, phi) where d(solid angle) = du dphi.
// tol bounds the error of the result; each inner phi integral gets a tenth of the
// matching share so its error does not drive the outer refinement.
double integrate_cell(const std::function<double(const glm::dvec3&)>& pdf, const Grid& g, int t, int p, double tol,
                      int panels = first_panels)
{
    double u0 = std::cos((t + 1) * g.dtheta()), u1 = std::cos(t * g.dtheta());
    double phi0 = p * g.dphi(), phi1 = (p + 1) * g.dphi();
    double inner_tol = 0.1 * tol / (u1 - u0);
    auto over_phi = [&](double u) {
        double s = std::sqrt(std::max(0.0, 1.0 - u * u));
        auto f = [&](double phi) { return pdf(glm::dvec3(s * std::cos(phi), s * std::sin(phi), u)); };
        return integrate(f, phi0, phi1, inner_tol, panels);
    };
    return integrate(over_phi, u0, u1, tol, panels);
}

std::string cell_name(const Grid& g, int cell)
{
    int t = cell / g.phi_res, p = cell % g.phi_res;
    double deg = 180.0 / pi;
    char buf[96];
    std::snprintf(buf, sizeof buf, "theta [%.1f, %.1f] deg, phi [%.1f, %.1f] deg", t * g.dtheta() * deg,
                  (t + 1) * g.dtheta() * deg, p * g.dphi() * deg, (p + 1) * g.dphi() * deg);
    return buf;
}

// The cells with the largest (obs - exp)^2 / exp, one per line.
std::string worst_cells(const Grid& g, const std::vector<double>& observed, const std::vector<double>& expected)
{
    std::vector<int> order(observed.size());
    std::iota(order.begin(), order.end(), 0);
    auto term = [&](int i) {
        double d = observed[i] - expected[i];
        return expected[i] > 0.0 ? d * d / expected[i] : 0.0;
    };
    std::sort(order.begin(), order.end(), [&](int a, int b) { return term(a) > term(b); });
    std::string out = "  cells that disagree most (observed vs expected):";
    for (std::size_t k = 0; k < std::min<std::size_t>(5, order.size()); ++k) {
        int i = order[k];
        char buf[256];
        std::snprintf(buf, sizeof buf, "\n    %s: %.0f vs %.1f, (o-e)^2/e = %.2f", cell_name(g, i).c_str(), observed[i],
                      expected[i], term(i));
        out += buf;
    }
    return out;
}

} // namespace

std::string ChiSquareResult::summary() const
{
    char buf[512];
    std::snprintf(buf, sizeof buf,
                  "chi-square %s: p = %.4g (needs >= %.4g), X^2 = %.2f, dof = %d, pdf integral = %.6f, "
                  "samples used %zu, discarded %zu, moved off zero-pdf cells %zu",
                  passed ? "passed" : "FAILED", p_value, threshold, statistic, degrees_of_freedom, pdf_integral,
                  samples_used, samples_discarded, samples_moved);
    std::string s = buf;
    if (!diagnosis.empty())
        s += "\n" + diagnosis;
    return s;
}

ChiSquareResult chi_square_directions(const std::vector<glm::dvec3>& sample_directions,
                                      const std::function<double(const glm::dvec3&)>& pdf, int theta_res, int phi_res,
                                      double alpha, int test_count)
{
    if (theta_res < 1 || phi_res < 1 || !(alpha > 0.0 && alpha < 1.0) || test_count < 1)
        throw std::invalid_argument("chi_square_directions: bad resolution, alpha or test_count");
    const Grid g{theta_res, phi_res};
    const double n = static_cast<double>(sample_directions.size());

    ChiSquareResult r;
    r.threshold = 1.0 - std::pow(1.0 - alpha, 1.0 / test_count);
    if (sample_directions.empty()) {
        r.diagnosis = "no samples";
        return r;
    }

    // Expected counts, to within half a sample per cell: that adds about 0.25 / E to the
    // cell's (o - e)^2 / e, far below its noise, while a tighter tolerance makes
    // discontinuous pdfs (cone and triangle edges) take minutes to integrate.
    std::vector<double> expected(g.cells());
    for (int c = 0; c < g.cells(); ++c) {
        double integral = integrate_cell(pdf, g, c / phi_res, c % phi_res, 0.5 / n);
        if (!std::isfinite(integral) || integral < 0.0) {
            r.diagnosis = "pdf is negative or not finite in " + cell_name(g, c);
            return r;
        }
        r.pdf_integral += integral;
        expected[c] = integral * n;
    }

    std::vector<double> observed(g.cells(), 0.0);
    for (const glm::dvec3& d : sample_directions) {
        double len = glm::length(d);
        if (!std::isfinite(len) || std::abs(len - 1.0) > 1e-3) {
            ++r.samples_discarded;
            continue;
        }
        ++r.samples_used;
        // atan2 rather than acos: accurate near the poles.
        double theta = std::atan2(std::sqrt(d.x * d.x + d.y * d.y), d.z), phi = std::atan2(d.y, d.x);
        if (phi < 0.0)
            phi += 2.0 * pi;
        int t = std::min(static_cast<int>(theta / g.dtheta()), theta_res - 1);
        int p = std::min(static_cast<int>(phi / g.dphi()), phi_res - 1);
        int cell = t * phi_res + p;
        if (expected[cell] == 0.0) {
            int candidates[4] = {-1, -1, -1, -1};
            if (t > 0 && theta - t * g.dtheta() < edge_tolerance)
                candidates[0] = cell - phi_res;
            if (t + 1 < theta_res && (t + 1) * g.dtheta() - theta < edge_tolerance)
                candidates[1] = cell + phi_res;
            if (phi - p * g.dphi() < edge_tolerance)
                candidates[2] = t * phi_res + (p + phi_res - 1) % phi_res;
            if ((p + 1) * g.dphi() - phi < edge_tolerance)
                candidates[3] = t * phi_res + (p + 1) % phi_res;
            for (int c : candidates)
                if (c >= 0 && expected[c] > 0.0) {
                    cell = c;
                    ++r.samples_moved;
                    break;
                }
        }
        observed[cell] += 1.0;
    }

    for (int c = 0; c < g.cells(); ++c)
        if (expected[c] == 0.0 && observed[c] > 0.0) {
            const double integral = integrate_cell(pdf, g, c / phi_res, c % phi_res, 0.5 / n, sliver_panels);
            if (std::isfinite(integral) && integral > 0.0) {
                r.pdf_integral += integral;
                expected[c] = integral * n;
            }
        }

    // Samples where the pdf is zero: no statistics needed.
    int empty_hit = -1;
    double empty_total = 0.0;
    for (int c = 0; c < g.cells(); ++c)
        if (expected[c] == 0.0 && observed[c] > 0.0) {
            empty_total += observed[c];
            if (empty_hit < 0 || observed[c] > observed[empty_hit])
                empty_hit = c;
        }
    if (empty_hit >= 0) {
        char buf[128];
        std::snprintf(buf, sizeof buf, "%.0f samples fell where the pdf integrates to 0, %.0f of them in ", empty_total,
                      observed[empty_hit]);
        r.diagnosis = buf + cell_name(g, empty_hit);
        return r;
    }

    // Pool the cells with low expected counts, smallest first, until the pool reaches the
    // minimum (pbrt's scheme); every other cell is a term of its own.
    std::vector<int> order(g.cells());
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](int a, int b) { return expected[a] < expected[b]; });
    double pool_obs = 0.0, pool_exp = 0.0;
    int terms = 0;
    for (int c : order) {
        if (expected[c] == 0.0)
            continue;
        if (expected[c] < min_expected || (pool_exp > 0.0 && pool_exp < min_expected)) {
            pool_obs += observed[c];
            pool_exp += expected[c];
        } else {
            double diff = observed[c] - expected[c];
            r.statistic += diff * diff / expected[c];
            ++terms;
        }
    }
    if (pool_exp > 0.0) {
        double diff = pool_obs - pool_exp;
        r.statistic += diff * diff / pool_exp;
        ++terms;
    }
    r.degrees_of_freedom = terms - 1;
    if (r.degrees_of_freedom < 1) {
        r.diagnosis = "too few cells with samples expected: raise the sample count or the resolution";
        return r;
    }
    r.p_value = chi_square_survival(r.statistic, r.degrees_of_freedom);
    r.passed = r.p_value >= r.threshold; // false for a NaN p-value too
    if (!r.passed)
        r.diagnosis = worst_cells(g, observed, expected);
    return r;
}

double regularized_gamma_q(double a, double x)
{
    if (!(a > 0.0) || !(x >= 0.0))
        return std::numeric_limits<double>::quiet_NaN();
    if (x == 0.0)
        return 1.0;
    constexpr double eps = 1e-15, tiny = 1e-300;
    constexpr int max_iterations = 100000;
    // x^a e^-x / Gamma(a), in logs so that large a and x do not overflow.
    double prefix = std::exp(a * std::log(x) - x - std::lgamma(a));
    if (x < a + 1.0) {
        // Series for P(a, x), which converges fast here; Q = 1 - P.
        double term = 1.0 / a, sum = term;
        for (int k = 1; k < max_iterations && std::abs(term) > std::abs(sum) * eps; ++k) {
            term *= x / (a + k);
            sum += term;
        }
        return std::max(0.0, 1.0 - prefix * sum);
    }
    // Continued fraction for Q(a, x) by the modified Lentz method.
    double b = x + 1.0 - a, c = 1.0 / tiny, d = 1.0 / b, h = d;
    for (int k = 1; k < max_iterations; ++k) {
        double an = -k * (k - a);
        b += 2.0;
        d = an * d + b;
        d = std::abs(d) < tiny ? tiny : d;
        c = b + an / c;
        c = std::abs(c) < tiny ? tiny : c;
        d = 1.0 / d;
        double delta = d * c;
        h *= delta;
        if (std::abs(delta - 1.0) < eps)
            break;
    }
    return prefix * h;
}

double chi_square_survival(double x, int k)
{
    return regularized_gamma_q(0.5 * k, 0.5 * x);
}

} // namespace pathcl::test
