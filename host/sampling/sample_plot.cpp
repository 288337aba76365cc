#include "sampling/sample_plot.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "common/error.h"
#include "plot/plot.h"
#include "sampling/samplers.h"
#include "types.h"

namespace pathcl {
namespace {

// Each panel is kPanelWidth x kPanelHeight pixels.
constexpr int kPanelWidth = 560, kPanelHeight = 540;

// The strata drawn under the points: vertical and horizontal lines at multiples of
// 1 / cols and 1 / rows. Sobol and Hammersley at spp = 2^m are (0,m,2)-nets: their
// squarest elementary intervals (2^ceil(m/2) x 2^floor(m/2)) are drawn.
std::vector<PlotGrid> strata_lines(SamplerType sampler, std::uint32_t spp, bool two_d)
{
    const double light = 0.82, medium = 0.55;
    std::vector<PlotGrid> g;
    auto fits = [](std::uint32_t n) { return n > 0 && n <= kPanelWidth / 4; }; // lines a few pixels apart
    const bool pow2 = spp > 0 && (spp & (spp - 1)) == 0;
    if (!two_d) { // two 1D decisions, each its own 1D set: stratified into spp intervals
        if ((sampler == SamplerType::Jittered || sampler == SamplerType::MultiJittered ||
             sampler == SamplerType::NRooks || sampler == SamplerType::Hammersley ||
             (sampler == SamplerType::Sobol && pow2)) &&
            fits(spp))
            g.push_back({spp, spp, light});
        return g;
    }
    StrataGrid s = sampler_strata(sampler, spp);
    if (s.fine && fits(s.fine))
        g.push_back({s.fine, s.fine, light});
    if (s.cols && fits(s.cols) && fits(s.rows))
        g.push_back({s.cols, s.rows, sampler == SamplerType::NRooks ? light : medium});
    if ((sampler == SamplerType::Sobol || sampler == SamplerType::Hammersley) && pow2) {
        int m = 0;
        while ((1u << m) < spp)
            ++m;
        std::uint32_t cols = 1u << ((m + 1) / 2), rows = 1u << (m / 2);
        if (fits(cols))
            g.push_back({cols, rows, medium});
    }
    return g;
}

} // namespace

PowerSpectrum power_spectrum(const std::vector<glm::vec2>& points, std::size_t set_size, int max_frequency)
{
    PowerSpectrum ps;
    const int F = max_frequency, W = 2 * F + 1;
    ps.max_frequency = F;
    ps.power.assign(static_cast<std::size_t>(W) * W, 0.0);
    if (set_size == 0)
        return ps;
    ps.sets = points.size() / set_size;
    const std::size_t n = set_size;
    const double two_pi = 2.0 * std::numbers::pi;
    // exp(-2 pi i fx x_k) for every point and fx; rows of W.
    std::vector<double> exr(n * W), exi(n * W), sr(W), si(W);
    for (std::size_t s = 0; s < ps.sets; ++s) {
        const glm::vec2* p = &points[s * n];
        for (std::size_t k = 0; k < n; ++k)
            for (int fx = -F; fx <= F; ++fx) {
                double a = two_pi * fx * static_cast<double>(p[k].x);
                exr[k * W + (fx + F)] = std::cos(a);
                exi[k * W + (fx + F)] = -std::sin(a);
            }
        // P(-f) = P(f) for real points: compute fy >= 0 and mirror.
        for (int fy = 0; fy <= F; ++fy) {
            std::fill(sr.begin(), sr.end(), 0.0);
            std::fill(si.begin(), si.end(), 0.0);
            for (std::size_t k = 0; k < n; ++k) {
                double b = two_pi * fy * static_cast<double>(p[k].y);
                double cy = std::cos(b), sy = -std::sin(b);
                const double* xr = &exr[k * W];
                const double* xi = &exi[k * W];
                for (int j = 0; j < W; ++j) {
                    sr[j] += xr[j] * cy - xi[j] * sy;
                    si[j] += xr[j] * sy + xi[j] * cy;
                }
            }
            for (int j = 0; j < W; ++j) {
                double pw = (sr[j] * sr[j] + si[j] * si[j]) / static_cast<double>(n);
                int fx = j - F;
                ps.power[static_cast<std::size_t>((fy + F) * W + j)] += pw;
                if (fy > 0)
                    ps.power[static_cast<std::size_t>((-fy + F) * W + (-fx + F))] += pw;
            }
        }
    }
    for (double& v : ps.power)
        v /= static_cast<double>(std::max<std::size_t>(ps.sets, 1));
    return ps;
}

Image draw_sample_plot(const ClDevice& dev, const cl::Program& program, const SamplePlotRequest& rq, std::string* note)
{
    if (rq.spectrum && rq.spp > kSpectrumMaxSpp)
        throw ParameterError("spectrum", "needs {spp} at most " + std::to_string(kSpectrumMaxSpp));
    const bool two_d = rq.dim1 == rq.dim0 + 1;
    SamplerPointsRequest pr;
    pr.sampler = rq.sampler;
    pr.spp = rq.spp;
    pr.seed = rq.seed;
    pr.dim0 = rq.dim0;
    pr.dim1 = rq.dim1;
    pr.pixels = {rq.pixel};
    std::vector<glm::vec2> points = compute_sampler_points(dev, program, pr);

    Plot plot(rq.spectrum ? 2 * kPanelWidth : kPanelWidth, kPanelHeight, rq.spectrum ? 2 : 1);
    PlotAxes axes;
    axes.title = sampler_name(rq.sampler) + ", " + std::to_string(rq.spp) + " spp, pixel " + rq.pixel_label +
                 ", seed " + std::to_string(rq.seed);
    const bool own_sets = !two_d && rq.sampler != SamplerType::Halton && rq.sampler != SamplerType::Independent;
    axes.x_label = "dim " + std::to_string(rq.dim0) +
                   (two_d ? " (2D decision at dims " + std::to_string(rq.dim0) + "," + std::to_string(rq.dim1) + ")"
                          : (own_sets ? " (own 1D set)" : " (1D decision)"));
    axes.y_label = "dim " + std::to_string(rq.dim1) + (own_sets ? " (own 1D set)" : "");
    plot.points(axes, points, strata_lines(rq.sampler, rq.spp, two_d));

    if (rq.spectrum) {
        // Frequencies up to about twice the blue-noise radius sqrt(spp); as many pixels as
        // a budget of ~3e8 complex multiply-adds allows (16 to 256).
        const int F = std::clamp(2 * static_cast<int>(std::ceil(std::sqrt(static_cast<double>(rq.spp)))), 16, 64);
        const double per_set = static_cast<double>(rq.spp) * (2 * F + 1) * (F + 1);
        const auto sets = static_cast<std::uint32_t>(std::clamp(3e8 / per_set, 16.0, 256.0));
        SamplerPointsRequest sr = pr;
        sr.pixels.clear();
        for (std::uint32_t k = 0; k < sets; ++k)
            sr.pixels.push_back(rq.pixel + k);
        PowerSpectrum ps = power_spectrum(compute_sampler_points(dev, program, sr), rq.spp, F);
        PlotAxes sa;
        sa.title = "power spectrum, mean of " + std::to_string(ps.sets) + " pixels' sets";
        sa.x_label = "frequency fx; red circle: |f| = sqrt(spp)";
        sa.y_label = "fy; grey: black 0, mid 1 (white noise), white 2+";
        // Blue-noise sets have little power inside the circle.
        plot.grey_map(sa, ps.power, 2 * F + 1, 2 * F + 1, -F - 0.5, F + 0.5, -F - 0.5, F + 0.5, 2.0,
                      std::sqrt(static_cast<double>(rq.spp)));
        if (note)
            *note = "spectrum: mean periodogram of " + std::to_string(ps.sets) +
                    " pixels, |fx|, |fy| <= " + std::to_string(F);
    }
    Image img = plot.finish();
    img.spp = rq.spp;
    return img;
}

} // namespace pathcl
