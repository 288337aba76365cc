// The exact arithmetic under the samplers of kernels/sample/, through the real kernel
// code: the Halton digit code (exact radical inverses; scrambling that keeps the digit
// strata), Sobol' dimension 1 against its generator matrix, and the warp's sine and cosine
// (within 1.5 ulps). Each property test names,
// beside it, the deliberately broken variant that was seen to fail it (checked once, by
// hand).
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <numbers>
#include <random>
#include <set>
#include <vector>

#include <gtest/gtest.h>

#include "sample/dimensions.h"
#include "sampling/samplers.h"
#include "support/device_fixture.h"
#include "support/sampler_points.h"
#include "types.h"

namespace pathcl::test_sampler_halton {
namespace {

using test::one_per_cell;
using test::one_per_stratum_1d;
using test::pixel_range;
using test::points;
using test::sampler_program;

// ---------------------------------------------------------------------------------------
// Halton digits

// The kernel's radical inverses of points 0..n-1 in `base` (test_radical_inverse): the
// float values and the digit prefixes digits / scale they come from.
struct RadicalInverses {
    std::vector<float> value;
    std::vector<cl_ulong> digits, scale;
};

RadicalInverses radical_inverses(std::uint32_t base, std::size_t n, bool scramble, std::uint32_t seed)
{
    ClDevice& dev = test::test_device();
    cl::Buffer out(dev.context, CL_MEM_WRITE_ONLY, n * sizeof(float));
    cl::Buffer digits(dev.context, CL_MEM_WRITE_ONLY, n * sizeof(cl_ulong));
    cl::Buffer scale(dev.context, CL_MEM_WRITE_ONLY, n * sizeof(cl_ulong));
    cl::Kernel k(sampler_program(), "test_radical_inverse");
    set_kernel_args(k, static_cast<cl_uint>(base), static_cast<cl_uint>(scramble), static_cast<cl_uint>(seed), out,
                    digits, scale);
    dev.queue.enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(n));
    RadicalInverses r{std::vector<float>(n), std::vector<cl_ulong>(n), std::vector<cl_ulong>(n)};
    dev.queue.enqueueReadBuffer(out, CL_TRUE, 0, n * sizeof(float), r.value.data());
    dev.queue.enqueueReadBuffer(digits, CL_TRUE, 0, n * sizeof(cl_ulong), r.digits.data());
    dev.queue.enqueueReadBuffer(scale, CL_TRUE, 0, n * sizeof(cl_ulong), r.scale.data());
    return r;
}

TEST(Samplers, HaltonRadicalInversesOfTheFirstPointsAreExact)
{
    // The unscrambled digit code gives the exact radical inverse (as a rational, and as
    // the float nearest to it) for the first 1000 indices in bases 2, 3, 5, 7 and 1619.
    // Broken variant seen to fail: the digits appended most significant first.
    const std::size_t n = 1000;
    for (std::uint32_t base : {2u, 3u, 5u, 7u, 1619u}) {
        RadicalInverses ri = radical_inverses(base, n, false, 0);
        const std::vector<float>& v = ri.value;
        const std::vector<cl_ulong>&d = ri.digits, &s = ri.scale;
        for (std::uint64_t i = 0; i < n; ++i) {
            // Reference: phi_b(i) = sum_k d_k b^-(k+1) as r / b^K.
            std::uint64_t r = 0, bk = 1;
            for (std::uint64_t a = i; a > 0; a /= base) {
                r = r * base + a % base;
                bk *= base;
            }
            ASSERT_EQ(d[i], r) << "base " << base << " index " << i;
            ASSERT_EQ(s[i], bk) << "base " << base << " index " << i;
            ASSERT_EQ(v[i], static_cast<float>(static_cast<double>(r) / static_cast<double>(bk)))
                << "base " << base << " index " << i;
        }
        if (base == 2) { // the textbook values
            EXPECT_EQ(v[1], 0.5f);
            EXPECT_EQ(v[2], 0.25f);
            EXPECT_EQ(v[3], 0.75f);
            EXPECT_EQ(v[6], 0.375f);
        }
        if (base == 3) {
            EXPECT_EQ(v[1], 1.0f / 3.0f);
            EXPECT_EQ(v[4], 4.0f / 9.0f);
        }
    }
}

TEST(Samplers, ScrambledHaltonKeepsTheDigitStrata)
{
    // Nested scrambling permutes digits within each node of the digit tree, so the first
    // n = b^k points of a scrambled radical inverse have k-digit prefixes that are a
    // permutation of 0 .. n-1 (exact, on the integer digits), and each value lies in its
    // prefix's interval [d / n, (d + 1) / n) (exact). Through the Halton sampler itself:
    // the first b^k values of dims 0..3 (bases 2, 3, 5, 7) hold one point per interval
    // of length b^-k, and the (base 2, base 3) pair of dims 0, 1 one point per
    // 2^-a x 3^-b box of the first 2^a 3^b points. Broken variants seen to fail: a digit
    // map d -> (m d + o) mod b whose multiplier m may be 0; a Kensler permutation seeded
    // with the digit's own value (neither is a permutation).
    for (std::uint32_t base : {2u, 3u, 5u, 13u}) {
        std::uint32_t k = base == 2 ? 10 : base == 3 ? 6 : base == 5 ? 4 : 2;
        std::size_t n = 1;
        for (std::uint32_t i = 0; i < k; ++i)
            n *= base;
        RadicalInverses ri = radical_inverses(base, n, true, 0x1234567);
        const std::vector<float>& v = ri.value;
        const std::vector<cl_ulong>&d = ri.digits, &s = ri.scale;
        std::set<std::uint64_t> prefixes;
        for (std::size_t i = 0; i < n; ++i) {
            ASSERT_EQ(s[i], n) << "base " << base;
            ASSERT_LT(d[i], s[i]);
            prefixes.insert(d[i]);
            double x = static_cast<double>(v[i]) * static_cast<double>(n); // exact
            ASSERT_TRUE(x >= static_cast<double>(d[i]) && x < static_cast<double>(d[i] + 1))
                << "base " << base << " point " << i << " value " << v[i] << " prefix " << d[i];
        }
        EXPECT_EQ(prefixes.size(), n) << "base " << base;
    }
    const std::uint32_t bases[4] = {2, 3, 5, 7}, ks[4] = {8, 5, 3, 3};
    for (std::uint32_t dim = 0; dim < 4; ++dim) {
        std::uint32_t n = 1;
        for (std::uint32_t i = 0; i < ks[dim]; ++i)
            n *= bases[dim];
        std::vector<glm::vec2> p = points(SamplerType::Halton, n, pixel_range(40, 4), dim, /*one_d=*/true);
        for (std::size_t px = 0; px < 4; ++px)
            EXPECT_TRUE(one_per_stratum_1d(&p[px * n], n, 0)) << "dim " << dim;
    }
    for (std::uint32_t a : {1u, 3u})
        for (std::uint32_t b : {1u, 2u}) {
            std::uint32_t cols = 1u << a, rows = b == 1 ? 3u : 9u, n = cols * rows;
            std::vector<glm::vec2> p = points(SamplerType::Halton, n, pixel_range(40, 4), DIM_PIXEL);
            for (std::size_t px = 0; px < 4; ++px)
                EXPECT_TRUE(one_per_cell(&p[px * n], n, cols, rows)) << cols << "x" << rows;
        }
}

// ---------------------------------------------------------------------------------------
// The warp's sine and cosine

// Error of float f against the exact value in units of the float spacing at the exact
// value (denormal spacing at least).
double ulps(float f, long double exact)
{
    long double spacing = std::ldexp(1.0L, std::max(std::ilogb(static_cast<float>(exact)), -126) - 23);
    if (exact == 0.0L)
        spacing = std::ldexp(1.0L, -149);
    return static_cast<double>(std::fabs(static_cast<long double>(f) - exact) / spacing);
}

struct SinCosErrors {
    double sin_ulps = 0.0, cos_ulps = 0.0;
};

// Worst errors of the kernels' sine and cosine (or the built-in's) over `in`.
SinCosErrors sin_cos_errors(const std::vector<float>& in, bool turns, bool builtin)
{
    ClDevice& dev = test::test_device();
    std::size_t n = in.size();
    cl::Buffer bin(dev.context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, n * sizeof(float),
                   const_cast<float*>(in.data()));
    cl::Buffer out(dev.context, CL_MEM_WRITE_ONLY, n * sizeof(cl_float2));
    cl::Buffer ref(dev.context, CL_MEM_WRITE_ONLY, n * sizeof(cl_float2));
    cl::Kernel k(sampler_program(), "test_sin_cos");
    set_kernel_args(k, bin, static_cast<cl_uint>(turns), out, ref);
    dev.queue.enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(n));
    std::vector<cl_float2> v(n);
    dev.queue.enqueueReadBuffer(builtin ? ref : out, CL_TRUE, 0, n * sizeof(cl_float2), v.data());
    SinCosErrors e;
    const long double two_pi = 2.0L * std::numbers::pi_v<long double>;
    for (std::size_t i = 0; i < n; ++i) {
        long double x = turns ? two_pi * static_cast<long double>(in[i]) : static_cast<long double>(in[i]);
        // Exact zeros and ones at multiples of a quarter turn (long double's pi is not).
        long double s = std::sin(x), c = std::cos(x);
        if (turns && std::rint(4.0f * in[i]) == 4.0f * in[i]) {
            int q = static_cast<int>(std::rint(4.0f * in[i])) & 3;
            s = q == 1 ? 1.0L : q == 3 ? -1.0L : 0.0L;
            c = q == 0 ? 1.0L : q == 2 ? -1.0L : 0.0L;
        }
        e.sin_ulps = std::max(e.sin_ulps, ulps(v[i].s[0], s));
        e.cos_ulps = std::max(e.cos_ulps, ulps(v[i].s[1], c));
    }
    return e;
}

TEST(Samplers, WarpSineAndCosineAreWithinOneAndAHalfUlps)
{
    // The polynomials on [-pi/4, pi/4] and the exact quarter-turn reduction, against long
    // double sin and cos: the polynomials within 1 ulp of the exact value, with the
    // reduction within 1.5 (measured worst: 0.84 and 1.31), including next to the zeros
    // of sin and cos, where a rounded argument 2 pi t is far off in relative terms.
    // Broken variants seen to fail: the built-in sincos(2 pi t) (a quarter turn gives
    // cos = -4.4e-8 instead of 0; checked here to fail); the reduction without the
    // a_lo correction (1.93 ulps); the cosine without its x^8 term.
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> small(-std::numbers::pi_v<float> / 4.0f, std::numbers::pi_v<float> / 4.0f);
    std::uniform_real_distribution<float> turn(-2.0f, 2.0f);
    std::vector<float> a = {
        0.0f, -0.0f, 1e-30f, -1e-30f, 1e-6f, std::numbers::pi_v<float> / 4.0f, -std::numbers::pi_v<float> / 4.0f};
    std::vector<float> t = {0.0f, 0.125f, 0.25f, 0.375f, 0.5f, 0.75f, 1.0f, -0.25f, -0.5f, 0.999999940f, 1e-20f};
    for (int i = 0; i < 200000; ++i) {
        a.push_back(small(rng));
        t.push_back(turn(rng));
    }
    // Next to every quarter turn of [0, 1], a few ulps either side.
    for (float q : {0.25f, 0.5f, 0.75f, 1.0f}) {
        float up = q, down = q;
        for (int i = 0; i < 8; ++i) {
            t.push_back(up = std::nextafter(up, 2.0f));
            t.push_back(down = std::nextafter(down, 0.0f));
        }
    }
    SinCosErrors small_err = sin_cos_errors(a, false, false), turn_err = sin_cos_errors(t, true, false);
    EXPECT_LE(small_err.sin_ulps, 1.0);
    EXPECT_LE(small_err.cos_ulps, 1.0);
    EXPECT_LE(turn_err.sin_ulps, 1.5);
    EXPECT_LE(turn_err.cos_ulps, 1.5);
    SinCosErrors builtin = sin_cos_errors(t, true, true);
    EXPECT_GT(std::max(builtin.sin_ulps, builtin.cos_ulps), 1e6) << "the built-in on a rounded 2 pi t should fail";
    std::printf("worst errors in ulps: small sin %.2f cos %.2f, turns sin %.2f cos %.2f, built-in %.3g %.3g\n",
                small_err.sin_ulps, small_err.cos_ulps, turn_err.sin_ulps, turn_err.cos_ulps, builtin.sin_ulps,
                builtin.cos_ulps);
}

TEST(Samplers, SobolDimensionOneMatchesItsGeneratorMatrix)
{
    // The kernel's closed form against the definition: index bit k adds direction number
    // v_k (v_0 = 2^31, v_{k+1} = v_k ^ (v_k >> 1): the rows of Pascal's triangle mod 2),
    // read back in reversed bit order. Every index below 2^20, then random 32-bit ones.
    // Broken variant seen to fail: the 4-bit shift step left out.
    auto definition = [](std::uint32_t a) {
        std::uint32_t v = 1u << 31, r = 0;
        for (; a != 0; a >>= 1, v ^= v >> 1)
            if (a & 1u)
                r ^= v;
        std::uint32_t reversed = 0;
        for (int b = 0; b < 32; ++b)
            reversed |= ((r >> b) & 1u) << (31 - b);
        return reversed;
    };
    std::vector<cl_uint> in(1u << 20);
    for (std::uint32_t i = 0; i < in.size(); ++i)
        in[i] = i;
    std::mt19937 rng(5);
    for (int i = 0; i < 100000; ++i)
        in.push_back(static_cast<cl_uint>(rng()));
    ClDevice& dev = test::test_device();
    cl::Buffer bin = test::upload(in);
    cl::Buffer out(dev.context, CL_MEM_WRITE_ONLY, in.size() * sizeof(cl_uint));
    cl::Kernel k(sampler_program(), "test_sobol_dimension1");
    set_kernel_args(k, bin, out);
    dev.queue.enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(in.size()));
    std::vector<cl_uint> got = test::read_back<cl_uint>(out, in.size());
    std::size_t wrong = 0;
    for (std::size_t i = 0; i < in.size(); ++i)
        wrong += got[i] != definition(in[i]);
    EXPECT_EQ(wrong, 0u);
}

} // namespace
} // namespace pathcl::test_sampler_halton
