// The film's host work runs on every core (common/parallel.h): every index is visited
// once, and a film of many chunks gives, bit for bit, what pixel-by-pixel serial
// arithmetic gives, whatever the thread count.
#include <atomic>
#include <cstring>
#include <random>

#include <gtest/gtest.h>

#include "common/parallel.h"
#include "render/film.h"

namespace pathcl::test_film_on_every_core {
namespace {

TEST(ParallelChunks, EveryIndexIsVisitedOnce)
{
    for (std::size_t count :
         {std::size_t(0), std::size_t(1), std::size_t(16384), std::size_t(16385), std::size_t(100003)}) {
        std::vector<std::atomic<int>> visits(count);
        std::atomic<int> calls{0};
        parallel_chunks(count, [&](std::size_t begin, std::size_t end) {
            ASSERT_LE(begin, end);
            ASSERT_LE(end, count);
            ++calls;
            for (std::size_t i = begin; i < end; ++i)
                ++visits[i];
        });
        for (std::size_t i = 0; i < count; ++i)
            ASSERT_EQ(visits[i].load(), 1) << "count " << count << ", index " << i;
        EXPECT_EQ(calls.load() > 1, count > 16384) << "count " << count;
    }
}

constexpr std::size_t kPixels = 50000; // a few chunks of 16384
constexpr int kBatches = 3;

// Batch b's film: random sums, grey (r = g = b) so a pixel's three estimate terms are
// equal; every 7th pixel has no sample in batch 1 (adaptive sampling).
std::vector<FilmPixel> batch_film(int b)
{
    std::mt19937 rng(1234 + b);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::vector<FilmPixel> film(kPixels);
    for (std::size_t i = 0; i < kPixels; ++i) {
        const float n = (b == 1 && i % 7 == 0) ? 0.0f : 16.0f;
        const float s = n * u(rng), q = s * s / 16.0f * (1.0f + u(rng));
        film[i].sum = {s, s, s, n};
        film[i].sum_compensation = {s * 1e-8f, s * 1e-8f, s * 1e-8f, 0.0f};
        film[i].sum_sq = {q, q, q, n};
        film[i].sum_sq_compensation = {0.0f, 0.0f, 0.0f, 0.0f};
    }
    return film;
}

FilmAccumulator whole_film()
{
    FilmAccumulator acc(kPixels, 16);
    for (int b = 0; b < kBatches; ++b) {
        FilmSum sum(kPixels);
        sum.add(batch_film(b), std::vector<pcl_uint>(kPixels, 1u));
        acc.add_batch(sum);
    }
    return acc;
}

struct Results {
    Image image;
    double relmse = 0.0, per_sample = 0.0;
};

Results results_with_threads(int threads)
{
    set_parallel_threads(static_cast<unsigned>(threads));
    const FilmAccumulator acc = whole_film();
    Results r{acc.image(kPixels, 1, 48), acc.relmse_estimate(), acc.per_sample_relmse_estimate()};
    set_parallel_threads(0); // back to one a core
    return r;
}

TEST(FilmOnEveryCore, ImageIsEachPixelsOwnSerialResultBitForBit)
{
    const FilmAccumulator acc = whole_film();
    EXPECT_EQ(acc.bad_samples(), kPixels * kBatches);
    const Image img = acc.image(kPixels, 1, 48);
    std::vector<std::vector<FilmPixel>> films;
    for (int b = 0; b < kBatches; ++b)
        films.push_back(batch_film(b));
    for (std::size_t i = 0; i < kPixels; i += 97) { // one-pixel films take the serial path
        FilmAccumulator one(1, 16);
        for (int b = 0; b < kBatches; ++b) {
            FilmSum sum(1);
            sum.add({films[b][i]}, {0u});
            one.add_batch(sum);
        }
        const Image ref = one.image(1, 1, 48);
        ASSERT_EQ(std::memcmp(&img.rgb[i * 3], ref.rgb.data(), 3 * sizeof(float)), 0) << "pixel " << i;
        ASSERT_EQ(std::memcmp(&img.variance[i * 3], ref.variance.data(), 3 * sizeof(float)), 0) << "pixel " << i;
        ASSERT_EQ(acc.pixel_relmse_estimate(i), one.pixel_relmse_estimate(0)) << "pixel " << i;
    }
}

TEST(FilmOnEveryCore, EstimateIsTheSerialSumInPixelOrder)
{
    const FilmAccumulator acc = whole_film();
    double sum = 0.0;
    std::size_t terms = 0;
    for (std::size_t i = 0; i < kPixels; ++i) {
        const double t = acc.pixel_relmse_estimate(i); // the largest of three equal terms
        if (t < 0.0)
            continue;
        for (int c = 0; c < 3; ++c)
            sum += t;
        terms += 3;
    }
    ASSERT_GT(terms, 0u);
    EXPECT_EQ(acc.relmse_estimate(), sum / static_cast<double>(terms));
}

TEST(FilmOnEveryCore, ResultsDoNotDependOnTheThreadCount)
{
    const Results one = results_with_threads(1), many = results_with_threads(8);
    ASSERT_EQ(one.image.rgb.size(), many.image.rgb.size());
    EXPECT_EQ(std::memcmp(one.image.rgb.data(), many.image.rgb.data(), one.image.rgb.size() * sizeof(float)), 0);
    EXPECT_EQ(
        std::memcmp(one.image.variance.data(), many.image.variance.data(), one.image.variance.size() * sizeof(float)),
        0);
    EXPECT_EQ(one.relmse, many.relmse);
    EXPECT_EQ(one.per_sample, many.per_sample);
    EXPECT_GT(one.relmse, 0.0);
    EXPECT_GT(one.per_sample, 0.0);
}

} // namespace
} // namespace pathcl::test_film_on_every_core
