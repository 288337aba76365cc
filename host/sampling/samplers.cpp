#include "sampling/samplers.h"

#include <cmath>

#include "cl/kernel_args.h"
#include "common/error.h"
#include "sample/strata.h"
#include "types.h"

namespace pathcl {

const std::map<std::string, SamplerType>& sampler_names()
{
    static const std::map<std::string, SamplerType> names = {{"independent", SamplerType::Independent},
                                                             {"jittered", SamplerType::Jittered},
                                                             {"multi-jittered", SamplerType::MultiJittered},
                                                             {"n-rooks", SamplerType::NRooks},
                                                             {"sobol", SamplerType::Sobol},
                                                             {"halton", SamplerType::Halton},
                                                             {"hammersley", SamplerType::Hammersley}};
    return names;
}

std::string sampler_name(SamplerType sampler)
{
    for (const auto& [name, value] : sampler_names())
        if (value == sampler)
            return name;
    throw Error("unknown sampler " + std::to_string(static_cast<std::uint32_t>(sampler)));
}

std::uint32_t sampler_spp(SamplerType sampler, std::uint32_t requested)
{
    std::uint64_t n = std::max<std::uint32_t>(requested, 1u);
    switch (sampler) {
    case SamplerType::Jittered:
    case SamplerType::MultiJittered: {
        auto r = static_cast<std::uint64_t>(std::sqrt(static_cast<double>(n)));
        while (r * r < n)
            ++r;
        while (r > 1 && (r - 1) * (r - 1) >= n)
            --r;
        if (r * r > (1u << 30))
            throw ParameterError("spp", std::to_string(requested) + " rounds up to " + std::to_string(r * r) +
                                            " for this sampler, more than the 2^30 allowed");
        return static_cast<std::uint32_t>(r * r);
    }
    case SamplerType::Hammersley: {
        std::uint64_t p = 1;
        while (p < n)
            p <<= 1;
        if (p > (1u << 30))
            throw ParameterError("spp", std::to_string(requested) + " rounds up to " + std::to_string(p) +
                                            " for hammersley, more than the 2^30 allowed");
        return static_cast<std::uint32_t>(p);
    }
    case SamplerType::Independent:
    case SamplerType::NRooks:
    case SamplerType::Sobol:
    case SamplerType::Halton:
        return static_cast<std::uint32_t>(n);
    }
    throw Error("unknown sampler " + std::to_string(static_cast<std::uint32_t>(sampler)));
}

StrataGrid sampler_strata(SamplerType sampler, std::uint32_t spp)
{
    StrataGrid g;
    // The kernels' grid (sample/strata.h).
    const std::uint32_t cols = strata_cols(spp), rows = strata_rows(spp, cols);
    switch (sampler) {
    case SamplerType::Jittered:
        g.cols = cols;
        g.rows = rows;
        break;
    case SamplerType::MultiJittered:
        g.cols = cols;
        g.rows = rows;
        g.fine = cols * rows;
        break;
    case SamplerType::NRooks:
        g.cols = g.rows = spp;
        break;
    default:
        break;
    }
    return g;
}

std::vector<glm::vec2> compute_sampler_points(const ClDevice& dev, const cl::Program& program,
                                              const SamplerPointsRequest& rq)
{
    if (rq.pixels.empty())
        return {};
    const std::uint32_t count = rq.count ? rq.count : rq.spp;
    const std::size_t n = static_cast<std::size_t>(count) * rq.pixels.size();
    std::vector<glm::vec2> points(n);
    try {
        cl::Buffer pixels(dev.context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR,
                          rq.pixels.size() * sizeof(std::uint32_t), const_cast<std::uint32_t*>(rq.pixels.data()));
        cl::Buffer out(dev.context, CL_MEM_WRITE_ONLY, n * sizeof(float) * 2);
        cl::Kernel k(program, "sampler_points");
        set_kernel_args(k, static_cast<cl_uint>(rq.sampler), static_cast<cl_uint>(rq.spp),
                        static_cast<cl_uint>(rq.seed), static_cast<cl_uint>(rq.dim0), static_cast<cl_uint>(rq.dim1),
                        pixels, static_cast<cl_uint>(rq.first_sample), static_cast<cl_uint>(count), out);
        dev.queue.enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(count, rq.pixels.size()));
        dev.queue.enqueueReadBuffer(out, CL_TRUE, 0, n * sizeof(float) * 2, points.data());
    } catch (const cl::Error& e) {
        throw Error(std::string("sampler_points kernel failed: ") + e.what() + " (OpenCL error " +
                    std::to_string(e.err()) + ")");
    }
    return points;
}

} // namespace pathcl
