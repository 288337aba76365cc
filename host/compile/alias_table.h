// Vose's alias method: n weights become n slots, each keeping its own entry with a
// probability and otherwise giving way to another, so that one uniform slot and one coin
// pick entry i with probability weight i / their sum. Both the power table (every light;
// light_distribution.h) and the light tree's clusters (light_tree.h) pick through one.
#pragma once

#include <cstdint>
#include <vector>

namespace pathcl {

// Slot i keeps entry i where the coin falls below keep[i] (in [0, 1]), else gives
// alias[i]. Computed in double so that tiny weights keep their share. Weights that sum to
// 0 give every entry an equal share; a weight of 0 among others keeps nothing.
struct AliasTable {
    std::vector<double> keep;
    std::vector<std::uint32_t> alias;
};

AliasTable build_alias_table(const std::vector<double>& weight);

} // namespace pathcl
