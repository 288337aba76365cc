#include "plot/plot.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include <plstream.h>

#include "common/error.h"

namespace pathcl {
namespace {

// cmap0: 0 the background, 1 text and axes, 2 .. 11 the series (Tableau 10), 12 a scratch
// entry set before each use (bands with alpha, grid greys, the spectrum's circle).
constexpr int kText = 1, kFirstSeries = 2, kSeriesColours = 10, kScratch = 12;
const PLINT kPaletteR[13] = {255, 0, 31, 255, 44, 214, 148, 140, 227, 127, 188, 23, 0};
const PLINT kPaletteG[13] = {255, 0, 119, 127, 160, 39, 103, 86, 119, 127, 189, 190, 0};
const PLINT kPaletteB[13] = {255, 0, 180, 14, 44, 40, 189, 75, 194, 127, 34, 207, 0};

bool has_memcairo()
{
    // plgDevs fills arrays the caller allocates; count is their size on entry.
    std::vector<const char*> menu_storage(256), name_storage(256);
    const char** menus = menu_storage.data();
    const char** names = name_storage.data();
    int count = static_cast<int>(name_storage.size());
    plgDevs(&menus, &names, &count);
    bool found = false;
    for (int i = 0; i < count; ++i)
        found = found || std::strcmp(names[i], "memcairo") == 0;
    return found;
}

float srgb_to_linear(float t)
{
    return t <= 0.04045f ? t / 12.92f : std::pow((t + 0.055f) / 1.055f, 2.4f);
}

// Data to plot coordinates: log axes take log10; NaN for what a log axis cannot show.
double to_axis(double v, bool log)
{
    if (!log)
        return v;
    return v > 0.0 ? std::log10(v) : std::numeric_limits<double>::quiet_NaN();
}

// The range of finite values, widened by 4% (or to a unit range when flat).
std::pair<double, double> padded_range(const std::vector<double>& values)
{
    double lo = INFINITY, hi = -INFINITY;
    for (double v : values)
        if (std::isfinite(v)) {
            lo = std::min(lo, v);
            hi = std::max(hi, v);
        }
    if (!std::isfinite(lo))
        return {0.0, 1.0};
    if (hi - lo < 1e-12)
        return {lo - 0.5, hi + 0.5};
    double pad = 0.04 * (hi - lo);
    return {lo - pad, hi + pad};
}

} // namespace

struct Plot::Impl {
    int width, height;
    std::vector<unsigned char> rgba;
    plstream pls;

    Impl(int w, int h) : width(w), height(h), rgba(static_cast<std::size_t>(w) * h * 4, 255) {}

    // The palette entry and dash style of series i: its own, else solid in ten colours,
    // then dashed styles past ten series.
    static int colour_of(const PlotSeries& s, std::size_t i)
    {
        return kFirstSeries + (s.colour >= 0 ? s.colour : static_cast<int>(i)) % kSeriesColours;
    }
    static int style_of(const PlotSeries& s, std::size_t i)
    {
        return 1 + (s.style >= 0 ? s.style : static_cast<int>(i) / kSeriesColours) % 8;
    }
    void scratch(double r, double g, double b, double alpha)
    {
        pls.scol0a(kScratch, static_cast<PLINT>(r * 255.0), static_cast<PLINT>(g * 255.0),
                   static_cast<PLINT>(b * 255.0), alpha);
        pls.col0(kScratch);
    }
    // A panel with axes `a` over the plot-coordinate window; legend_room: the fraction of
    // the page's width kept free on the right.
    void panel(const PlotAxes& a, double x0, double x1, double y0, double y1, bool square, double legend_room = 0.0)
    {
        pls.adv(0);
        if (legend_room > 0.0)
            pls.vpor(0.08, 0.98 - legend_room, 0.1, 0.92);
        else
            pls.vsta();
        if (square)
            pls.vasp(1.0);
        pls.wind(x0, x1, y0, y1);
        pls.lsty(1);
        pls.width(1.0);
        scratch(0.88, 0.88, 0.88, 1.0);
        if (!square)
            pls.box(a.log_x ? "gl" : "g", 0.0, 0, a.log_y ? "gl" : "g", 0.0, 0);
        pls.col0(kText);
        pls.box(a.log_x ? "bcnstl" : "bcnst", 0.0, 0, a.log_y ? "bcnstvl" : "bcnstv", 0.0, 0);
        pls.lab(a.x_label.c_str(), a.y_label.c_str(), a.title.c_str());
    }
};

Plot::Plot(int width, int height, int columns) : impl_(std::make_unique<Impl>(width, height))
{
    if (!has_memcairo())
        throw Error("plotting needs PLplot's cairo driver (Debian package plplot-driver-cairo)");
    plstream& p = impl_->pls;
    p.sdev("memcairo");
    p.smema(width, height, impl_->rgba.data());
    p.scmap0(kPaletteR, kPaletteG, kPaletteB, 13);
    p.ssub(columns, 1);
    p.init();
    p.schr(0.0, 0.8);
}

Plot::~Plot() = default;

void Plot::lines(const PlotAxes& a, const std::vector<PlotSeries>& series)
{
    std::vector<double> xs, ys;
    for (const PlotSeries& s : series) {
        for (double v : s.x)
            xs.push_back(to_axis(v, a.log_x));
        for (const auto* band : {&s.y, &s.y_low, &s.y_high})
            for (double v : *band)
                ys.push_back(to_axis(v, a.log_y));
    }
    auto [x0, x1] =
        a.x_min < a.x_max ? std::pair(to_axis(a.x_min, a.log_x), to_axis(a.x_max, a.log_x)) : padded_range(xs);
    auto [y0, y1] =
        a.y_min < a.y_max ? std::pair(to_axis(a.y_min, a.log_y), to_axis(a.y_max, a.log_y)) : padded_range(ys);
    Impl& m = *impl_;
    // A long legend gets smaller text, so that it fits the panel's height; room for it:
    // one page-width per 110 characters of its longest line at that size (80 at the other).
    const std::size_t entries = series.size() + (a.legend_title.empty() ? 0 : 1);
    const bool long_legend = entries > 16;
    std::size_t longest = a.legend_title.size();
    for (const PlotSeries& s : series)
        longest = std::max(longest, s.label.size());
    const double legend_room =
        series.empty() ? 0.0
                       : std::clamp(0.08 + static_cast<double>(longest) / (long_legend ? 110.0 : 80.0), 0.2, 0.45);
    m.panel(a, x0, x1, y0, y1, false, legend_room);
    for (std::size_t i = 0; i < series.size(); ++i) {
        const PlotSeries& s = series[i];
        if (s.y_low.size() != s.x.size() || s.y_high.size() != s.x.size())
            continue;
        // The band: along the upper edge and back along the lower, the series' colour, faint.
        std::vector<PLFLT> px, py;
        for (std::size_t k = 0; k < s.x.size(); ++k)
            if (std::isfinite(to_axis(s.x[k], a.log_x)) && std::isfinite(to_axis(s.y_high[k], a.log_y))) {
                px.push_back(to_axis(s.x[k], a.log_x));
                py.push_back(to_axis(s.y_high[k], a.log_y));
            }
        for (std::size_t k = s.x.size(); k-- > 0;)
            if (std::isfinite(to_axis(s.x[k], a.log_x)) && std::isfinite(to_axis(s.y_low[k], a.log_y))) {
                px.push_back(to_axis(s.x[k], a.log_x));
                py.push_back(to_axis(s.y_low[k], a.log_y));
            }
        if (px.size() < 3)
            continue;
        int c = Impl::colour_of(s, i);
        m.scratch(kPaletteR[c] / 255.0, kPaletteG[c] / 255.0, kPaletteB[c] / 255.0, 0.18);
        m.pls.fill(static_cast<PLINT>(px.size()), px.data(), py.data());
    }
    m.pls.width(2.0);
    for (std::size_t i = 0; i < series.size(); ++i) {
        const PlotSeries& s = series[i];
        m.pls.col0(Impl::colour_of(s, i));
        m.pls.lsty(Impl::style_of(s, i));
        // Runs of drawable points (a log axis breaks the line at values <= 0).
        std::vector<PLFLT> px, py;
        auto flush = [&] {
            if (px.size() >= 2)
                m.pls.line(static_cast<PLINT>(px.size()), px.data(), py.data());
            px.clear();
            py.clear();
        };
        for (std::size_t k = 0; k < s.x.size() && k < s.y.size(); ++k) {
            double x = to_axis(s.x[k], a.log_x), y = to_axis(s.y[k], a.log_y);
            if (!std::isfinite(x) || !std::isfinite(y)) {
                flush();
                continue;
            }
            px.push_back(x);
            py.push_back(y);
        }
        flush();
    }
    m.pls.width(1.0);
    m.pls.lsty(1);
    if (series.empty())
        return;
    // The legend: an optional title line (no line sample), then one entry per series.
    std::vector<PLINT> opt, text_colours, line_colours, line_styles;
    std::vector<PLFLT> line_widths;
    std::vector<const char*> text;
    auto entry = [&](PLINT o, const std::string& label, int colour, int style) {
        opt.push_back(o);
        text_colours.push_back(kText);
        line_colours.push_back(colour);
        line_styles.push_back(style);
        line_widths.push_back(2.0);
        text.push_back(label.c_str());
    };
    if (!a.legend_title.empty())
        entry(PL_LEGEND_NONE, a.legend_title, kText, 1);
    for (std::size_t i = 0; i < series.size(); ++i)
        entry(PL_LEGEND_LINE, series[i].label, Impl::colour_of(series[i], i), Impl::style_of(series[i], i));
    const PLINT n = static_cast<PLINT>(opt.size());
    PLFLT legend_width = 0.0, legend_height = 0.0;
    const PLFLT text_scale = long_legend ? 0.55 : 0.75, text_spacing = long_legend ? 1.3 : 2.0;
    m.pls.legend(&legend_width, &legend_height, PL_LEGEND_BACKGROUND | PL_LEGEND_BOUNDING_BOX,
                 PL_POSITION_RIGHT | PL_POSITION_OUTSIDE, 0.01, 0.0, 0.06, 0, kText, 1, n, 1, n, opt.data(), 0.8,
                 text_scale, text_spacing, 0.0, text_colours.data(), text.data(), nullptr, nullptr, nullptr, nullptr,
                 line_colours.data(), line_styles.data(), line_widths.data(), nullptr, nullptr, nullptr, nullptr);
}

void Plot::points(const PlotAxes& a, const std::vector<glm::vec2>& points, const std::vector<PlotGrid>& grids)
{
    Impl& m = *impl_;
    m.panel(a, 0.0, 1.0, 0.0, 1.0, true);
    for (const PlotGrid& g : grids) {
        m.scratch(g.grey, g.grey, g.grey, 1.0);
        for (unsigned i = 1; i < g.cols; ++i)
            m.pls.join(static_cast<double>(i) / g.cols, 0.0, static_cast<double>(i) / g.cols, 1.0);
        for (unsigned i = 1; i < g.rows; ++i)
            m.pls.join(0.0, static_cast<double>(i) / g.rows, 1.0, static_cast<double>(i) / g.rows);
    }
    // Dots sized to the set: a quarter of the mean spacing, within 0.2% and 1% of the side.
    const double r =
        std::clamp(0.25 / std::sqrt(static_cast<double>(std::max<std::size_t>(points.size(), 1))), 0.002, 0.01);
    m.scratch(0.05, 0.2, 0.65, 1.0);
    for (const glm::vec2& p : points)
        m.pls.arc(p.x, p.y, r, r, 0.0, 360.0, 0.0, true);
    m.pls.col0(kText);
    m.pls.box("bc", 0.0, 0, "bc", 0.0, 0); // the frame over the grid
}

void Plot::grey_map(const PlotAxes& a, const std::vector<double>& z, int nx, int ny, double x0, double x1, double y0,
                    double y1, double z_white, double circle)
{
    Impl& m = *impl_;
    m.panel(a, x0, x1, y0, y1, true);
    PLFLT pos[2] = {0.0, 1.0}, lo[2] = {0.0, 1.0};
    m.pls.scmap1l(true, 2, pos, lo, lo, lo, nullptr);
    std::vector<PLFLT> column(static_cast<std::size_t>(nx) * ny);
    std::vector<PLFLT*> cols(static_cast<std::size_t>(nx));
    for (int x = 0; x < nx; ++x) {
        cols[static_cast<std::size_t>(x)] = &column[static_cast<std::size_t>(x) * ny];
        for (int y = 0; y < ny; ++y)
            cols[static_cast<std::size_t>(x)][y] = std::min(z[static_cast<std::size_t>(y) * nx + x], z_white);
    }
    m.pls.image(cols.data(), nx, ny, x0, x1, y0, y1, 0.0, z_white, x0, x1, y0, y1);
    if (circle > 0.0) {
        m.scratch(0.9, 0.1, 0.1, 1.0);
        m.pls.width(1.5);
        m.pls.arc(0.0, 0.0, circle, circle, 0.0, 360.0, 0.0, false);
        m.pls.width(1.0);
    }
    m.pls.col0(kText);
    m.pls.box("bcnst", 0.0, 0, "bcnstv", 0.0, 0);
}

Image Plot::finish()
{
    Impl& m = *impl_;
    m.pls.eop();
    Image img;
    img.width = static_cast<std::uint32_t>(m.width);
    img.height = static_cast<std::uint32_t>(m.height);
    img.spp = 1;
    const std::size_t n = static_cast<std::size_t>(m.width) * m.height;
    img.rgb.resize(n * 3);
    for (std::size_t i = 0; i < n; ++i)
        for (int c = 0; c < 3; ++c)
            img.rgb[i * 3 + c] = srgb_to_linear(m.rgba[i * 4 + c] / 255.0f); // write_image encodes sRGB
    img.variance.assign(n * 3, 0.0f);
    return img;
}

} // namespace pathcl
