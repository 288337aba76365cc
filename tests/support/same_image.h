// The bit-for-bit image check of the reproducibility tests (resume, several devices,
// merged sample ranges): means, variances, sample counts, metadata and film part.
#pragma once

#include <cstring>
#include <string>

#include <gtest/gtest.h>

#include "image/image.h"

namespace pathcl::test {

inline void expect_same_image(const Image& a, const Image& b, const std::string& what = "")
{
    ASSERT_EQ(a.rgb.size(), b.rgb.size()) << what;
    EXPECT_EQ(a.spp, b.spp) << what;
    EXPECT_EQ(std::memcmp(a.rgb.data(), b.rgb.data(), a.rgb.size() * sizeof(float)), 0) << what << ": radiance differs";
    EXPECT_EQ(std::memcmp(a.variance.data(), b.variance.data(), a.variance.size() * sizeof(float)), 0)
        << what << ": variance differs";
    EXPECT_EQ(a.samples, b.samples) << what << ": per-pixel samples differ";
    EXPECT_EQ(a.metadata, b.metadata) << what; // stop, seed, sampler, batches, the error estimate
    EXPECT_EQ(a.film_channels, b.film_channels) << what;
    EXPECT_TRUE(a.film == b.film) << what << ": film parts differ";
}

} // namespace pathcl::test
