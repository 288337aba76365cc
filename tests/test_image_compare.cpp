// The statistical comparator itself: it must accept two independent estimates of the
// same image and reject a small bias, so the render tests that rely on it can fail.
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "image/image_compare.h"

namespace pathcl::test_image_compare {
namespace {

// An image whose pixel means are the average of spp normal samples around `truth`.
Image synthetic(std::uint32_t w, std::uint32_t h, std::uint32_t spp, double bias, std::uint32_t seed)
{
    std::mt19937 rng(seed);
    Image img;
    img.width = w;
    img.height = h;
    img.spp = spp;
    for (std::uint32_t i = 0; i < w * h * 3; ++i) {
        double truth = 0.2 + 0.6 * (i % 97) / 97.0, sigma = 0.5 * truth;
        std::normal_distribution<double> g(truth * (1.0 + bias), sigma);
        double s = 0.0, s2 = 0.0;
        for (std::uint32_t k = 0; k < spp; ++k) {
            double x = g(rng);
            s += x;
            s2 += x * x;
        }
        double mean = s / spp;
        img.rgb.push_back(static_cast<float>(mean));
        img.variance.push_back(static_cast<float>((s2 - s * mean) / (spp - 1)));
    }
    return img;
}

TEST(ImageCompare, SidakThresholdMatchesKnownValues)
{
    EXPECT_NEAR(sidak_z_threshold(0.05, 1), 1.95996, 1e-4);
    // 1 - (1 - 0.01)^(1/1000) = 1.00503e-5 two-sided -> z = 4.4172
    EXPECT_NEAR(sidak_z_threshold(0.01, 1000), 4.4172, 2e-3);
}

TEST(ImageCompare, IndependentEstimatesOfTheSameImagePass)
{
    for (std::uint32_t seed = 0; seed < 5; ++seed) {
        CompareReport r = compare_images(synthetic(48, 48, 32, 0.0, seed), synthetic(48, 48, 256, 0.0, 100 + seed));
        EXPECT_TRUE(r.passed) << r.summary();
    }
}

TEST(ImageCompare, TwoPercentBiasFails)
{
    CompareReport r = compare_images(synthetic(48, 48, 32, 0.02, 1), synthetic(48, 48, 256, 0.0, 2));
    EXPECT_FALSE(r.passed) << r.summary();
}

TEST(ImageCompare, OneWrongPixelOutOfFewFails)
{
    Image a = synthetic(8, 8, 64, 0.0, 3), b = synthetic(8, 8, 64, 0.0, 4);
    a.rgb[27] *= 3.0f; // 1 of 192 tests is within the 1% tolerance, but the image mean moves
    a.rgb[28] *= 3.0f;
    a.rgb[29] *= 3.0f;
    EXPECT_FALSE(compare_images(a, b).passed);
}

TEST(ImageCompare, RmseIsTheRootMeanSquarePixelDifferencePerChannel)
{
    // Exact (1e-12): two pixels, differences (0.3, 0, -1) and (0.4, 0, 1).
    Image a, b;
    a.width = 2;
    a.height = 1;
    a.spp = 1;
    a.rgb = {1.3f, 0.5f, 0.0f, 2.4f, 0.5f, 3.0f};
    a.variance.assign(6, 0.0f);
    b = a;
    b.rgb = {1.0f, 0.5f, 1.0f, 2.0f, 0.5f, 2.0f};
    CompareReport r = compare_images(a, b);
    auto d = [](float x, float y) { return static_cast<double>(x) - static_cast<double>(y); };
    double r0 = std::sqrt((d(1.3f, 1.0f) * d(1.3f, 1.0f) + d(2.4f, 2.0f) * d(2.4f, 2.0f)) / 2.0);
    EXPECT_NEAR(r.rmse[0], r0, 1e-12);
    EXPECT_EQ(r.rmse[1], 0.0);
    EXPECT_NEAR(r.rmse[2], 1.0, 1e-12);
    EXPECT_NEAR(r.rmse_all, std::sqrt((2.0 * r0 * r0 + 2.0) / 6.0), 1e-12);
}

TEST(ImageCompare, SizeMismatchThrows)
{
    EXPECT_THROW(compare_images(synthetic(4, 4, 8, 0, 1), synthetic(4, 5, 8, 0, 1)), std::exception);
}

TEST(ImageCompare, BitwiseFindsEveryDifferenceDownToOneUlpAndTheSampleCount)
{
    Image a = synthetic(6, 5, 8, 0, 1), b = a;
    EXPECT_TRUE(compare_bitwise(a, b).identical());
    EXPECT_EQ(compare_bitwise(a, b).values, 6u * 5u * 6u);
    b.variance[40] = std::nextafter(b.variance[40], 1.0f); // one ulp in one variance value
    BitwiseReport r = compare_bitwise(a, b);
    EXPECT_FALSE(r.identical());
    EXPECT_EQ(r.differing, 1u);
    EXPECT_EQ(r.first_pixel, 40u / 3u);
    b = a;
    b.rgb[0] = -0.0f * b.rgb[0]; // a sign bit alone
    a.rgb[0] = 0.0f;
    EXPECT_EQ(compare_bitwise(a, b).differing, 1u);
    b = a;
    b.spp = a.spp + 1;
    EXPECT_FALSE(compare_bitwise(a, b).identical());
    EXPECT_THROW(compare_bitwise(a, synthetic(6, 4, 8, 0, 1)), std::exception);
}

} // namespace
} // namespace pathcl::test_image_compare
