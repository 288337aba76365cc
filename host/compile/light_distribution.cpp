#include "compile/light_distribution.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "compile/alias_table.h"
#include "light/light_pick.h"

namespace pathcl {

std::vector<LightAliasEntry> build_light_distribution(const std::vector<double>& power)
{
    const std::size_t n = power.size();
    std::vector<LightAliasEntry> d(n, LightAliasEntry{});
    const AliasTable table = build_alias_table(power);
    // Thresholds on the kernel's coin grid; a light that has a slot of its own keeps at
    // least one grid step of it, so even a powerless light stays pickable.
    const double grid = static_cast<double>(LIGHT_PICK_GRID);
    std::vector<std::uint32_t> threshold(n);
    for (std::size_t i = 0; i < n; ++i) {
        threshold[i] = static_cast<std::uint32_t>(
            std::clamp(std::llround(table.keep[i] * grid), 1LL, static_cast<long long>(LIGHT_PICK_GRID)));
        d[i].alias = static_cast<pcl_int>(table.alias[i]);
    }
    // Each light's pmf as the kernel realizes it: slot j comes up for the grid steps
    // [first_step(j), first_step(j + 1)), and keeps its light for `threshold` of the coin's.
    std::vector<double> pmf(n, 0.0);
    for (std::size_t j = 0; j < n; ++j) {
        double slot = static_cast<double>(light_pick_first_step(j + 1, n) - light_pick_first_step(j, n)) / grid;
        double keep = static_cast<double>(threshold[j]) / grid;
        pmf[j] += slot * keep;
        pmf[static_cast<std::size_t>(d[j].alias)] += slot * (1.0 - keep);
        d[j].alias_threshold = threshold[j];
    }
    for (std::size_t i = 0; i < n; ++i)
        d[i].pmf = static_cast<float>(pmf[i]);
    return d;
}

} // namespace pathcl
