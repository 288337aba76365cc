#include "support/sampler_points.h"

#include <cmath>
#include <cstddef>
#include <numeric>

#include "support/device_fixture.h"

namespace pathcl::test {

namespace {

// Exact stratum of x in n equal strata (x is a float, n * x is exact in double).
std::uint32_t stratum(float x, std::uint32_t n)
{
    return static_cast<std::uint32_t>(std::floor(static_cast<double>(x) * n));
}

} // namespace

const cl::Program& sampler_program()
{
    static cl::Program p = test::build_test_program("sampler_test_kernels.cl");
    return p;
}

std::vector<std::uint32_t> pixel_range(std::uint32_t first, std::uint32_t n)
{
    std::vector<std::uint32_t> v(n);
    std::iota(v.begin(), v.end(), first);
    return v;
}

std::vector<glm::vec2> points(SamplerType sampler, std::uint32_t spp, const std::vector<std::uint32_t>& pixels,
                              std::uint32_t dim, bool one_d, std::uint32_t seed)
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

::testing::AssertionResult one_per_stratum_1d(const glm::vec2* p, std::uint32_t n, int c)
{
    std::vector<int> count(n, 0);
    for (std::uint32_t k = 0; k < n; ++k) {
        float x = p[k][c];
        if (!(x >= 0.0f && x < 1.0f))
            return ::testing::AssertionFailure() << "value " << x << " outside [0, 1)";
        if (++count[stratum(x, n)] > 1)
            return ::testing::AssertionFailure()
                   << "two points in stratum " << stratum(x, n) << " of " << n << " (coordinate " << c << ")";
    }
    return ::testing::AssertionSuccess();
}

::testing::AssertionResult one_per_cell(const glm::vec2* p, std::uint32_t n, std::uint32_t cols, std::uint32_t rows)
{
    std::vector<int> count(static_cast<std::size_t>(cols) * rows, 0);
    for (std::uint32_t k = 0; k < n; ++k) {
        std::size_t cell = stratum(p[k].y, rows) * cols + stratum(p[k].x, cols);
        if (++count[cell] > 1)
            return ::testing::AssertionFailure()
                   << "two points in cell (" << cell % cols << ", " << cell / cols << ") of " << cols << "x" << rows;
    }
    return ::testing::AssertionSuccess();
}

} // namespace pathcl::test
