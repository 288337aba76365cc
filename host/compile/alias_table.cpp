#include "compile/alias_table.h"

#include <cstddef>

namespace pathcl {

AliasTable build_alias_table(const std::vector<double>& weight)
{
    const std::size_t n = weight.size();
    AliasTable t{std::vector<double>(n, 1.0), std::vector<std::uint32_t>(n)}; // leftovers: always keep
    double total = 0.0;
    for (double w : weight)
        total += w;
    std::vector<double> scaled(n);
    std::vector<std::size_t> small, large;
    for (std::size_t i = 0; i < n; ++i) {
        const double share = total > 0.0 ? weight[i] / total : 1.0 / static_cast<double>(n);
        scaled[i] = share * static_cast<double>(n);
        t.alias[i] = static_cast<std::uint32_t>(i);
        (scaled[i] < 1.0 ? small : large).push_back(i);
    }
    while (!small.empty() && !large.empty()) {
        const std::size_t s = small.back(), l = large.back();
        small.pop_back();
        t.keep[s] = scaled[s];
        t.alias[s] = static_cast<std::uint32_t>(l);
        scaled[l] = (scaled[l] + scaled[s]) - 1.0;
        if (scaled[l] < 1.0) {
            large.pop_back();
            small.push_back(l);
        }
    }
    return t;
}

} // namespace pathcl
