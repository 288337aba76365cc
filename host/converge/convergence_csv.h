// convergence.csv: one line per render of a study (setting x spp x seed), written as the
// study goes so that an interrupted study keeps its rows. Units are in the column names.
#pragma once

#include <string>
#include <vector>

#include "converge/convergence.h"

namespace pathcl {

std::string csv_header(const ConvergenceStudy& study);
// The row's line (the setting's knob values in their own columns), with a newline.
std::string csv_line(const ConvergenceStudy& study, const std::vector<SettingBuild>& builds, const ConvergenceRow& row);

} // namespace pathcl
