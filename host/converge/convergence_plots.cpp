#include "converge/convergence_plots.h"

#include "plot/plot.h"

namespace pathcl {

Image error_plot(const ConvergenceReport& rep, bool by_time)
{
    const ConvergenceStudy& st = *rep.study;
    std::vector<SettingCurve> curves = setting_curves(rep.rows, st.settings.size(), st.ladder);
    std::vector<PlotSeries> series;
    for (std::size_t s = 0; s < curves.size(); ++s) {
        PlotSeries p;
        p.label = st.settings[s].label();
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
    Plot plot(1100, 760);
    plot.lines(axes, series);
    return plot.finish();
}

} // namespace pathcl
