// The plots of a convergence study: relMSE against render time (error_vs_time.png) or
// samples per pixel (error_vs_spp.png), log-log, one line per setting (the median over
// seeds) with its min-max band.
#pragma once

#include "converge/convergence_summary.h"
#include "image/image.h"

namespace pathcl {

Image error_plot(const ConvergenceReport& report, bool by_time);

} // namespace pathcl
