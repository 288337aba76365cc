// Shared access to OpenCL device 0 for the device tests, plus helpers that compile test
// kernels (tests/kernels/*.cl) together with the real kernel sources.
#pragma once

#include <string>

#include <glm/glm.hpp>

#include "cl/cl_runtime.h"
#include "render/environment.h"
#include "shared_types.h"

namespace pathcl::test {

// Device 0, opened once per test binary.
ClDevice& test_device();

// The real kernels plus tests/kernels/<file>, built with `defines`.
cl::Program build_test_program(const std::string& file, const std::string& defines = "");

std::string read_text_file(const std::string& path);

// Texture data as the kernels read it (kernels/shared_types.h), for test kernels.
struct TextureData {
    std::vector<pcl_uint> texels;
    std::vector<TextureImage> images;
    std::vector<TextureView> views;
    std::vector<TriangleTexcoords> texcoords;
};

// Runs test_light_sample (tests/kernels/trace_test_kernels.cl, built into `program`) once
// per sample: light_sample from `ref` over `lights` (environment buffers from `env`, and
// emissive textures from `textures`, if any). Each result is (direction, pdf), or zero
// when there was no sample; the radiance each sample carries goes to `radiance` if given.
std::vector<pcl_float4> sample_lights_on_device(const cl::Program& program, const std::vector<Light>& lights,
                                                const EnvironmentMap* env, glm::vec3 ref, std::uint32_t seed,
                                                std::size_t n, std::vector<pcl_float4>* radiance = nullptr,
                                                const TextureData* textures = nullptr);

} // namespace pathcl::test
