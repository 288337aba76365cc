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
    // A partial render's exact film state (render/film_channels.h), written to an EXR as
    // a second part named "film" of 32-bit unsigned channels: film_channels names them,
    // film holds width * height * film_channels.size() values, pixel by pixel. Empty for
    // a whole render.
    std::vector<std::string> film_channels;
    std::vector<std::uint32_t> film;

    double pixel_spp(std::size_t pixel) const { return samples.empty() ? spp : samples[pixel]; }
};

} // namespace pathcl
