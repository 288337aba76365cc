#include "converge/convergence_summary.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace pathcl {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

double median(std::vector<double> v)
{
    if (v.empty())
        return kNaN;
    std::sort(v.begin(), v.end());
    std::size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// One significant digit: 0.00347 -> 0.003.
double round_1sig(double v)
{
    double p = std::pow(10.0, std::floor(std::log10(v)));
    return std::round(v / p) * p;
}

std::string fmt(const char* format, double v)
{
    char buf[64];
    std::snprintf(buf, sizeof buf, format, v);
    return buf;
}

std::string seconds_text(double s)
{
    if (!std::isfinite(s))
        return "not reached";
    return s < 10.0 ? fmt("%.3g s", s) : fmt("%.0f s", s);
}

// The rows of one setting at the ladder's last point it reached.
std::vector<const ConvergenceRow*> last_point(const std::vector<ConvergenceRow>& rows, std::size_t setting)
{
    std::uint32_t top = 0;
    for (const ConvergenceRow& r : rows)
        if (r.setting == setting)
            top = std::max(top, r.spp);
    std::vector<const ConvergenceRow*> out;
    for (const ConvergenceRow& r : rows)
        if (r.setting == setting && r.spp == top)
            out.push_back(&r);
    return out;
}

} // namespace

std::vector<SettingCurve> setting_curves(const std::vector<ConvergenceRow>& rows, std::size_t settings,
                                         const std::vector<std::uint32_t>& ladder)
{
    std::vector<SettingCurve> curves(settings);
    for (std::size_t s = 0; s < settings; ++s)
        for (std::uint32_t n : ladder) {
            std::vector<double> spp, seconds, err;
            for (const ConvergenceRow& r : rows)
                if (r.setting == s && r.spp == n) {
                    spp.push_back(r.spp_taken);
                    seconds.push_back(r.render_seconds);
                    err.push_back(r.error.relmse);
                }
            if (err.empty())
                continue;
            SettingCurve& c = curves[s];
            c.spp.push_back(median(spp));
            c.seconds.push_back(median(seconds));
            c.relmse.push_back(median(err));
            c.relmse_min.push_back(*std::min_element(err.begin(), err.end()));
            c.relmse_max.push_back(*std::max_element(err.begin(), err.end()));
        }
    return curves;
}

double log_log_slope(const std::vector<double>& x, const std::vector<double>& y)
{
    double sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0, n = 0.0;
    for (std::size_t i = 0; i < x.size() && i < y.size(); ++i) {
        if (!(x[i] > 0.0) || !(y[i] > 0.0))
            continue;
        double lx = std::log(x[i]), ly = std::log(y[i]);
        sx += lx;
        sy += ly;
        sxx += lx * lx;
        sxy += lx * ly;
        n += 1.0;
    }
    double d = n * sxx - sx * sx;
    if (n < 2.0 || !(std::fabs(d) > 0.0))
        return kNaN;
    return (n * sxy - sx * sy) / d;
}

double time_to_reach(const SettingCurve& c, double target)
{
    for (std::size_t i = 0; i < c.relmse.size(); ++i) {
        if (!(c.relmse[i] <= target))
            continue;
        if (i == 0)
            return c.seconds[0];
        double e0 = std::log(c.relmse[i - 1]), e1 = std::log(c.relmse[i]);
        double t0 = std::log(c.seconds[i - 1]), t1 = std::log(c.seconds[i]);
        if (!(e1 < e0))
            return c.seconds[i];
        return std::exp(t0 + (std::log(target) - e0) * (t1 - t0) / (e1 - e0));
    }
    return kNaN;
}

std::vector<double> default_targets(const std::vector<SettingCurve>& curves)
{
    // Spread between the settings' median first and median last error: a setting whose
    // bias stops it short (few bounces) neither sets nor narrows the range.
    std::vector<double> first, last;
    for (const SettingCurve& c : curves)
        if (c.relmse.size() >= 2) {
            first.push_back(c.relmse.front());
            last.push_back(c.relmse.back());
        }
    if (first.empty())
        return {};
    double hi = std::log(median(first)), lo = std::log(median(last));
    std::vector<double> t;
    for (double f : {0.25, 0.5, 0.75}) {
        double v = round_1sig(std::exp(hi + f * (lo - hi)));
        if (t.empty() || v < t.back())
            t.push_back(v);
    }
    return t;
}

std::string summary_markdown(const ConvergenceReport& rep)
{
    const ConvergenceStudy& st = *rep.study;
    const std::vector<SettingCurve> curves = setting_curves(rep.rows, st.settings.size(), st.ladder);
    const std::vector<double> targets = rep.targets.empty() ? default_targets(curves) : rep.targets;
    std::string md = "# Convergence: " + rep.scene_path + "\n\n";
    if (rep.interrupted)
        md += "**Interrupted**: the figures below are from the rows finished before the stop.\n\n";
    md += "Command: `" + rep.command + "`\n\n";
    md += "Reference: " + rep.reference + ".\n\n";
    md += std::to_string(st.base.width) + "x" + std::to_string(st.base.height) + " pixels; spp ladder";
    for (std::uint32_t n : st.ladder)
        md += " " + std::to_string(n);
    md += "; " + std::to_string(st.seeds) +
          " seeds per point. relMSE is the mean over pixels and channels of "
          "(x - r)^2 / (r^2 + 0.01) against the reference r. Times are render "
          "times, kernel build and the first dispatch excluded (the driver's "
          "lazy compile; see the last column), medians over seeds. The slopes are "
          "least-squares fits of log relMSE against log spp and log time over "
          "the ladder; the time to a target is interpolated on the median curve. "
          "Efficiency is 1 / (relMSE x time) at each setting's largest spp, "
          "relative to the first setting; efficiency (RMSE) is 1 / (RMSE^2 x time), "
          "which bright pixels dominate where relMSE weighs every pixel alike.\n\n";
    md += "| setting | slope vs spp | slope vs time";
    for (double t : targets)
        md += " | time to " + fmt("%g", t);
    md += " | efficiency | efficiency (RMSE) | samples/s | mean bias (std. err.) | failing pixels | build cold / "
          "cached, first render |\n|---|---|---";
    for (std::size_t i = 0; i < targets.size(); ++i)
        md += "|---";
    md += "|---|---|---|---|---|---|\n";
    double first_efficiency = kNaN, first_rmse_efficiency = kNaN;
    for (std::size_t s = 0; s < st.settings.size(); ++s) {
        const SettingCurve& c = curves[s];
        md += "| " + st.settings[s].label();
        if (c.relmse.empty()) {
            md += " | no rows |\n";
            continue;
        }
        md += " | " + fmt("%.2f", log_log_slope(c.spp, c.relmse)) + " | " +
              fmt("%.2f", log_log_slope(c.seconds, c.relmse));
        for (double t : targets)
            md += " | " + seconds_text(time_to_reach(c, t));
        double efficiency = 1.0 / (c.relmse.back() * c.seconds.back());
        if (s == 0)
            first_efficiency = efficiency;
        std::vector<double> rate, bias, bias_se, failing, rmse;
        for (const ConvergenceRow* r : last_point(rep.rows, s)) {
            rmse.push_back(r->error.rmse);
            rate.push_back(r->samples_per_second);
            bias.push_back(r->error.mean_bias);
            bias_se.push_back(r->error.mean_bias_stderr);
            failing.push_back(r->error.failing_pixels);
        }
        const double rmse_efficiency = 1.0 / (median(rmse) * median(rmse) * c.seconds.back());
        if (s == 0)
            first_rmse_efficiency = rmse_efficiency;
        const SettingBuild b = s < rep.builds.size() ? rep.builds[s] : SettingBuild{};
        md += " | " + fmt("%.2f", efficiency / first_efficiency) + " | " +
              fmt("%.2f", rmse_efficiency / first_rmse_efficiency) + " | " + fmt("%.3g", median(rate)) + " | " +
              fmt("%.2g", median(bias)) + " (" + fmt("%.1g", median(bias_se)) + ") | " +
              fmt("%.2g%%", 100.0 * median(failing)) + " | " + fmt("%.2f", b.cold_seconds) + " / " +
              fmt("%.3f", b.cached_seconds) + " s, " + fmt("%.3f", b.first_render_seconds) + " s |\n";
    }
    md += "\n![relMSE against render time](error_vs_time.png)\n\n![relMSE against spp](error_vs_spp.png)\n";
    return md;
}

} // namespace pathcl
