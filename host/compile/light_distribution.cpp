#include "compile/light_distribution.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "light/light_pick.h"

namespace pathcl {

std::vector<LightAliasEntry> build_light_distribution(const std::vector<double>& power)
{
    // Vose's alias method, in double so that tiny lights keep their probability.
    const std::size_t n = power.size();
    std::vector<LightAliasEntry> d(n, LightAliasEntry{});
    if (n == 0)
        return d;
    double total = 0.0;
    for (double p : power)
        total += p;
    std::vector<double> scaled(n);
    std::vector<std::size_t> small, large;
    for (std::size_t i = 0; i < n; ++i) {
        double pmf = total > 0.0 ? power[i] / total : 1.0 / static_cast<double>(n);
        scaled[i] = pmf * static_cast<double>(n);
        d[i].alias = static_cast<pcl_int>(i);
        (scaled[i] < 1.0 ? small : large).push_back(i);
    }
    // Thresholds on the kernel's coin grid; a light that has a slot of its own keeps at
    // least one grid step of it, so even a powerless light stays pickable.
    const double grid = static_cast<double>(LIGHT_PICK_GRID);
    std::vector<std::uint32_t> threshold(n, LIGHT_PICK_GRID); // leftovers: always keep
    while (!small.empty() && !large.empty()) {
        std::size_t s = small.back(), l = large.back();
        small.pop_back();
        threshold[s] = static_cast<std::uint32_t>(
            std::clamp(std::llround(scaled[s] * grid), 1LL, static_cast<long long>(LIGHT_PICK_GRID)));
        d[s].alias = static_cast<pcl_int>(l);
        scaled[l] = (scaled[l] + scaled[s]) - 1.0;
        if (scaled[l] < 1.0) {
            large.pop_back();
            small.push_back(l);
        }
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
