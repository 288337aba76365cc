#include "converge/convergence_plots.h"

#include <algorithm>

#include "plot/plot.h"

namespace pathcl {

namespace {

// Where `value` first appears among the settings' values of knob k (its colour or dash).
int value_index(const ConvergenceStudy& st, std::size_t k, const std::string& value)
{
    std::vector<std::string> seen;
    for (const Setting& s : st.settings) {
        const std::string& v = s.values[k].second;
        if (v == value)
            break;
        if (std::find(seen.begin(), seen.end(), v) == seen.end())
            seen.push_back(v);
    }
    return static_cast<int>(seen.size());
}

} // namespace

Image error_plot(const ConvergenceReport& rep, bool by_time)
{
    const ConvergenceStudy& st = *rep.study;
    std::vector<SettingCurve> curves = setting_curves(rep.rows, st.settings.size(), st.ladder);
    // Legend lines list the values; its title names the knobs. Two knobs: the first
    // gives the colour, the second the dash style.
    const std::size_t knobs = st.settings.empty() ? 0 : st.settings.front().values.size();
    std::vector<PlotSeries> series;
    for (std::size_t s = 0; s < curves.size(); ++s) {
        PlotSeries p;
        const Setting& setting = st.settings[s];
        for (const auto& [knob, v] : setting.values)
            p.label += (p.label.empty() ? "" : ", ") + v;
        if (knobs == 2) {
            p.colour = value_index(st, 0, setting.values[0].second);
            p.style = value_index(st, 1, setting.values[1].second);
        }
        p.x = by_time ? curves[s].seconds : curves[s].spp;
        p.y = curves[s].relmse;
        p.y_low = curves[s].relmse_min;
        p.y_high = curves[s].relmse_max;
        series.push_back(std::move(p));
    }
    PlotAxes axes;
    axes.log_x = axes.log_y = true;
    axes.title = rep.scene_path + ", " + std::to_string(st.base.width) + "x" + std::to_string(st.base.height) +
                 ": median of " + std::to_string(st.seeds) + " seeds, band min-max";
    axes.x_label = by_time ? "render time (s, kernel build excluded)" : "samples per pixel";
    axes.y_label = "relMSE against the reference";
    if (!st.settings.empty())
        for (const auto& [knob, v] : st.settings.front().values)
            axes.legend_title += (axes.legend_title.empty() ? "" : ", ") + knob;
    Plot plot(1300, 760);
    plot.lines(axes, series);
    return plot.finish();
}

} // namespace pathcl
