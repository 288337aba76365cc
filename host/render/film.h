// The image from the devices' films. Each device keeps compensated float sums of L and L^2
// per pixel (kernels/film/film.cl); a batch's films are added in double (FilmSum), and a
// render's batches are added up (FilmAccumulator), which also keeps, per pixel and
// channel, the spread of the batch means: with two or more independently scrambled
// batches (render/batches.h) that spread is an honest estimate of the image's error for
// every sampler, the stratified and quasi-Monte Carlo ones included, whose per-sample
// variance overstates it.
#pragma once

#include <cstdint>
#include <vector>

#include "image/image.h"
#include "image/image_error.h"
#include "types.h"

namespace pathcl {

// One batch: every device's film added.
class FilmSum {
public:
    explicit FilmSum(std::size_t pixels);

    // Adds one device's film (compensation terms folded in) and bad-sample counts.
    void add(const std::vector<FilmPixel>& film, const std::vector<pcl_uint>& bad_samples);

    std::uint64_t bad_samples() const { return bad_; }

    // Per-pixel means and per-sample variances; spp is recorded in the image (the sum's
    // own per-pixel sample count, which excludes rejected samples, divides).
    Image image(std::uint32_t width, std::uint32_t height, std::uint32_t spp) const;

private:
    friend class FilmAccumulator;
    struct Moments {
        double n = 0.0, mean = 0.0, variance = 0.0; // samples, mean, per-sample variance (0 below 2)
    };
    Moments moments(std::size_t pixel, int channel) const;

    std::vector<double> sum_, sum_sq_; // four channels per pixel: rgb and the sample count
    std::uint64_t bad_ = 0;
};

// A render's batches.
class FilmAccumulator {
public:
    // batch_spp: the sample count of a whole batch (render/batches.h).
    FilmAccumulator(std::size_t pixels, std::uint32_t batch_spp);

    // A whole batch: counts towards the image and the spread of the batch means.
    void add_batch(const FilmSum& batch);
    // A partial batch (a budget ended it): counts towards the image only.
    void add_partial_batch(const FilmSum& batch);

    std::uint32_t batches() const { return batches_; } // whole ones
    std::uint64_t bad_samples() const { return total_.bad_; }
    Image image(std::uint32_t width, std::uint32_t height, std::uint32_t spp) const
    {
        return total_.image(width, height, spp);
    }
    // Samples each pixel has accumulated (rejected ones excluded).
    std::vector<std::uint32_t> pixel_samples() const;

    // Everything it holds, for a checkpoint (render/checkpoint.h); restore() takes back a
    // state of the same pixel count and batch size and continues bit for bit.
    struct State {
        std::vector<double> sum, sum_sq, batch_mean_sum, batch_mean_sq;
        std::vector<std::uint32_t> pixel_batches;
        std::uint64_t bad = 0;
        std::uint32_t batches = 0;
    };
    State state() const;
    void restore(const State& state); // throws pathcl::Error when the sizes differ

    // The estimated relMSE of image(): the mean over pixels and channels of
    // var(mean) / (mean^2 + 0.01). var(mean) is s^2 * batch_spp / n, s^2 the variance of
    // the pixel's whole-batch means and n its samples (s^2 / k after k whole batches).
    // Negative before two whole batches.
    double relmse_estimate() const;
    // The same for pixel i alone, its channels' largest (the adaptive sampler's measure);
    // negative before two whole batches of it.
    double pixel_relmse_estimate(std::size_t i) const;
    // The estimate from the per-sample variance instead, var(mean) = var(sample) / n:
    // right for independent samples, an upper bound for stratified and quasi-Monte Carlo
    // ones (by as much as their gain over independent sampling). Needs one batch only.
    double per_sample_relmse_estimate() const;

private:
    FilmSum total_;
    std::uint32_t batch_spp_;
    std::vector<double> batch_mean_sum_, batch_mean_sq_; // three channels per pixel
    std::vector<std::uint32_t> pixel_batches_;
    std::uint32_t batches_ = 0;
    void add_to_total(const FilmSum& batch);
    double pixel_channel_estimate(std::size_t i, int c) const;
};

} // namespace pathcl
