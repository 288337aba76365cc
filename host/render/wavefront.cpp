#include "render/wavefront.h"

#include "common/error.h"
#include "compile/kernel_features.h"
#include "features.h"
#include "wavefront/path_state.h"

namespace pathcl {
namespace {

// Work-items per group in every stage.
constexpr std::uint32_t kGroup = 64;

std::uint32_t round_up(std::uint64_t v, std::uint32_t m)
{
    return static_cast<std::uint32_t>((v + m - 1) / m * m);
}

} // namespace

std::string wavefront_unsupported(std::uint32_t feature_mask)
{
    const std::uint32_t uncovered = feature_mask & ~std::uint32_t(FEATURE_AREA_LIGHTS);
    if (uncovered == 0)
        return "";
    std::string names;
    for (const std::string& name : feature_names(uncovered))
        names += (names.empty() ? "" : ", ") + name;
    return "wavefront: the scene needs " + names +
           "; the wavefront's stages cover only Lambertian materials lit by emissive triangles so far";
}

std::uint32_t wavefront_lanes(const DeviceInfo& device, std::uint32_t requested)
{
    if (requested != 0)
        return requested;
    return device.type.find("CPU") != std::string::npos ? 8u : 1u;
}

std::string wavefront_lanes_option(std::uint32_t lanes)
{
    if (lanes != 1 && lanes != 8)
        throw ParameterError("wavefront-lanes", "must be 1 or 8, not " + std::to_string(lanes));
    return " -DLANES=" + std::to_string(lanes);
}

WavefrontPass::WavefrontPass(const ClDevice& dev, const cl::Program& program, std::size_t max_paths,
                             std::uint32_t lanes)
    : lanes_(lanes)
{
    capacity_ = round_up(max_paths, lanes_ * kGroup);
    state_bytes_ = std::size_t(WAVEFRONT_FIELD_COUNT) * capacity_ * sizeof(float);
    start_ = cl::Kernel(program, "wavefront_start");
    extend_ = cl::Kernel(program, "wavefront_extend");
    shade_ = cl::Kernel(program, "wavefront_shade");
    shadow_ = cl::Kernel(program, "wavefront_shadow");
    film_ = cl::Kernel(program, "wavefront_film");
    state_ = cl::Buffer(dev.context, CL_MEM_READ_WRITE, state_bytes_);
}

void WavefrontPass::enqueue(cl::CommandQueue& queue, const DeviceArrays& arrays, const FrameParams& frame,
                            std::uint32_t paths, cl::Event* done)
{
    const cl::NDRange group(kGroup);
    const cl::NDRange slots(capacity_), lane_groups(capacity_ / lanes_);
    bind_kernel(start_, arrays, frame, state_, capacity_, paths);
    queue.enqueueNDRangeKernel(start_, cl::NullRange, slots, group);
    for (std::uint32_t depth = 0; depth <= frame.max_bounces; ++depth) {
        bind_kernel(extend_, arrays, frame, state_, capacity_, depth);
        queue.enqueueNDRangeKernel(extend_, cl::NullRange, slots, group);
        bind_kernel(shade_, arrays, frame, state_, capacity_, depth);
        queue.enqueueNDRangeKernel(shade_, cl::NullRange, lane_groups, group);
        if (depth < frame.max_bounces) {
            bind_kernel(shadow_, arrays, frame, state_, capacity_);
            queue.enqueueNDRangeKernel(shadow_, cl::NullRange, slots, group);
        }
    }
    bind_kernel(film_, arrays, frame, state_, capacity_, paths);
    queue.enqueueNDRangeKernel(film_, cl::NullRange, cl::NDRange(round_up(paths, kGroup)), group, nullptr, done);
}

} // namespace pathcl
