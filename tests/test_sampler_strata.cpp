// The stratification each of the seven samplers of kernels/sample/sampler.cl promises, through
// the real kernel code (the kernel sampler_points the visualizer uses): one sample per
// stratum, row and column, (0,m,2)-nets, and a different point set for every pixel. Each
// property test names, beside it, the deliberately broken variant that was seen to fail
// it (checked once, by hand).
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "sample/dimensions.h"
#include "sampling/samplers.h"
#include "support/device_fixture.h"
#include "support/sampler_points.h"

namespace pathcl::test_sampler_strata {
namespace {

using test::one_per_cell;
using test::one_per_stratum_1d;
using test::pixel_range;
using test::points;
using test::sampler_program;

// Dimension pairs the tests look at: the film position, the lens, and decisions of the
// first and of a deep bounce (1D decisions at odd starts too).
const std::vector<std::uint32_t> kDims = {DIM_PIXEL, DIM_LENS, DIM_PATH_START + 1,
                                          DIM_PATH_START + 5 * DIMS_PER_BOUNCE + 5};

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

TEST(Samplers, DecisionsPastTheStratifiedBouncesAreIndependentNumbers)
{
    // frame.stratified_dims splits a path's decisions: below it the sampler's sets, from
    // it on the independent sampler's numbers, bit for bit. Broken variant seen to fail:
    // the 2D draw ignoring the limit (the 1D one honouring it).
    auto draw = [](SamplerType sampler, std::uint32_t stratified_dims, std::uint32_t dim) {
        FrameParams f{};
        f.width = 256;
        f.height = 1;
        f.sample_index = 5;
        f.seed = 9;
        f.sampler = static_cast<pcl_uint>(sampler);
        f.spp = 16;
        f.stratified_dims = stratified_dims;
        ClDevice& dev = test::test_device();
        cl::Buffer out(dev.context, CL_MEM_WRITE_ONLY, 256 * sizeof(float) * 2);
        cl::Kernel k(sampler_program(), "test_frame_sampler");
        set_kernel_args(k, f, static_cast<cl_uint>(dim), out);
        dev.queue.enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(256));
        return test::read_back<glm::vec2>(out, 256);
    };
    const std::uint32_t limit = DIM_PATH_START + DIMS_PER_BOUNCE; // the camera and bounce 0
    for (SamplerType sampler : {SamplerType::Sobol, SamplerType::MultiJittered, SamplerType::Halton}) {
        auto deep = draw(sampler, limit, limit), deep_independent = draw(SamplerType::Independent, limit, limit);
        EXPECT_EQ(deep, deep_independent) << sampler_name(sampler);
        auto first = draw(sampler, limit, DIM_PATH_START + DIM_BSDF);
        auto first_independent = draw(SamplerType::Independent, limit, DIM_PATH_START + DIM_BSDF);
        std::size_t same = 0;
        for (std::size_t i = 0; i < first.size(); ++i)
            same += first[i] == first_independent[i];
        EXPECT_LT(same, 4u) << sampler_name(sampler) << ": the first bounce should use the sampler's sets";
    }
}

TEST(Samplers, ABouncesNumbersDrawnAtOnceAreThoseDrawnOneByOne)
{
    // The megakernel draws a bounce's numbers in lanes (sampler_draw_bounce); every value
    // must be the one-by-one draw's, bit for bit: for the samplers it draws at once and for
    // those it leaves alone, power-of-two and other spp (the permutation's cycle walk), the
    // first and a deep bounce, and the stratified dimensions ending before, inside (between
    // a pair's two numbers) and after the bounce. Broken variants seen to fail: a pair's
    // second number judged stratified by its own dimension instead of the pair's (limit
    // inside the pair); the lanes' permutation stopping after one round (spp 12).
    const std::uint32_t first = DIM_PATH_START, deep = DIM_PATH_START + 3 * DIMS_PER_BOUNCE;
    const std::uint32_t pair = DIM_LIGHT_POINT; // the light point's pair starts here
    static_assert((DIM_PAIRS_IN_BOUNCE >> DIM_LIGHT_POINT & 1u) != 0u);
    const std::uint32_t n = 256, per_pixel = 2 * DIMS_PER_BOUNCE;
    for (SamplerType sampler :
         {SamplerType::Sobol, SamplerType::Independent, SamplerType::MultiJittered, SamplerType::Halton})
        for (std::uint32_t spp : {1u, 12u, 16u, 256u})
            for (std::uint32_t start : {first, deep})
                for (std::uint32_t limit : {first, first + pair + 1, first + DIMS_PER_BOUNCE, 0xffffffffu}) {
                    SCOPED_TRACE(std::string(sampler_name(sampler)) + " spp " + std::to_string(spp) + " start " +
                                 std::to_string(start) + " stratified below " + std::to_string(limit));
                    FrameParams f{};
                    f.width = n;
                    f.height = 1;
                    f.sample_index = 7;
                    f.seed = 3;
                    f.sampler = static_cast<pcl_uint>(sampler);
                    f.spp = spp;
                    f.stratified_dims = limit;
                    ClDevice& dev = test::test_device();
                    cl::Buffer at_once(dev.context, CL_MEM_WRITE_ONLY, n * per_pixel * sizeof(float));
                    cl::Buffer one_by_one(dev.context, CL_MEM_WRITE_ONLY, n * per_pixel * sizeof(float));
                    cl::Buffer count(dev.context, CL_MEM_WRITE_ONLY, n * sizeof(cl_uint));
                    cl::Kernel k(sampler_program(), "test_sampler_draw_bounce");
                    set_kernel_args(k, f, static_cast<cl_uint>(start), at_once, one_by_one, count);
                    dev.queue.enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(n));
                    auto a = test::read_back<std::uint32_t>(at_once, n * per_pixel); // the floats' bits
                    auto b = test::read_back<std::uint32_t>(one_by_one, n * per_pixel);
                    auto c = test::read_back<std::uint32_t>(count, n);
                    EXPECT_EQ(a, b);
                    // Drawn at once exactly where the lanes can: Sobol' and independent
                    // numbers (also a stratified sampler's past its stratified bounces).
                    bool lanes = sampler == SamplerType::Sobol || sampler == SamplerType::Independent || start >= limit;
                    EXPECT_EQ(c[0], lanes ? 8u : 0u);
                }
}

} // namespace
} // namespace pathcl::test_sampler_strata
