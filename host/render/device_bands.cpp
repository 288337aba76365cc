#include "render/device_bands.h"

#include <algorithm>
#include <cmath>

namespace pathcl {

std::vector<std::uint32_t> band_bounds(std::uint32_t height, std::size_t bands, const std::vector<double>& weights)
{
    const std::size_t n = std::max<std::size_t>(1, bands);
    double total = 0.0;
    bool valid = weights.size() == n;
    for (double w : weights) {
        valid = valid && std::isfinite(w) && w >= 0.0;
        total += w;
    }
    valid = valid && total > 0.0 && std::isfinite(total);
    std::vector<std::uint32_t> bounds(n + 1, 0);
    double cumulative = 0.0;
    for (std::size_t i = 1; i < n; ++i) {
        cumulative += valid ? weights[i - 1] / total : 1.0 / static_cast<double>(n);
        const double rows = std::round(cumulative * height / kBandRows) * kBandRows;
        bounds[i] = std::clamp(static_cast<std::uint32_t>(std::min<double>(rows, height)), bounds[i - 1], height);
    }
    bounds[n] = height;
    return bounds;
}

} // namespace pathcl
