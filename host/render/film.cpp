#include "render/film.h"

#include <algorithm>

namespace pathcl {

FilmSum::FilmSum(std::size_t pixels) : sum_(pixels * 4, 0.0), sum_sq_(pixels * 4, 0.0)
{}

void FilmSum::add(const std::vector<FilmPixel>& film, const std::vector<pcl_uint>& bad_samples)
{
    for (std::size_t i = 0; i < film.size(); ++i) {
        const FilmPixel& f = film[i];
        const float* s = &f.sum.x;
        const float* sc = &f.sum_compensation.x;
        const float* q = &f.sum_sq.x;
        const float* qc = &f.sum_sq_compensation.x;
        for (int c = 0; c < 4; ++c) {
            sum_[i * 4 + c] += static_cast<double>(s[c]) + static_cast<double>(sc[c]);
            sum_sq_[i * 4 + c] += static_cast<double>(q[c]) + static_cast<double>(qc[c]);
        }
        bad_ += bad_samples[i];
    }
}

Image FilmSum::image(std::uint32_t width, std::uint32_t height, std::uint32_t spp) const
{
    const std::size_t pixels = static_cast<std::size_t>(width) * height;
    Image img;
    img.width = width;
    img.height = height;
    img.spp = spp;
    img.rgb.resize(pixels * 3);
    img.variance.resize(pixels * 3);
    for (std::size_t i = 0; i < pixels; ++i) {
        double n = sum_[i * 4 + 3]; // samples actually accumulated (bad ones excluded)
        for (int c = 0; c < 3; ++c) {
            double s = sum_[i * 4 + c], q = sum_sq_[i * 4 + c];
            double mean = n > 0.0 ? s / n : 0.0;
            double var = n > 1.0 ? std::max(0.0, (q - s * mean) / (n - 1.0)) : 0.0;
            img.rgb[i * 3 + c] = static_cast<float>(mean);
            img.variance[i * 3 + c] = static_cast<float>(var);
        }
    }
    return img;
}

} // namespace pathcl
