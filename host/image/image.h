// A rendered image: per-pixel mean radiance and per-sample variance, linear Rec.709 RGB,
// with how it was made.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace pathcl {

struct Image {
    std::uint32_t width = 0, height = 0;
    std::vector<float> rgb;      // width * height * 3, row 0 at the top
    std::vector<float> variance; // same layout: variance of one sample (not of the mean)
    std::uint32_t spp = 0;       // samples per pixel behind each mean
    // Samples behind each pixel's mean where they differ (adaptive sampling); empty: spp.
    std::vector<std::uint32_t> samples;
    // How the render went, as text (EXR attributes "pathcl:<key>"): the stop reason, the
    // estimated error, the batches, the seed.
    std::map<std::string, std::string> metadata;

    double pixel_spp(std::size_t pixel) const { return samples.empty() ? spp : samples[pixel]; }
};

} // namespace pathcl
