#include "render/film.h"

#include <algorithm>

#include "common/error.h"

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

FilmSum::Moments FilmSum::moments(std::size_t i, int c) const
{
    Moments m;
    m.n = sum_[i * 4 + 3]; // samples actually accumulated (bad ones excluded)
    const double s = sum_[i * 4 + c], q = sum_sq_[i * 4 + c];
    m.mean = m.n > 0.0 ? s / m.n : 0.0;
    m.variance = m.n > 1.0 ? std::max(0.0, (q - s * m.mean) / (m.n - 1.0)) : 0.0;
    return m;
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
    for (std::size_t i = 0; i < pixels; ++i)
        for (int c = 0; c < 3; ++c) {
            const Moments m = moments(i, c);
            img.rgb[i * 3 + c] = static_cast<float>(m.mean);
            img.variance[i * 3 + c] = static_cast<float>(m.variance);
        }
    return img;
}

FilmAccumulator::FilmAccumulator(std::size_t pixels, std::uint32_t batch_spp)
    : total_(pixels), batch_spp_(batch_spp), batch_mean_sum_(pixels * 3, 0.0), batch_mean_sq_(pixels * 3, 0.0),
      pixel_batches_(pixels, 0)
{}

void FilmAccumulator::add_to_total(const FilmSum& batch)
{
    for (std::size_t i = 0; i < total_.sum_.size(); ++i) {
        total_.sum_[i] += batch.sum_[i];
        total_.sum_sq_[i] += batch.sum_sq_[i];
    }
    total_.bad_ += batch.bad_;
}

void FilmAccumulator::add_batch(const FilmSum& batch)
{
    add_to_total(batch);
    for (std::size_t i = 0; i < pixel_batches_.size(); ++i) {
        double n = batch.sum_[i * 4 + 3];
        if (!(n > 0.0))
            continue; // the pixel took no sample in this batch (adaptive sampling)
        ++pixel_batches_[i];
        for (int c = 0; c < 3; ++c) {
            double m = batch.sum_[i * 4 + c] / n;
            batch_mean_sum_[i * 3 + c] += m;
            batch_mean_sq_[i * 3 + c] += m * m;
        }
    }
    ++batches_;
}

void FilmAccumulator::add_partial_batch(const FilmSum& batch)
{
    add_to_total(batch);
}

FilmAccumulator::State FilmAccumulator::state() const
{
    return State{total_.sum_, total_.sum_sq_, batch_mean_sum_, batch_mean_sq_, pixel_batches_, total_.bad_, batches_};
}

void FilmAccumulator::restore(const State& s)
{
    if (s.sum.size() != total_.sum_.size() || s.sum_sq.size() != total_.sum_sq_.size() ||
        s.batch_mean_sum.size() != batch_mean_sum_.size() || s.batch_mean_sq.size() != batch_mean_sq_.size() ||
        s.pixel_batches.size() != pixel_batches_.size())
        throw Error("the film state does not match the image size");
    total_.sum_ = s.sum;
    total_.sum_sq_ = s.sum_sq;
    total_.bad_ = s.bad;
    batch_mean_sum_ = s.batch_mean_sum;
    batch_mean_sq_ = s.batch_mean_sq;
    pixel_batches_ = s.pixel_batches;
    batches_ = s.batches;
}

std::vector<std::uint32_t> FilmAccumulator::pixel_samples() const
{
    std::vector<std::uint32_t> n(pixel_batches_.size());
    for (std::size_t i = 0; i < n.size(); ++i)
        n[i] = static_cast<std::uint32_t>(total_.sum_[i * 4 + 3]);
    return n;
}

double FilmAccumulator::pixel_channel_estimate(std::size_t i, int c) const
{
    double k = pixel_batches_[i];
    double s = batch_mean_sum_[i * 3 + c], q = batch_mean_sq_[i * 3 + c];
    double spread = std::max(0.0, (q - s * s / k) / (k - 1.0)); // variance of one batch mean
    const FilmSum::Moments m = total_.moments(i, c);
    return spread * batch_spp_ / m.n / (m.mean * m.mean + kRelMseEpsilon);
}

double FilmAccumulator::pixel_relmse_estimate(std::size_t i) const
{
    if (pixel_batches_[i] < 2)
        return -1.0;
    return std::max({pixel_channel_estimate(i, 0), pixel_channel_estimate(i, 1), pixel_channel_estimate(i, 2)});
}

double FilmAccumulator::relmse_estimate() const
{
    double sum = 0.0;
    std::size_t terms = 0;
    for (std::size_t i = 0; i < pixel_batches_.size(); ++i) {
        if (pixel_batches_[i] < 2)
            continue;
        for (int c = 0; c < 3; ++c)
            sum += pixel_channel_estimate(i, c);
        terms += 3;
    }
    return terms > 0 && batches_ >= 2 ? sum / static_cast<double>(terms) : -1.0;
}

double FilmAccumulator::per_sample_relmse_estimate() const
{
    double sum = 0.0;
    std::size_t terms = 0;
    for (std::size_t i = 0; i < pixel_batches_.size(); ++i) {
        if (!(total_.sum_[i * 4 + 3] > 1.0))
            continue;
        for (int c = 0; c < 3; ++c) {
            const FilmSum::Moments m = total_.moments(i, c);
            sum += m.variance / m.n / (m.mean * m.mean + kRelMseEpsilon);
        }
        terms += 3;
    }
    return terms > 0 ? sum / static_cast<double>(terms) : -1.0;
}

} // namespace pathcl
