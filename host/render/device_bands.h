// How a render's rows are dealt to its devices. Each device renders a band of whole rows
// and keeps those pixels' film; every pixel's samples are taken and summed by exactly one
// device, in the same order as on one device, so the image is bit for bit the one-device
// image whatever the number of devices and wherever the band boundaries fall (a pixel's
// film moves with its row when the bands change; render/renderer.cpp). Band boundaries are
// multiples of kBandRows, which every work-group tile height divides, so a device's
// launch, rounded up to whole tiles, never reaches into the next band; the last band ends
// at the image's height, which the kernels check.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace pathcl {

constexpr std::uint32_t kBandRows = 8;

// Boundaries b[0] = 0 <= b[1] <= ... <= b[n] = height of n = `bands` bands (at least 1)
// with sizes as near to proportional to `weights` as multiples of kBandRows allow (a band
// may be empty). Weights that are not one per band, all finite and non-negative with a
// positive sum (an empty list included: no shares given) count as equal.
std::vector<std::uint32_t> band_bounds(std::uint32_t height, std::size_t bands, const std::vector<double>& weights);

} // namespace pathcl
