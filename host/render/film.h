// The image from the devices' films: each device's compensated float sums of L and L^2
// (kernels/film/film.cl) are added in double, then turned into per-pixel means and
// per-sample variances.
#pragma once

#include <cstdint>
#include <vector>

#include "image/image.h"
#include "types.h"

namespace pathcl {

class FilmSum {
public:
    explicit FilmSum(std::size_t pixels);

    // Adds one device's film and bad-sample counters (pixel order).
    void add(const std::vector<FilmPixel>& film, const std::vector<pcl_uint>& bad_samples);

    std::uint64_t bad_samples() const { return bad_; }

    // Means and per-sample variances of the samples added (bad ones excluded); the image
    // records `spp` as its sample count.
    Image image(std::uint32_t width, std::uint32_t height, std::uint32_t spp) const;

private:
    std::vector<double> sum_, sum_sq_; // four channels per pixel: rgb and the sample count
    std::uint64_t bad_ = 0;
};

} // namespace pathcl
