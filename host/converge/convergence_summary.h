// What a convergence study's rows say: per setting, the curve over the ladder (medians
// over seeds with their min and max), the fitted slope of log relMSE against log spp and
// log time, the time to reach error targets, and the efficiencies 1 / (relMSE x time)
// and 1 / (RMSE^2 x time) relative to the first setting (summary.md).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "converge/convergence.h"

namespace pathcl {

// One setting over the ladder points it has rows for.
struct SettingCurve {
    std::vector<double> spp;     // median over seeds of the samples per pixel taken
    std::vector<double> seconds; // median render time
    std::vector<double> relmse, relmse_min, relmse_max;
};

std::vector<SettingCurve> setting_curves(const std::vector<ConvergenceRow>& rows, std::size_t settings,
                                         const std::vector<std::uint32_t>& ladder);

// Least-squares slope of log y against log x over the points where both are positive
// (NaN with fewer than two).
double log_log_slope(const std::vector<double>& x, const std::vector<double>& y);

// The render time at which the curve's median relMSE first reaches `target`,
// interpolated log-linearly between ladder points; NaN when it never does.
double time_to_reach(const SettingCurve& curve, double target);

// Three targets spread evenly (in log) from the settings' median first-point error to
// their median last-point error, rounded to one significant digit.
std::vector<double> default_targets(const std::vector<SettingCurve>& curves);

struct ConvergenceReport {
    std::string scene_path, command;
    const ConvergenceStudy* study = nullptr;
    std::vector<SettingBuild> builds;
    std::vector<ConvergenceRow> rows;
    std::vector<double> targets; // empty: default_targets
    std::string reference;       // how the reference was made (or the file it came from)
    bool interrupted = false;
};

std::string summary_markdown(const ConvergenceReport& report);

} // namespace pathcl
