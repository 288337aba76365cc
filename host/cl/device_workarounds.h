// Workarounds for OpenCL compilers that miscompile pathcl's kernels, chosen per platform:
// the defines a program is built with on that device (docs/devices.md has each bug's
// minimal reproducer). Nowhere else does pathcl look at a platform's name.
#pragma once

#include <string>

#include "cl/cl_runtime.h"

namespace pathcl {

// Intel's CPU runtime (the platform "Intel(R) OpenCL" on a CPU; 2026.2 tested) vectorizes
// each kernel across work-items, and then passes the float3 arguments of a function it
// does not inline wrongly: each work-item reads its neighbours' components, the last 4 of
// every 16 read garbage. PATHCL_KERNEL_WIDTH_HINT makes every kernel declare its width
// (vec_type_hint(float8), kernels/util/compat.h), and that compiler leaves a kernel with a
// vector width hint as it is.
bool needs_kernel_width_hint(const DeviceInfo& device);

// The workaround defines for `device` (" -DNAME ..."; empty on a platform without known bugs).
std::string workaround_options(const DeviceInfo& device);

} // namespace pathcl
