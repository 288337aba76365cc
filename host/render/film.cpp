#include "render/film.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <unistd.h>

#include "common/error.h"
#include "common/memory_limits.h"
#include "common/parallel.h"

namespace pathcl {

double host_film_bytes(std::size_t pixels, std::size_t devices)
{
    const double total = 12 * sizeof(ExactSum) + sizeof(double) + sizeof(std::uint32_t);
    const double batch = 8 * sizeof(double);
    const double device = sizeof(FilmPixel) + sizeof(pcl_uint);
    return static_cast<double>(pixels) * (total + batch + device * static_cast<double>(devices));
}

void check_host_memory(double needed, double available)
{
    if (available <= 0.0) {
        check_memory_for(needed, "the film");
        return;
    }
    if (needed > available)
        throw Error("the film needs " + gib(needed) + " of host memory, more than this machine's " + gib(available));
}

FilmSum::FilmSum(std::size_t pixels) : sum_(new double[pixels * 4]), sum_sq_(new double[pixels * 4])
{
    parallel_chunks(pixels, [&](std::size_t begin, std::size_t end) {
        std::fill(&sum_[begin * 4], &sum_[end * 4], 0.0);
        std::fill(&sum_sq_[begin * 4], &sum_sq_[end * 4], 0.0);
    });
}

void FilmSum::add(const std::vector<FilmPixel>& film, const std::vector<pcl_uint>& bad_samples)
{
    parallel_chunks(film.size(), [&](std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i) {
            const FilmPixel& f = film[i];
            const float* s = &f.sum.x;
            const float* sc = &f.sum_compensation.x;
            const float* q = &f.sum_sq.x;
            const float* qc = &f.sum_sq_compensation.x;
            for (int c = 0; c < 4; ++c) {
                sum_[i * 4 + c] += static_cast<double>(s[c]) + static_cast<double>(sc[c]);
                sum_sq_[i * 4 + c] += static_cast<double>(q[c]) + static_cast<double>(qc[c]);
            }
        }
    });
    for (pcl_uint n : bad_samples)
        bad_ += n;
}

FilmAccumulator::FilmAccumulator(std::size_t pixels, std::uint32_t batch_spp) : batch_spp_(batch_spp)
{
    state_.sum.resize(pixels * 3);
    state_.sum_sq.resize(pixels * 3);
    state_.batch_mean_sum.resize(pixels * 3);
    state_.batch_mean_sq.resize(pixels * 3);
    state_.samples.assign(pixels, 0.0);
    state_.pixel_batches.assign(pixels, 0);
}

FilmAccumulator::Moments FilmAccumulator::moments(std::size_t i, int c) const
{
    Moments m;
    m.n = state_.samples[i]; // samples actually accumulated (bad ones excluded)
    const double s = state_.sum[i * 3 + c].value(), q = state_.sum_sq[i * 3 + c].value();
    m.mean = m.n > 0.0 ? s / m.n : 0.0;
    if (!(m.n > 1.0))
        return m; // variance 0
    const double variance = (q - s * m.mean) / (m.n - 1.0);
    // A square past the sums' range (ExactSum::poisoned) leaves a spread no figure bounds:
    // +inf, not the 0 that max(0, NaN) would make of it, which claims an exact pixel. A
    // poisoned sum leaves no mean either: NaN.
    if (std::isnan(variance))
        m.variance = std::isnan(s) ? NAN : INFINITY;
    else
        m.variance = std::max(0.0, variance);
    return m;
}

Image FilmAccumulator::image(std::uint32_t width, std::uint32_t height, std::uint32_t spp) const
{
    const std::size_t pixels = static_cast<std::size_t>(width) * height;
    if (pixels != state_.samples.size())
        throw Error("internal error: the film does not match the image size");
    Image img;
    img.width = width;
    img.height = height;
    img.spp = spp;
    img.rgb.resize(pixels * 3);
    img.variance.resize(pixels * 3);
    parallel_chunks(pixels, [&](std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i)
            for (int c = 0; c < 3; ++c) {
                const Moments m = moments(i, c);
                img.rgb[i * 3 + c] = static_cast<float>(m.mean);
                img.variance[i * 3 + c] = static_cast<float>(m.variance);
            }
    });
    return img;
}

void FilmAccumulator::add_to_total(const FilmSum& batch)
{
    parallel_chunks(state_.samples.size(), [&](std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i) {
            for (int c = 0; c < 3; ++c) {
                state_.sum[i * 3 + c].add(batch.sum_[i * 4 + c]);
                state_.sum_sq[i * 3 + c].add(batch.sum_sq_[i * 4 + c]);
            }
            state_.samples[i] += batch.sum_[i * 4 + 3]; // whole numbers: exact in any order
        }
    });
    state_.bad += batch.bad_;
}

void FilmAccumulator::add_batch(const FilmSum& batch)
{
    add_to_total(batch);
    parallel_chunks(state_.pixel_batches.size(), [&](std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i) {
            double n = batch.sum_[i * 4 + 3];
            if (!(n > 0.0))
                continue; // the pixel took no sample in this batch (adaptive sampling)
            ++state_.pixel_batches[i];
            for (int c = 0; c < 3; ++c) {
                double m = batch.sum_[i * 4 + c] / n;
                state_.batch_mean_sum[i * 3 + c].add(m);
                state_.batch_mean_sq[i * 3 + c].add(m * m);
            }
        }
    });
    ++state_.batches;
}

void FilmAccumulator::add_partial_batch(const FilmSum& batch)
{
    add_to_total(batch);
}

void FilmAccumulator::check_sizes(const State& s) const
{
    const std::size_t pixels = state_.samples.size();
    if (s.sum.size() != pixels * 3 || s.sum_sq.size() != pixels * 3 || s.batch_mean_sum.size() != pixels * 3 ||
        s.batch_mean_sq.size() != pixels * 3 || s.samples.size() != pixels || s.pixel_batches.size() != pixels)
        throw Error("the film state does not match the image size");
}

std::string FilmAccumulator::state_problem(const State& s, std::size_t pixels, std::uint32_t batches,
                                           std::uint64_t max_samples)
{
    if (s.sum.size() != pixels * 3 || s.sum_sq.size() != pixels * 3 || s.batch_mean_sum.size() != pixels * 3 ||
        s.batch_mean_sq.size() != pixels * 3 || s.samples.size() != pixels || s.pixel_batches.size() != pixels)
        return "its film does not have the image's " + std::to_string(pixels) + " pixels";
    if (s.batches != batches)
        return "its film holds " + std::to_string(s.batches) + " whole batches, not the " + std::to_string(batches) +
               " its sample counts make";
    if (s.bad > max_samples * pixels)
        return "its film counts " + std::to_string(s.bad) + " bad samples, more than it has samples";
    for (std::size_t i = 0; i < pixels; ++i) {
        const double n = s.samples[i];
        const std::string pixel = "pixel " + std::to_string(i) + " of its film ";
        if (!(n >= 0.0 && n <= static_cast<double>(max_samples) && n == std::floor(n)))
            return pixel + "has a sample count that is not a whole number from 0 to " + std::to_string(max_samples);
        if (s.pixel_batches[i] > batches)
            return pixel + "has samples in more batches than the film holds";
        for (std::size_t k = i * 3; k < i * 3 + 3; ++k) {
            const ExactSum* sums[4] = {&s.sum[k], &s.sum_sq[k], &s.batch_mean_sum[k], &s.batch_mean_sq[k]};
            for (const ExactSum* e : sums) {
                // A render's sums stay within +-2^126 (exact_sum.h): the top limb within +-2^62.
                const auto top = static_cast<std::int64_t>(e->limb[2]);
                if (e->poisoned() || top > (std::int64_t(1) << 62) || top < -(std::int64_t(1) << 62) ||
                    (n == 0.0 && !(*e == ExactSum{})))
                    return pixel + "holds a sum that is not a number, out of range, or without samples";
            }
            if (s.sum_sq[k].value() < 0.0 || s.batch_mean_sq[k].value() < 0.0)
                return pixel + "holds a negative sum of squares";
        }
    }
    return "";
}

void FilmAccumulator::restore(State s)
{
    check_sizes(s);
    state_ = std::move(s);
}

void FilmAccumulator::merge(const State& s)
{
    check_sizes(s);
    parallel_chunks(state_.sum.size(), [&](std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i) {
            state_.sum[i].add(s.sum[i]);
            state_.sum_sq[i].add(s.sum_sq[i]);
            state_.batch_mean_sum[i].add(s.batch_mean_sum[i]);
            state_.batch_mean_sq[i].add(s.batch_mean_sq[i]);
        }
    });
    for (std::size_t i = 0; i < state_.samples.size(); ++i) {
        state_.samples[i] += s.samples[i];
        state_.pixel_batches[i] += s.pixel_batches[i];
    }
    state_.bad += s.bad;
    state_.batches += s.batches;
}

std::vector<std::uint32_t> FilmAccumulator::pixel_samples() const
{
    std::vector<std::uint32_t> n(state_.samples.size());
    for (std::size_t i = 0; i < n.size(); ++i)
        n[i] = static_cast<std::uint32_t>(state_.samples[i]);
    return n;
}

double FilmAccumulator::pixel_channel_estimate(std::size_t i, int c) const
{
    if (state_.batch_mean_sum[i * 3 + c].poisoned() || state_.batch_mean_sq[i * 3 + c].poisoned())
        return NAN; // a batch mean past ExactSum's range (its square past 2e28): no spread to tell
    double k = state_.pixel_batches[i];
    double s = state_.batch_mean_sum[i * 3 + c].value(), q = state_.batch_mean_sq[i * 3 + c].value();
    double spread = std::max(0.0, (q - s * s / k) / (k - 1.0)); // variance of one batch mean
    // The pixel's mean as moments() has it, without the sum of squares this does not need
    // (it runs after every batch; each exact value costs a conversion).
    const double n = state_.samples[i];
    const double mean = n > 0.0 ? state_.sum[i * 3 + c].value() / n : 0.0;
    return spread * batch_spp_ / n / (mean * mean + kRelMseEpsilon);
}

double FilmAccumulator::pixel_relmse_estimate(std::size_t i) const
{
    if (state_.pixel_batches[i] < 2)
        return -1.0;
    double worst = 0.0;
    for (int c = 0; c < 3; ++c) {
        const double e = pixel_channel_estimate(i, c);
        if (!std::isfinite(e))
            return -1.0; // a channel lost (std::max would drop its nan)
        worst = std::max(worst, e);
    }
    return worst;
}

double FilmAccumulator::mean_of_pixel_terms(const std::function<bool(std::size_t, double*)>& pixel_terms) const
{
    // The terms are computed on every core, then summed in pixel and channel order: the
    // same double, bit for bit, as one serial loop.
    const std::size_t pixels = state_.samples.size();
    std::vector<double> term(pixels * 3);
    std::vector<unsigned char> counted(pixels);
    parallel_chunks(pixels, [&](std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i)
            counted[i] = pixel_terms(i, &term[i * 3]) ? 1 : 0;
    });
    double sum = 0.0;
    std::size_t terms = 0;
    for (std::size_t i = 0; i < pixels; ++i) {
        if (!counted[i])
            continue;
        for (int c = 0; c < 3; ++c)
            sum += term[i * 3 + c];
        terms += 3;
    }
    // Not finite where a pixel's sums are lost (poisoned ExactSums: a square past 2e28, a
    // radiance past 1.4e14): no estimate then, rather than nan.
    return terms > 0 && std::isfinite(sum) ? sum / static_cast<double>(terms) : -1.0;
}

double FilmAccumulator::relmse_estimate() const
{
    if (state_.batches < 2)
        return -1.0;
    return mean_of_pixel_terms([this](std::size_t i, double* t) {
        if (state_.pixel_batches[i] < 2)
            return false;
        for (int c = 0; c < 3; ++c)
            t[c] = pixel_channel_estimate(i, c);
        return true;
    });
}

double FilmAccumulator::per_sample_relmse_estimate() const
{
    return mean_of_pixel_terms([this](std::size_t i, double* t) {
        if (!(state_.samples[i] > 1.0))
            return false;
        for (int c = 0; c < 3; ++c) {
            const Moments m = moments(i, c);
            const bool lost = state_.sum[i * 3 + c].poisoned() || state_.sum_sq[i * 3 + c].poisoned();
            t[c] = lost ? NAN : m.variance / m.n / (m.mean * m.mean + kRelMseEpsilon);
        }
        return true;
    });
}

} // namespace pathcl
