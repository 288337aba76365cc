// Film accumulation on the device: 1e7 samples into one pixel keep the mean to < 1e-6
// relative error (a plain float sum, run beside it, drifts far more), and NaN/Inf samples
// are counted instead of poisoning the pixel.
#include <cmath>

#include <gtest/gtest.h>

#include "support/device_fixture.h"
#include "types.h"

namespace pathcl {
namespace {

const cl::Program& program()
{
    static cl::Program p = test::build_test_program("film_test_kernels.cl");
    return p;
}

// The samples the kernels accumulate, generated on the device, summed exactly (long
// double) on the host.
double exact_sum(std::uint32_t count)
{
    ClDevice& dev = test::test_device();
    cl::Buffer out(dev.context, CL_MEM_WRITE_ONLY, count * sizeof(float));
    cl::Kernel k(program(), "test_film_samples");
    set_kernel_args(k, out);
    dev.queue.enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(count));
    std::vector<float> samples(count);
    dev.queue.enqueueReadBuffer(out, CL_TRUE, 0, count * sizeof(float), samples.data());
    long double sum = 0.0L;
    for (float v : samples)
        sum += v;
    return static_cast<double>(sum);
}

TEST(Film, TenMillionSamplesKeepRelativeErrorBelow1e6)
{
    ClDevice& dev = test::test_device();
    const std::uint32_t count = 10000000;
    FilmPixel zero{};
    cl_uint bad0 = 0;
    cl::Buffer film(dev.context, CL_MEM_READ_WRITE | CL_MEM_COPY_HOST_PTR, sizeof(FilmPixel), &zero);
    cl::Buffer bad(dev.context, CL_MEM_READ_WRITE | CL_MEM_COPY_HOST_PTR, sizeof(cl_uint), &bad0);
    cl::Buffer naive(dev.context, CL_MEM_WRITE_ONLY, sizeof(float));
    cl::Kernel k(program(), "test_film_accumulate");
    set_kernel_args(k, film, bad, count);
    cl::Kernel kn(program(), "test_naive_accumulate");
    set_kernel_args(kn, naive, count);
    dev.queue.enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(1));
    dev.queue.enqueueNDRangeKernel(kn, cl::NullRange, cl::NDRange(1));
    FilmPixel px;
    float naive_sum;
    dev.queue.enqueueReadBuffer(film, CL_TRUE, 0, sizeof px, &px);
    dev.queue.enqueueReadBuffer(naive, CL_TRUE, 0, sizeof naive_sum, &naive_sum);

    double exact = exact_sum(count);
    double film_sum = static_cast<double>(px.sum.x) + static_cast<double>(px.sum_compensation.x);
    double film_count = static_cast<double>(px.sum.w) + static_cast<double>(px.sum_compensation.w);
    EXPECT_EQ(film_count, static_cast<double>(count));
    EXPECT_LT(std::fabs(film_sum - exact) / exact, 1e-6) << "film " << film_sum << " exact " << exact;
    // The naive float sum is the accumulator this design rejects: it must be visibly worse.
    EXPECT_GT(std::fabs(static_cast<double>(naive_sum) - exact) / exact, 1e-4) << "naive " << naive_sum;
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
} // namespace pathcl
