#include "sampling/sample_plot.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include "common/error.h"
#include "sampling/samplers.h"
#include "types.h"

namespace pathcl {
namespace {

constexpr int kPanel = 512; // each panel is kPanel x kPanel pixels
constexpr int kMargin = 24; // around and between panels
constexpr int kTop = 48;    // room for two title lines
constexpr int kBottom = 40; // room for one legend line

float srgb_to_linear(float t)
{
    return t <= 0.04045f ? t / 12.92f : std::pow((t + 0.055f) / 1.055f, 2.4f);
}

// Colours are given as displayed (sRGB) and stored linear: write_image encodes to sRGB.
glm::vec3 display(float r, float g, float b)
{
    return {srgb_to_linear(r), srgb_to_linear(g), srgb_to_linear(b)};
}

struct Canvas {
    int w, h;
    std::vector<float> rgb;

    Canvas(int width, int height) : w(width), h(height), rgb(static_cast<std::size_t>(width) * height * 3, 1.0f) {}

    void blend(int x, int y, glm::vec3 c, float alpha)
    {
        if (x < 0 || y < 0 || x >= w || y >= h || alpha <= 0.0f)
            return;
        float* p = &rgb[(static_cast<std::size_t>(y) * w + x) * 3];
        for (int i = 0; i < 3; ++i)
            p[i] = p[i] * (1.0f - alpha) + c[i] * alpha;
    }
    void hline(int x0, int x1, int y, glm::vec3 c)
    {
        for (int x = x0; x <= x1; ++x)
            blend(x, y, c, 1.0f);
    }
    void vline(int x, int y0, int y1, glm::vec3 c)
    {
        for (int y = y0; y <= y1; ++y)
            blend(x, y, c, 1.0f);
    }
    void frame(int x0, int y0, int size, glm::vec3 c)
    {
        hline(x0 - 1, x0 + size, y0 - 1, c);
        hline(x0 - 1, x0 + size, y0 + size, c);
        vline(x0 - 1, y0 - 1, y0 + size, c);
        vline(x0 + size, y0 - 1, y0 + size, c);
    }
    // An antialiased filled disk centred at (cx, cy) (pixel centres at integer + 0.5).
    void disk(float cx, float cy, float r, glm::vec3 c)
    {
        for (int y = static_cast<int>(std::floor(cy - r - 1)); y <= static_cast<int>(std::ceil(cy + r + 1)); ++y)
            for (int x = static_cast<int>(std::floor(cx - r - 1)); x <= static_cast<int>(std::ceil(cx + r + 1)); ++x) {
                float d = std::hypot(static_cast<float>(x) + 0.5f - cx, static_cast<float>(y) + 0.5f - cy);
                blend(x, y, c, std::clamp(r + 0.5f - d, 0.0f, 1.0f));
            }
    }
};

// Text through OpenImageIO (FreeType, DejaVu Sans from fonts-dejavu-core). Labels are a
// convenience: without the font the plot is drawn without them.
void draw_text(Canvas& canvas, const std::vector<std::pair<glm::ivec2, std::string>>& labels)
{
    OIIO::ImageBuf buf(OIIO::ImageSpec(canvas.w, canvas.h, 3, OIIO::TypeDesc::FLOAT));
    buf.set_pixels(OIIO::ROI::All(), OIIO::TypeDesc::FLOAT, canvas.rgb.data());
    const float black[3] = {0.0f, 0.0f, 0.0f};
    for (const auto& [at, text] : labels)
        if (!OIIO::ImageBufAlgo::render_text(buf, at.x, at.y, text, 15, "DejaVuSans", black))
            return;
    buf.get_pixels(OIIO::ROI::All(), OIIO::TypeDesc::FLOAT, canvas.rgb.data());
}

// The strata drawn under the points: vertical and horizontal lines at multiples of
// 1 / cols and 1 / rows. Sobol and Hammersley at spp = 2^m are (0,m,2)-nets: their
// squarest elementary intervals (2^ceil(m/2) x 2^floor(m/2)) are drawn.
struct GridLines {
    std::uint32_t cols = 0, rows = 0;
    glm::vec3 colour{0.0f};
};

std::vector<GridLines> strata_lines(SamplerType sampler, std::uint32_t spp, bool two_d)
{
    const glm::vec3 light = display(0.82f, 0.82f, 0.82f), medium = display(0.55f, 0.55f, 0.55f);
    std::vector<GridLines> g;
    auto fits = [](std::uint32_t n) { return n > 0 && n <= kPanel / 3; }; // at least 3 pixels apart
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

    const int width = kMargin + kPanel + kMargin + (rq.spectrum ? kPanel + kMargin : 0);
    const int height = kTop + kPanel + kBottom;
    Canvas canvas(width, height);
    const int x0 = kMargin, y0 = kTop;
    const glm::vec3 black = display(0.0f, 0.0f, 0.0f);

    // Points: first dimension to the right, second upwards.
    for (const GridLines& g : strata_lines(rq.sampler, rq.spp, two_d)) {
        for (std::uint32_t i = 1; i < g.cols; ++i)
            canvas.vline(x0 + static_cast<int>(std::lround(static_cast<double>(i) * kPanel / g.cols)), y0,
                         y0 + kPanel - 1, g.colour);
        for (std::uint32_t i = 1; i < g.rows; ++i)
            canvas.hline(x0, x0 + kPanel - 1,
                         y0 + kPanel - static_cast<int>(std::lround(static_cast<double>(i) * kPanel / g.rows)),
                         g.colour);
    }
    canvas.frame(x0, y0, kPanel, black);
    const float radius = std::clamp(0.25f * kPanel / std::sqrt(static_cast<float>(points.size())), 1.2f, 5.0f);
    const glm::vec3 dot = display(0.05f, 0.2f, 0.65f);
    for (const glm::vec2& p : points)
        canvas.disk(static_cast<float>(x0) + p.x * kPanel, static_cast<float>(y0) + (1.0f - p.y) * kPanel, radius, dot);

    std::vector<std::pair<glm::ivec2, std::string>> labels;
    std::string dims = two_d ? "2D decision at dims " + std::to_string(rq.dim0) + "," + std::to_string(rq.dim1)
                             : "1D decisions at dims " + std::to_string(rq.dim0) + " and " + std::to_string(rq.dim1);
    labels.push_back({{x0, 20},
                      sampler_name(rq.sampler) + ", " + std::to_string(rq.spp) + " spp, pixel " + rq.pixel_label +
                          ", seed " + std::to_string(rq.seed)});
    labels.push_back({{x0, 40}, dims});
    labels.push_back(
        {{x0, y0 + kPanel + 26},
         two_d || rq.sampler == SamplerType::Halton || rq.sampler == SamplerType::Independent
             ? "x: dim " + std::to_string(rq.dim0) + " (right), y: dim " + std::to_string(rq.dim1) + " (up)"
             : "x: dim " + std::to_string(rq.dim0) + ", y: dim " + std::to_string(rq.dim1) + " (own 1D sets)"});

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
        const int sx0 = x0 + kPanel + kMargin;
        const int W = 2 * F + 1;
        for (int y = 0; y < kPanel; ++y)
            for (int x = 0; x < kPanel; ++x) {
                int fx = x * W / kPanel - F;
                int fy = F - y * W / kPanel;
                // Display grey: 0 = no power, 0.5 = white noise (1), white = 2 or more.
                float t = static_cast<float>(std::clamp(ps.at(fx, fy) / 2.0, 0.0, 1.0));
                canvas.blend(sx0 + x, y0 + y, display(t, t, t), 1.0f);
            }
        // The circle |f| = sqrt(spp): blue-noise sets have little power inside it.
        const float cell = static_cast<float>(kPanel) / static_cast<float>(W);
        const float cx = static_cast<float>(sx0) + (static_cast<float>(F) + 0.5f) * cell;
        const float cy = static_cast<float>(y0) + (static_cast<float>(F) + 0.5f) * cell;
        const float r = std::sqrt(static_cast<float>(rq.spp)) * cell;
        const glm::vec3 red = display(0.9f, 0.1f, 0.1f);
        for (int i = 0; i < 2000; ++i) {
            float a = 2.0f * std::numbers::pi_v<float> * static_cast<float>(i) / 2000.0f;
            canvas.blend(static_cast<int>(cx + r * std::cos(a)), static_cast<int>(cy + r * std::sin(a)), red, 1.0f);
        }
        canvas.frame(sx0, y0, kPanel, black);
        labels.push_back({{sx0, 20}, "power spectrum, mean of " + std::to_string(ps.sets) + " pixels' sets"});
        labels.push_back(
            {{sx0, 40},
             "frequencies -" + std::to_string(F) + ".." + std::to_string(F) + ", red circle |f| = sqrt(spp)"});
        labels.push_back({{sx0, y0 + kPanel + 26}, "grey: black 0, mid-grey 1 (white noise), white >= 2"});
        if (note)
            *note = "spectrum: mean periodogram of " + std::to_string(ps.sets) +
                    " pixels, |fx|, |fy| <= " + std::to_string(F);
    }
    draw_text(canvas, labels);

    Image img;
    img.width = static_cast<std::uint32_t>(width);
    img.height = static_cast<std::uint32_t>(height);
    img.spp = rq.spp;
    img.rgb = std::move(canvas.rgb);
    img.variance.assign(img.rgb.size(), 0.0f);
    return img;
}

} // namespace pathcl
