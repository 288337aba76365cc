// The seven samplers of kernels/samplers.cl, through the real kernel code (the kernel
// sampler_points the visualizer uses, and the Halton digit code): the stratification
// each one promises, bit-identical values whatever the order of computation, and the
// convergence order of a smooth 2D integral. Each property test names, beside it, the
// deliberately broken variant that was seen to fail it (checked once, by hand).
#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>
#include <random>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "sampling/samplers.h"
#include "sample/dimensions.h"
#include "types.h"
#include "support/device_fixture.h"

namespace pathcl {
namespace {

// The real kernel sources plus tests/kernels/sampler_test_kernels.cl, built once.
const cl::Program& sampler_program()
{
    static cl::Program p = test::build_test_program("sampler_test_kernels.cl");
    return p;
}

// Dimension pairs the tests look at: the film position, the lens, and decisions of the
// first and of a deep bounce (1D decisions at odd starts too).
const std::vector<std::uint32_t> kDims = {DIM_PIXEL, DIM_LENS, DIM_PATH_START + 1, DIM_PATH_START + 5 * DIMS_PER_BOUNCE + 5};

std::vector<std::uint32_t> pixel_range(std::uint32_t first, std::uint32_t n)
{
    std::vector<std::uint32_t> v(n);
    std::iota(v.begin(), v.end(), first);
    return v;
}

// Points of `pixels`, spp each, for the 2D decision at dim (or two 1D decisions at dim
// and dim + 2 when one_d).
std::vector<glm::vec2> points(SamplerType sampler, std::uint32_t spp, const std::vector<std::uint32_t>& pixels,
                              std::uint32_t dim, bool one_d = false, std::uint32_t seed = 11)
{
    SamplerPointsRequest r;
    r.sampler = sampler;
    r.spp = spp;
    r.seed = seed;
    r.dim0 = dim;
    r.dim1 = one_d ? dim + 2 : dim + 1;
    r.pixels = pixels;
    return compute_sampler_points(test::test_device(), sampler_program(), r);
}

// Exact stratum of x in n equal strata (x is a float, n * x is exact in double).
std::uint32_t stratum(float x, std::uint32_t n)
{
    return static_cast<std::uint32_t>(std::floor(static_cast<double>(x) * n));
}

// Every value in [0, 1), and each of the n strata of coordinate c holds exactly one of
// the set's n points.
::testing::AssertionResult one_per_stratum_1d(const glm::vec2* p, std::uint32_t n, int c)
{
    std::vector<int> count(n, 0);
    for (std::uint32_t k = 0; k < n; ++k) {
        float x = p[k][c];
        if (!(x >= 0.0f && x < 1.0f))
            return ::testing::AssertionFailure() << "value " << x << " outside [0, 1)";
        if (++count[stratum(x, n)] > 1)
            return ::testing::AssertionFailure() << "two points in stratum " << stratum(x, n) << " of " << n
                                                 << " (coordinate " << c << ")";
    }
    return ::testing::AssertionSuccess();
}

// Each of the cols x rows cells holds exactly spp / (cols * rows) points (one for a
// full grid).
::testing::AssertionResult one_per_cell(const glm::vec2* p, std::uint32_t n, std::uint32_t cols, std::uint32_t rows)
{
    std::vector<int> count(static_cast<std::size_t>(cols) * rows, 0);
    for (std::uint32_t k = 0; k < n; ++k) {
        std::size_t cell = stratum(p[k].y, rows) * cols + stratum(p[k].x, cols);
        if (++count[cell] > 1)
            return ::testing::AssertionFailure() << "two points in cell (" << cell % cols << ", " << cell / cols
                                                 << ") of " << cols << "x" << rows;
    }
    return ::testing::AssertionSuccess();
}

TEST(Samplers, JitteredHasExactlyOneSamplePerStratum)
{
    // Broken variant seen to fail: the stratum taken from a hash of the sample index
    // instead of a permutation (two samples in one stratum, another empty).
    for (std::uint32_t spp : {1u, 4u, 9u, 16u, 64u, 256u})
        for (std::uint32_t dim : kDims) {
            SCOPED_TRACE("spp " + std::to_string(spp) + " dim " + std::to_string(dim));
            auto side = static_cast<std::uint32_t>(std::lround(std::sqrt(spp)));
            std::vector<glm::vec2> p = points(SamplerType::Jittered, spp, pixel_range(100, 8), dim);
            std::vector<glm::vec2> q = points(SamplerType::Jittered, spp, pixel_range(100, 8), dim, /*one_d=*/true);
            for (std::size_t px = 0; px < 8; ++px) {
                EXPECT_TRUE(one_per_cell(&p[px * spp], spp, side, side));
                // 1D decisions: spp strata each.
                EXPECT_TRUE(one_per_stratum_1d(&q[px * spp], spp, 0));
                EXPECT_TRUE(one_per_stratum_1d(&q[px * spp], spp, 1));
            }
        }
}

TEST(Samplers, NRooksHasOneSamplePerRowAndColumn)
{
    // Broken variant seen to fail: the y stratum from a hash of the sample index.
    for (std::uint32_t spp : {1u, 2u, 7u, 64u, 100u, 256u})
        for (std::uint32_t dim : kDims) {
            SCOPED_TRACE("spp " + std::to_string(spp) + " dim " + std::to_string(dim));
            std::vector<glm::vec2> p = points(SamplerType::NRooks, spp, pixel_range(7, 8), dim);
            std::vector<glm::vec2> q = points(SamplerType::NRooks, spp, pixel_range(7, 8), dim, true);
            for (std::size_t px = 0; px < 8; ++px) {
                EXPECT_TRUE(one_per_stratum_1d(&p[px * spp], spp, 0));
                EXPECT_TRUE(one_per_stratum_1d(&p[px * spp], spp, 1));
                EXPECT_TRUE(one_per_stratum_1d(&q[px * spp], spp, 0));
            }
        }
}

TEST(Samplers, MultiJitteredIsJitteredAndNRooks)
{
    // Broken variant seen to fail: the sub-column taken from the sample's own column
    // (sx where sy belongs), which keeps the coarse cells but puts two samples in one
    // fine column.
    for (std::uint32_t spp : {1u, 4u, 16u, 64u, 256u})
        for (std::uint32_t dim : kDims) {
            SCOPED_TRACE("spp " + std::to_string(spp) + " dim " + std::to_string(dim));
            auto side = static_cast<std::uint32_t>(std::lround(std::sqrt(spp)));
            std::vector<glm::vec2> p = points(SamplerType::MultiJittered, spp, pixel_range(3, 8), dim);
            for (std::size_t px = 0; px < 8; ++px) {
                EXPECT_TRUE(one_per_cell(&p[px * spp], spp, side, side));
                EXPECT_TRUE(one_per_stratum_1d(&p[px * spp], spp, 0));
                EXPECT_TRUE(one_per_stratum_1d(&p[px * spp], spp, 1));
            }
        }
}

// (0,m,2)-net in base 2: for every a = 0..m, every elementary interval
// [i / 2^a, (i + 1) / 2^a) x [j / 2^(m-a), (j + 1) / 2^(m-a)) holds exactly one point.
::testing::AssertionResult is_02_net(const glm::vec2* p, std::uint32_t m)
{
    const std::uint32_t n = 1u << m;
    for (std::uint32_t a = 0; a <= m; ++a) {
        ::testing::AssertionResult r = one_per_cell(p, n, 1u << a, 1u << (m - a));
        if (!r)
            return r << " (elementary intervals 2^-" << a << " x 2^-" << (m - a) << ")";
    }
    return ::testing::AssertionSuccess();
}

TEST(Samplers, SobolAndHammersleyAre02NetsForM2To10)
{
    // Broken variants seen to fail: a Cranley-Patterson rotation (adding a random offset
    // mod 1) instead of Owen scrambling; Hammersley's second coordinate in base 3.
    for (SamplerType sampler : {SamplerType::Sobol, SamplerType::Hammersley})
        for (std::uint32_t m = 2; m <= 10; ++m)
            for (std::uint32_t dim : kDims) {
                SCOPED_TRACE(sampler_name(sampler) + " m " + std::to_string(m) + " dim " + std::to_string(dim));
                const std::uint32_t spp = 1u << m;
                std::vector<glm::vec2> p = points(sampler, spp, pixel_range(1000, 4), dim);
                std::vector<glm::vec2> q = points(sampler, spp, pixel_range(1000, 4), dim, true);
                for (std::size_t px = 0; px < 4; ++px) {
                    EXPECT_TRUE(is_02_net(&p[px * spp], m));
                    EXPECT_TRUE(one_per_stratum_1d(&q[px * spp], spp, 0)); // 1D decisions
                }
            }
}

TEST(Samplers, PixelsGetDifferentPointSets)
{
    // Per-pixel scrambling: two pixels never share a point set (else the image would
    // show the sampler's structure as aliasing). Broken variant seen to fail: the
    // scramble seed without the pixel.
    for (const auto& [sampler_label, sampler] : sampler_names()) {
        std::vector<glm::vec2> p = points(sampler, 16, {5, 6}, DIM_PIXEL);
        std::set<std::pair<float, float>> a, b;
        for (int k = 0; k < 16; ++k) {
            a.insert({p[k].x, p[k].y});
            b.insert({p[16 + k].x, p[16 + k].y});
        }
        EXPECT_NE(a, b) << sampler_name(sampler);
    }
}

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
    set_kernel_args(k, static_cast<cl_uint>(base), static_cast<cl_uint>(scramble), static_cast<cl_uint>(seed), out, digits, scale);
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
    cl::Buffer bin(dev.context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, n * sizeof(float), const_cast<float*>(in.data()));
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
    std::vector<float> a = {0.0f, -0.0f, 1e-30f, -1e-30f, 1e-6f, std::numbers::pi_v<float> / 4.0f,
                            -std::numbers::pi_v<float> / 4.0f};
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

TEST(Samplers, ValuesDoNotDependOnTheOrderOfComputation)
{
    // The same (pixel, sample, dimension) gives bit-identical values whether the pixels
    // are computed in order, shuffled, or one at a time, and whether the samples are
    // computed in one launch or in two. Broken variant seen to fail: a scramble seeded
    // with the work-item id instead of the pixel.
    std::vector<std::uint32_t> order = pixel_range(500, 64);
    std::vector<std::uint32_t> shuffled = order;
    std::mt19937 rng(5);
    std::shuffle(shuffled.begin(), shuffled.end(), rng);
    const std::uint32_t spp = 64;
    for (const auto& [sampler_label, sampler] : sampler_names())
        for (bool one_d : {false, true}) {
            SCOPED_TRACE(sampler_name(sampler) + (one_d ? " 1D" : " 2D"));
            const std::uint32_t dim = DIM_PATH_START + 2 * DIMS_PER_BOUNCE + 3;
            std::vector<glm::vec2> a = points(sampler, spp, order, dim, one_d);
            std::vector<glm::vec2> b = points(sampler, spp, shuffled, dim, one_d);
            for (std::size_t i = 0; i < shuffled.size(); ++i) {
                std::size_t j = shuffled[i] - 500; // where pixel shuffled[i] sits in `a`
                for (std::uint32_t k = 0; k < spp; ++k) {
                    ASSERT_EQ(b[i * spp + k].x, a[j * spp + k].x);
                    ASSERT_EQ(b[i * spp + k].y, a[j * spp + k].y);
                }
            }
            // Samples 40..63 of one pixel alone.
            SamplerPointsRequest r;
            r.sampler = sampler;
            r.spp = spp;
            r.seed = 11;
            r.dim0 = dim;
            r.dim1 = one_d ? dim + 2 : dim + 1;
            r.pixels = {order[17]};
            r.first_sample = 40;
            r.count = 24;
            std::vector<glm::vec2> c = compute_sampler_points(test::test_device(), sampler_program(), r);
            for (std::uint32_t k = 0; k < 24; ++k) {
                ASSERT_EQ(c[k].x, a[17 * spp + 40 + k].x);
                ASSERT_EQ(c[k].y, a[17 * spp + 40 + k].y);
            }
        }
}

// Least-squares slope of log(mse) against log(spp).
double loglog_slope(const std::vector<double>& spp, const std::vector<double>& mse)
{
    double mx = 0, my = 0;
    for (std::size_t i = 0; i < spp.size(); ++i) {
        mx += std::log(spp[i]);
        my += std::log(mse[i]);
    }
    mx /= static_cast<double>(spp.size());
    my /= static_cast<double>(spp.size());
    double sxy = 0, sxx = 0;
    for (std::size_t i = 0; i < spp.size(); ++i) {
        double dx = std::log(spp[i]) - mx;
        sxy += dx * (std::log(mse[i]) - my);
        sxx += dx * dx;
    }
    return sxy / sxx;
}

// Integral over [0, 1] of exp(-(x - mu)^2 / (2 sigma^2)).
double gaussian_integral(double mu, double sigma)
{
    double k = sigma * std::sqrt(2.0);
    return sigma * std::sqrt(std::numbers::pi / 2.0) * (std::erf((1.0 - mu) / k) + std::erf(mu / k));
}

TEST(Samplers, ConvergenceOrderOfSmooth2DIntegrals)
{
    // The MSE of the per-pixel estimate over 256 pixels (independent randomizations) at
    // spp 16, 64, 256, 1024, 4096, for the film-position pair and a padded pair deep in
    // the path, of two smooth integrands with known integrals:
    //   bump:  an off-centre Gaussian, exp(-(x-0.45)^2 / (2 0.12^2) - (y-0.55)^2 / (2 0.18^2)),
    //          about 3e-5 of its peak at the border (product of erf integrals);
    //   exp(x y), whose integral is sum_{n>=1} 1 / (n n!) = 1.3179021514...
    // Independent sampling converges as spp^-1; jittered as spp^-2, the Owen-scrambled
    // nets faster. Multi-jittered is Kensler's correlated construction: all samples of a
    // row of cells share one sub-column offset, so each row is a randomly shifted grid
    // rule in x, whose first-order error (f(1, y) - f(0, y)) / (2 cols) does not cancel
    // between rows: spp^-3 on the bump, but only about spp^-1.5 on exp(x y) (measured
    // -1.46; the original, uncorrelated multi-jittered construction of Chiu, Shirley and
    // Wang, simulated outside this repository, gave -2.1). Halton at dims 45, 46 (bases
    // 199 and 211) is only reported: at these spp its high bases converge slowly (-1.4).
    // Broken variant seen to fail: jittered with each sample's stratum drawn at random
    // (slope -1.0 on both integrands).
    double exp_xy = 0.0, term = 1.0;
    for (int n = 1; n < 30; ++n) {
        term /= n;
        exp_xy += term / n;
    }
    const double bump = gaussian_integral(0.45, 0.12) * gaussian_integral(0.55, 0.18);
    auto f_bump = [](double x, double y) {
        return std::exp(-(x - 0.45) * (x - 0.45) / (2.0 * 0.12 * 0.12) - (y - 0.55) * (y - 0.55) / (2.0 * 0.18 * 0.18));
    };
    const std::vector<double> spps = {16, 64, 256, 1024, 4096};
    const std::uint32_t replicates = 256;
    for (std::uint32_t dim : {static_cast<std::uint32_t>(DIM_PIXEL),
                              static_cast<std::uint32_t>(DIM_PATH_START + 4 * DIMS_PER_BOUNCE + 5)})
        for (const auto& [sampler_label, sampler] : sampler_names()) {
            std::vector<double> mse_bump, mse_exp;
            for (double spp_d : spps) {
                auto spp = static_cast<std::uint32_t>(spp_d);
                std::vector<glm::vec2> p = points(sampler, spp, pixel_range(0, replicates), dim, false, 3);
                double sq_bump = 0.0, sq_exp = 0.0;
                for (std::uint32_t r = 0; r < replicates; ++r) {
                    double sb = 0.0, se = 0.0;
                    for (std::uint32_t k = 0; k < spp; ++k) {
                        const glm::vec2& u = p[static_cast<std::size_t>(r) * spp + k];
                        double x = u.x, y = u.y;
                        sb += f_bump(x, y);
                        se += std::exp(x * y);
                    }
                    sq_bump += (sb / spp - bump) * (sb / spp - bump);
                    sq_exp += (se / spp - exp_xy) * (se / spp - exp_xy);
                }
                mse_bump.push_back(sq_bump / replicates);
                mse_exp.push_back(sq_exp / replicates);
            }
            double slope_bump = loglog_slope(spps, mse_bump), slope_exp = loglog_slope(spps, mse_exp);
            std::printf("  %-15s dims %2u,%2u: log-log MSE slope: bump %.2f (MSE %.2g at 16 spp, %.2g at 4096), "
                        "exp(xy) %.2f (%.2g, %.2g)\n",
                        sampler_name(sampler).c_str(), dim, dim + 1, slope_bump, mse_bump.front(), mse_bump.back(),
                        slope_exp, mse_exp.front(), mse_exp.back());
            const std::string what = sampler_name(sampler) + " dims " + std::to_string(dim);
            switch (sampler) {
            case SamplerType::Independent:
                EXPECT_NEAR(slope_bump, -1.0, 0.2) << what;
                EXPECT_NEAR(slope_exp, -1.0, 0.2) << what;
                break;
            case SamplerType::MultiJittered:
                EXPECT_LE(slope_bump, -1.5) << what;
                EXPECT_LE(slope_exp, -1.3) << what; // see above
                break;
            case SamplerType::Jittered:
            case SamplerType::Sobol:
            case SamplerType::Hammersley:
                EXPECT_LE(slope_bump, -1.5) << what;
                EXPECT_LE(slope_exp, -1.5) << what;
                break;
            default: // n-rooks, halton: reported only
                break;
            }
        }
}

} // namespace
} // namespace pathcl
