// The light distribution: how often next event estimation picks each light. Lights are
// picked in proportion to their power (luminance) through an alias table (Vose's method),
// whose coin and slot are integers on the kernels' 2^24 grid (kernels/light/light_pick.h),
// so each light's pmf is exactly the probability the kernel picks it with. Kept apart from
// the light records (compile_lights.cpp), as pbrt keeps its light samplers apart from its
// lights.
#pragma once

#include <vector>

#include "types.h"

namespace pathcl {

// One entry per light, in the order of `power`: pmf, alias threshold and alias. A light
// with no power keeps at least one grid step, so every light stays pickable.
std::vector<LightAliasEntry> build_light_distribution(const std::vector<double>& power);

} // namespace pathcl
