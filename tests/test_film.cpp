// Film accumulation on the device: 1e7 samples into one pixel keep the mean to < 1e-6
// relative error (a plain float sum of the same samples drifts far more), and NaN/Inf
// samples are counted instead of poisoning the pixel.
#include <cmath>

#include <gtest/gtest.h>

#include "support/device_fixture.h"
#include "types.h"

namespace pathcl::test_film {
namespace {

const cl::Program& program()
{
    static cl::Program p = test::build_test_program("film_test_kernels.cl");
    return p;
}

struct HostSums {
    double exact = 0.0;    // long double, rounded once
    float in_order = 0.0f; // one float addition after the other, in sample order
};

// The samples the kernels accumulate, generated on the device, summed on the host exactly
// and as a plain float sum in order. The plain sum is the accumulator the film's design
// rejects; it is taken here and not in a kernel, because an OpenCL compiler may in
// practice reorder a loop's float sum (Intel's CPU runtime 2026.2 adds in partial sums,
// which came out better than 1e-4; docs/devices.md), and the contrast must be the sum in
// sample order.
HostSums host_sums(std::uint32_t count)
{
    ClDevice& dev = test::test_device();
    cl::Buffer out(dev.context, CL_MEM_WRITE_ONLY, count * sizeof(float));
    cl::Kernel k(program(), "test_film_samples");
    set_kernel_args(k, out);
    dev.queue.enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(count));
    std::vector<float> samples(count);
    dev.queue.enqueueReadBuffer(out, CL_TRUE, 0, count * sizeof(float), samples.data());
    long double sum = 0.0L;
    HostSums sums;
    for (float v : samples) {
        sum += v;
        sums.in_order += v;
    }
    sums.exact = static_cast<double>(sum);
    return sums;
}

TEST(Film, TenMillionSamplesKeepRelativeErrorBelow1e6)
{
    ClDevice& dev = test::test_device();
    const std::uint32_t count = 10000000;
    FilmPixel zero{};
    cl_uint bad0 = 0;
    cl::Buffer film(dev.context, CL_MEM_READ_WRITE | CL_MEM_COPY_HOST_PTR, sizeof(FilmPixel), &zero);
    cl::Buffer bad(dev.context, CL_MEM_READ_WRITE | CL_MEM_COPY_HOST_PTR, sizeof(cl_uint), &bad0);
    cl::Kernel k(program(), "test_film_accumulate");
    set_kernel_args(k, film, bad, count);
    dev.queue.enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(1));
    FilmPixel px;
    dev.queue.enqueueReadBuffer(film, CL_TRUE, 0, sizeof px, &px);

    const HostSums sums = host_sums(count);
    const double exact = sums.exact;
    double film_sum = static_cast<double>(px.sum.x) + static_cast<double>(px.sum_compensation.x);
    double film_count = static_cast<double>(px.sum.w) + static_cast<double>(px.sum_compensation.w);
    EXPECT_EQ(film_count, static_cast<double>(count));
    EXPECT_LT(std::fabs(film_sum - exact) / exact, 1e-6) << "film " << film_sum << " exact " << exact;
    // The plain float sum is the accumulator this design rejects: it must be visibly worse.
    EXPECT_GT(std::fabs(static_cast<double>(sums.in_order) - exact) / exact, 1e-4) << "plain " << sums.in_order;
}

TEST(Film, NonFiniteSamplesAreCountedNotAdded)
{
    ClDevice& dev = test::test_device();
    FilmPixel zero{};
    cl_uint bad0 = 0;
    cl::Buffer film(dev.context, CL_MEM_READ_WRITE | CL_MEM_COPY_HOST_PTR, sizeof(FilmPixel), &zero);
    cl::Buffer bad(dev.context, CL_MEM_READ_WRITE | CL_MEM_COPY_HOST_PTR, sizeof(cl_uint), &bad0);
    cl::Kernel k(program(), "test_film_rejects_non_finite");
    set_kernel_args(k, film, bad);
    dev.queue.enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(1));
    FilmPixel px;
    cl_uint bad_count;
    dev.queue.enqueueReadBuffer(film, CL_TRUE, 0, sizeof px, &px);
    dev.queue.enqueueReadBuffer(bad, CL_TRUE, 0, sizeof bad_count, &bad_count);
    EXPECT_EQ(bad_count, 3u);
    EXPECT_EQ(px.sum.x, 1.0f);
    EXPECT_EQ(px.sum.w, 1.0f);
}

} // namespace
} // namespace pathcl::test_film
