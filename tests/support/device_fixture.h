// Shared access to OpenCL device 0 for the device tests: test programs assembled from
// tests/kernels/*.cl (each includes the kernel files it tests), built with a typed feature
// mask, and the scene arrays uploaded and bound exactly as a render does it
// (compile/device_arrays.h).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "cl/cl_runtime.h"
#include "cl/kernel_args.h"
#include "compile/device_arrays.h"
#include "features.h"
#include "types.h"

namespace pathcl::test {

// Device 0, opened once per test binary.
ClDevice& test_device();

// tests/kernels/<file>, assembled with the kernel tree and built with the feature mask
// (FEATURE_* bits), and the patches (deliberately broken variants) applied; extra_options
// are added to the build options (e.g. -cl-denorms-are-zero, to behave as a device
// without single-precision denormals).
cl::Program build_test_program(const std::string& file, std::uint32_t features = 0,
                               const std::vector<KernelPatch>& patches = {}, const std::string& extra_options = "");

std::string read_text_file(const std::string& path);

// A read-only buffer holding `data` (one zeroed element when empty), and a read-back.
template <typename T>
cl::Buffer upload(const std::vector<T>& data)
{
    static const T zero{};
    std::size_t bytes = std::max<std::size_t>(1, data.size()) * sizeof(T);
    return cl::Buffer(test_device().context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, bytes,
                      const_cast<T*>(data.empty() ? &zero : data.data()));
}

template <typename T>
std::vector<T> read_back(const cl::Buffer& buffer, std::size_t n)
{
    std::vector<T> out(n);
    test_device().queue.enqueueReadBuffer(buffer, CL_TRUE, 0, n * sizeof(T), out.data());
    return out;
}

// Runs test_light_sample (tests/kernels/trace_test_kernels.cl, built into `program`) once
// per sample: light_sample from `ref` over the lights of `arrays` (with their light
// distribution, environment and emissive textures). Each result is (direction, pdf), or
// zero when there was no sample; the radiance each sample carries goes to `radiance` if
// given.
std::vector<pcl_float4> sample_lights_on_device(const cl::Program& program, const SceneArrays& arrays, glm::vec3 ref,
                                                std::uint32_t seed, std::size_t n,
                                                std::vector<pcl_float4>* radiance = nullptr);

} // namespace pathcl::test
