// The device's own math routines against double precision, through the real kernel code:
// atan2_fast (kernels/util/atan.cl), which the environment lookup uses in place of the
// built-in atan2.
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "support/device_fixture.h"

namespace pathcl::test_kernel_math {
namespace {

// The distance from `got` to the exact value in units of the float spacing at it.
double ulps(float got, double exact)
{
    double spacing =
        std::nextafter(static_cast<float>(std::fabs(exact)), INFINITY) - std::fabs(static_cast<float>(exact));
    if (exact == 0.0)
        return got == 0.0f ? 0.0 : std::fabs(got) / static_cast<double>(std::numeric_limits<float>::denorm_min());
    return std::fabs(static_cast<double>(got) - exact) / spacing;
}

TEST(KernelMath, Atan2IsWithinTwoAndAHalfUlpsEverywhere)
{
    // Every quadrant, the axes and signed zeros, angles near the reduction points
    // (tan(pi/8), 1, tan(3pi/8)), tiny and huge ratios, and random directions: the worst
    // seen is 2.2 ulps, just above tan(pi/8), where pi/4 - atan(...) cancels. Broken
    // variants seen to fail: pi/4 added without its low part (3.1 ulps); zero returned at
    // the origin whatever the signs of the zeros.
    std::vector<float> ys, xs;
    auto add = [&](double y, double x) {
        ys.push_back(static_cast<float>(y));
        xs.push_back(static_cast<float>(x));
    };
    for (double y : {0.0, -0.0, 1.0, -1.0})
        for (double x : {0.0, -0.0, 1.0, -1.0, 1e-30, -1e30})
            add(y, x);
    for (double r : {0.41421356, 0.41421357, 1.0, 0.99999994, 1.0000001, 2.4142135, 2.4142137, 1e-20, 1e20})
        for (int q = 0; q < 4; ++q)
            add((q & 1 ? -1.0 : 1.0) * r, q & 2 ? -1.0 : 1.0);
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int i = 0; i < 200000; ++i)
        add(u(rng), u(rng));
    std::vector<float> yx;
    for (std::size_t i = 0; i < ys.size(); ++i) {
        yx.push_back(ys[i]);
        yx.push_back(xs[i]);
    }
    static cl::Program program = test::build_test_program("math_test_kernels.cl");
    ClDevice& dev = test::test_device();
    cl::Buffer in = test::upload(yx);
    cl::Buffer out(dev.context, CL_MEM_WRITE_ONLY, ys.size() * sizeof(float));
    cl::Kernel k(program, "test_atan2");
    set_kernel_args(k, in, out);
    dev.queue.enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(ys.size()));
    std::vector<float> got = test::read_back<float>(out, ys.size());
    double worst = 0.0;
    std::size_t worst_at = 0;
    for (std::size_t i = 0; i < ys.size(); ++i) {
        double exact = std::atan2(static_cast<double>(ys[i]), static_cast<double>(xs[i]));
        double e = ulps(got[i], exact);
        if (e > worst) {
            worst = e;
            worst_at = i;
        }
    }
    EXPECT_LE(worst, 2.5) << "atan2(" << ys[worst_at] << ", " << xs[worst_at] << ") = " << got[worst_at];
}

} // namespace
} // namespace pathcl::test_kernel_math
