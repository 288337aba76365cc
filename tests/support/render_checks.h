// Checks of rendered images that several device tests share: the mean of one channel over
// every pixel with its standard error, and "every light-sampling strategy renders the
// same image as BSDF sampling alone".
#pragma once

#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <iostream>
#include <string>

#include <gtest/gtest.h>

#include "image/image_compare.h"
#include "render/renderer.h"

namespace pathcl::test {

struct ChannelMean {
    double mean = 0.0, stderr_ = 0.0; // stderr_: from the per-sample variance (independent sampler)
    std::uint64_t bad = 0;            // the render's rejected NaN/Inf samples
};

// The mean of channel `channel` (0 red, 1 green, 2 blue) over every pixel of a render.
inline ChannelMean channel_mean(const RenderResult& r, int channel)
{
    ChannelMean m;
    double var = 0.0;
    std::size_t n = static_cast<std::size_t>(r.image.width) * r.image.height;
    for (std::size_t i = 0; i < n; ++i) {
        m.mean += r.image.rgb[i * 3 + static_cast<std::size_t>(channel)];
        var += r.image.variance[i * 3 + static_cast<std::size_t>(channel)] / static_cast<double>(r.image.spp);
    }
    m.mean /= static_cast<double>(n);
    m.stderr_ = std::sqrt(var) / static_cast<double>(n);
    m.bad = r.stats.bad_samples;
    return m;
}

// Light sampling and its combinations must converge to what BSDF sampling alone finds.
// Expects two images to agree statistically, each judged by its own variance (not
// pooled: two estimators or two programs share the mean, not the variance).
inline void expect_same_mean(const Image& a, const Image& b, const std::string& what = "")
{
    CompareOptions co;
    co.pooled_variance = false;
    CompareReport cmp = compare_images(a, b, co);
    std::cout << what << (what.empty() ? "" : "\n") << cmp.summary();
    EXPECT_TRUE(cmp.passed) << what << "\n" << cmp.summary();
}

// Renders `scene` with BSDF sampling at o.spp and o.seed as the reference, then with each
// strategy at `spp` samples and seed seed_base + the strategy's value, and expects every
// image to match the reference statistically (different estimators share the mean only,
// so variances are not pooled) with no rejected samples.
inline void expect_same_image_by_strategies(const Scene& scene, RenderOptions o,
                                            std::initializer_list<Strategy> strategies, std::uint32_t spp,
                                            std::uint32_t seed_base)
{
    o.strategy = Strategy::Bsdf;
    RenderResult reference = render(scene, o);
    EXPECT_EQ(reference.stats.bad_samples, 0u);
    for (Strategy strategy : strategies) {
        o.strategy = strategy;
        o.spp = spp;
        o.seed = seed_base + static_cast<std::uint32_t>(strategy);
        RenderResult r = render(scene, o);
        EXPECT_EQ(r.stats.bad_samples, 0u);
        expect_same_mean(r.image, reference.image, std::string("strategy ") + strategy_name(strategy));
    }
}

} // namespace pathcl::test
