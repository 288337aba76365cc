#include "converge/convergence_csv.h"

#include <cstdio>

namespace pathcl {
namespace {

std::string g(double v)
{
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", v);
    return buf;
}

// The knobs the study varies, in --vary order (the first setting lists them all).
std::vector<std::string> varied(const ConvergenceStudy& study)
{
    std::vector<std::string> names;
    if (!study.settings.empty())
        for (const auto& kv : study.settings.front().values)
            names.push_back(kv.first);
    return names;
}

} // namespace

std::string csv_header(const ConvergenceStudy& study)
{
    std::string h = "setting";
    for (const std::string& k : varied(study))
        h += "," + k;
    return h +
           ",spp,spp_taken,seed,render_seconds,samples_per_second,rmse,relmse,mean_bias,mean_bias_stderr,"
           "failing_pixel_fraction,relmse_estimate,stop,build_cold_seconds,build_cached_seconds,first_render_seconds\n";
}

std::string csv_line(const ConvergenceStudy& study, const std::vector<SettingBuild>& builds, const ConvergenceRow& r)
{
    const Setting& s = study.settings[r.setting];
    std::string line = std::to_string(r.setting);
    for (const std::string& k : varied(study))
        line += "," + s.value(k);
    const SettingBuild b = r.setting < builds.size() ? builds[r.setting] : SettingBuild{};
    line += "," + std::to_string(r.spp) + "," + g(r.spp_taken) + "," + std::to_string(r.seed) + "," +
            g(r.render_seconds) + "," + g(r.samples_per_second) + "," + g(r.error.rmse) + "," + g(r.error.relmse) +
            "," + g(r.error.mean_bias) + "," + g(r.error.mean_bias_stderr) + "," + g(r.error.failing_pixels) + "," +
            g(r.error_estimate) + "," + r.stop + "," + g(b.cold_seconds) + "," + g(b.cached_seconds) + "," +
            g(b.first_render_seconds) + "\n";
    return line;
}

} // namespace pathcl
