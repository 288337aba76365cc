// The wavefront integrator on one device (kernels/wavefront/): the paths of a pass, one
// per pixel of the device's band, held in a structure of arrays in device memory
// (kernels/wavefront/path_state.h), and the pass as a sequence of stage kernels instead of
// the megakernel's one launch.
#pragma once

#include <cstdint>
#include <string>

#include <CL/opencl.hpp>

#include "cl/cl_runtime.h"
#include "compile/device_arrays.h"
#include "types.h"

namespace pathcl {

// Empty when the wavefront can render a program of these kernel features, else why not
// (its stage kernels cover Lambertian materials lit by emissive triangles so far).
std::string wavefront_unsupported(std::uint32_t feature_mask);

// The build option that compiles the wavefront's kernels into the render program.
inline const char* wavefront_build_option()
{
    return "-DPATHCL_WAVEFRONT";
}

// Paths per shading work-item on a device (kernels/wavefront/lanes.cl): `requested` (1 or
// 8) when not 0, else 8 on CPUs (whose OpenCL compilers do not run shading in lanes on
// their own) and 1 elsewhere (GPUs run work-items in lanes).
std::uint32_t wavefront_lanes(const DeviceInfo& device, std::uint32_t requested);

// The build option that sets them.
std::string wavefront_lanes_option(std::uint32_t lanes);

class WavefrontPass {
public:
    // `max_paths`: the most pixels a band can hold (the image's); `lanes`: what the program
    // was built with (wavefront_lanes_option).
    WavefrontPass(const ClDevice& dev, const cl::Program& program, std::size_t max_paths, std::uint32_t lanes);

    // Enqueues the stages of one pass (after the camera kernel has written the band's rays):
    // `paths` pixels from row frame.first_row; `done` (may be null) signals the last stage.
    void enqueue(cl::CommandQueue& queue, const DeviceArrays& arrays, const FrameParams& frame, std::uint32_t paths,
                 cl::Event* done);

    // Bytes of device memory the path state takes.
    std::size_t state_bytes() const { return state_bytes_; }

private:
    cl::Kernel start_, extend_, shade_, shadow_, film_;
    cl::Buffer state_;
    std::uint32_t lanes_ = 8;    // paths per shading work-item
    std::uint32_t capacity_ = 0; // slots in the state arrays: whole groups of shading work-items
    std::size_t state_bytes_ = 0;
};

} // namespace pathcl
