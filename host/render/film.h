// The image from the devices' films. Each device keeps compensated float sums of L and L^2
// per pixel (kernels/film/film.cl); a batch's films are added in double (FilmSum), and a
// render's batches are added up exactly (FilmAccumulator, render/exact_sum.h), which also
// keeps, per pixel and channel, the spread of the batch means: with two or more independently scrambled
// batches (render/batches.h) that spread is an honest estimate of the image's error for
// every sampler, the stratified and quasi-Monte Carlo ones included, whose per-sample
// variance overstates it.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "image/image.h"
#include "image/image_error.h"
#include "render/exact_sum.h"
#include "types.h"

namespace pathcl {

// Host bytes a render's film takes for `pixels` pixels on `devices` devices: the totals
// (FilmAccumulator, 300 a pixel), a batch's sums (FilmSum, 64) and each device's film read
// back (68).
double host_film_bytes(std::size_t pixels, std::size_t devices);
// Throws pathcl::Error naming both figures when `needed` exceeds `available` bytes
// (available 0: what the process may still take, common/memory_limits.h): a refusal
// before allocating instead of std::bad_alloc or the out-of-memory killer halfway
// through a render.
void check_host_memory(double needed, double available = 0.0);

// One batch: every device's film added.
class FilmSum {
public:
    explicit FilmSum(std::size_t pixels);

    // Adds one device's film (compensation terms folded in) and bad-sample counts.
    void add(const std::vector<FilmPixel>& film, const std::vector<pcl_uint>& bad_samples);

    std::uint64_t bad_samples() const { return bad_; }

private:
    friend class FilmAccumulator;
    // Four channels per pixel: rgb and the sample count. Not std::vector: its zeroing is
    // one thread's, page faults included; these are zeroed on every core.
    std::unique_ptr<double[]> sum_, sum_sq_;
    std::uint64_t bad_ = 0;
};

// A render's batches, or a sample range's (a range is made of whole batches): every total
// is an ExactSum, so the state of a render is the same however its batches were split
// over processes and merged back (merge()), and the image bit for bit.
class FilmAccumulator {
public:
    // batch_spp: the sample count of a whole batch (render/batches.h).
    FilmAccumulator(std::size_t pixels, std::uint32_t batch_spp);

    // A whole batch: counts towards the image and the spread of the batch means.
    void add_batch(const FilmSum& batch);
    // A partial batch (a budget ended it): counts towards the image only.
    void add_partial_batch(const FilmSum& batch);

    std::uint32_t batches() const { return state_.batches; } // whole ones
    std::uint64_t bad_samples() const { return state_.bad; }
    // Per-pixel means and per-sample variances; spp is recorded in the image (the
    // pixel's own sample count, which excludes rejected samples, divides).
    Image image(std::uint32_t width, std::uint32_t height, std::uint32_t spp) const;
    // Samples each pixel has accumulated (rejected ones excluded).
    std::vector<std::uint32_t> pixel_samples() const;

    // Everything it holds: for a checkpoint (render/checkpoint.h) and for the film
    // channels of a partial render (render/film_channels.h).
    struct State {
        std::vector<ExactSum> sum, sum_sq;                   // rgb per pixel
        std::vector<ExactSum> batch_mean_sum, batch_mean_sq; // rgb per pixel: whole batches' means
        std::vector<double> samples;                         // per pixel: whole numbers, exact
        std::vector<std::uint32_t> pixel_batches;            // per pixel: whole batches with samples
        std::uint64_t bad = 0;
        std::uint32_t batches = 0;
    };
    const State& state() const { return state_; }
    // Takes back a state of the same pixel count; throws pathcl::Error when sizes differ.
    void restore(State state);
    // Adds another accumulator's state (other batches of the same render): exact, so the
    // order of merges does not matter. Throws pathcl::Error when sizes differ.
    void merge(const State& other);

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
    // Each estimate is negative where a pixel's sums are lost (ExactSum::poisoned: a
    // radiance past 1.4e14, whose square passes the sums' range).
    double per_sample_relmse_estimate() const;

    // What is wrong with `state` as the film of `pixels` pixels after exactly `batches`
    // whole batches of at most `max_samples` samples per pixel in all, or "" when nothing
    // is: every array of that size, every count within those bounds (bad samples
    // included), every sum a number (not poisoned; squares not negative), a pixel
    // without samples without sums. A state read from a file (a checkpoint, a partial
    // render) is checked so before it makes an image.
    static std::string state_problem(const State& state, std::size_t pixels, std::uint32_t batches,
                                     std::uint64_t max_samples);

private:
    struct Moments {
        double n = 0.0, mean = 0.0, variance = 0.0; // samples, mean, per-sample variance (0 below 2)
    };
    Moments moments(std::size_t pixel, int channel) const;
    void add_to_total(const FilmSum& batch);
    double pixel_channel_estimate(std::size_t i, int c) const;
    // The mean of every pixel's three terms, over the pixels for which pixel_terms(i,
    // terms) returns true; -1 when there are none.
    double mean_of_pixel_terms(const std::function<bool(std::size_t, double*)>& pixel_terms) const;
    void check_sizes(const State& other) const;

    std::uint32_t batch_spp_;
    State state_;
};

} // namespace pathcl
