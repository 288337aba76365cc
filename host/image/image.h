// A rendered image: per-pixel mean radiance and per-sample variance, linear Rec.709 RGB.
#pragma once

#include <cstdint>
#include <vector>

namespace pathcl {

struct Image {
    std::uint32_t width = 0, height = 0;
    std::vector<float> rgb;      // width * height * 3, row 0 at the top
    std::vector<float> variance; // same layout: variance of one sample (not of the mean)
    std::uint32_t spp = 0;       // samples per pixel behind each mean
};

} // namespace pathcl
