// How rows are dealt to devices (render/device_bands.h): bands cover the image once, in
// order, with boundaries on multiples of kBandRows, in proportion to the weights.
#include <cstdint>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "render/device_bands.h"

namespace pathcl::test_device_bands {
namespace {

void expect_valid(const std::vector<std::uint32_t>& b, std::uint32_t height, std::size_t bands)
{
    ASSERT_EQ(b.size(), bands + 1);
    EXPECT_EQ(b.front(), 0u);
    EXPECT_EQ(b.back(), height);
    for (std::size_t i = 1; i < b.size(); ++i) {
        EXPECT_LE(b[i - 1], b[i]) << "band " << i - 1;
        if (i + 1 < b.size() && b[i] < height) {
            EXPECT_EQ(b[i] % kBandRows, 0u) << "boundary " << i;
        }
    }
}

TEST(DeviceBands, OneDeviceTakesEveryRow)
{
    EXPECT_EQ(band_bounds(37, 1, {1.0}), (std::vector<std::uint32_t>{0, 37}));
}

TEST(DeviceBands, BandsFollowTheWeightsOnMultiplesOfTheBandRows)
{
    EXPECT_EQ(band_bounds(64, 2, {1.0, 1.0}), (std::vector<std::uint32_t>{0, 32, 64}));
    EXPECT_EQ(band_bounds(64, 2, {1.0, 3.0}), (std::vector<std::uint32_t>{0, 16, 64}));
    EXPECT_EQ(band_bounds(100, 3, {1.0, 1.0, 2.0}), (std::vector<std::uint32_t>{0, 24, 48, 100}));
    for (std::uint32_t h : {1u, 7u, 8u, 9u, 33u, 1080u})
        for (const std::vector<double>& w : {std::vector<double>{1, 1}, {5, 1, 1}, {0, 1}, {1, 0, 0, 2}})
            expect_valid(band_bounds(h, w.size(), w), h, w.size());
}

TEST(DeviceBands, BadWeightsCountAsEqual)
{
    const double nan = std::numeric_limits<double>::quiet_NaN();
    EXPECT_EQ(band_bounds(64, 2, {nan, 1.0}), band_bounds(64, 2, {1.0, 1.0}));
    EXPECT_EQ(band_bounds(64, 2, {-1.0, 2.0}), band_bounds(64, 2, {1.0, 1.0}));
    EXPECT_EQ(band_bounds(64, 2, {0.0, 0.0}), band_bounds(64, 2, {1.0, 1.0}));
}

TEST(DeviceBands, NoSharesGiveOneEqualBandPerDevice)
{
    // A render without --device-shares passes no weights. Broken variant seen to fail (the
    // bands counted from the weights): one band for two devices, so the renderer read the
    // second device's end past the list (a garbage row count: clEnqueueWriteBuffer -30 on
    // resume in fresh CI runs).
    EXPECT_EQ(band_bounds(64, 2, {}), (std::vector<std::uint32_t>{0, 32, 64}));
    EXPECT_EQ(band_bounds(100, 3, {}), band_bounds(100, 3, {1.0, 1.0, 1.0}));
    EXPECT_EQ(band_bounds(64, 2, {1.0, 1.0, 1.0}), band_bounds(64, 2, {1.0, 1.0})) << "weights not one per band";
    expect_valid(band_bounds(37, 4, {}), 37, 4);
}

TEST(DeviceBands, AZeroWeightGetsAnEmptyBand)
{
    EXPECT_EQ(band_bounds(64, 2, {0.0, 1.0}), (std::vector<std::uint32_t>{0, 0, 64}));
}

} // namespace
} // namespace pathcl::test_device_bands
