// Shared access to OpenCL device 0 for the device tests, plus helpers that compile test
// kernels (tests/kernels/*.cl) together with the real kernel sources.
#pragma once

#include <string>

#include "cl/cl_runtime.h"

namespace pathcl::test {

// Device 0, opened once per test binary.
ClDevice& test_device();

// The real kernels plus tests/kernels/<file>, built with `defines`.
cl::Program build_test_program(const std::string& file, const std::string& defines = "");

std::string read_text_file(const std::string& path);

} // namespace pathcl::test
