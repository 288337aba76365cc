#include "cl/device_workarounds.h"

namespace pathcl {

bool needs_kernel_width_hint(const DeviceInfo& device)
{
    // Intel's GPU runtime names its platform "Intel(R) OpenCL Graphics" and compiles with
    // another compiler (IGC); only the CPU device has the vectorizer in question.
    return device.platform.rfind("Intel(R) OpenCL", 0) == 0 && device.type == "CPU";
}

std::string workaround_options(const DeviceInfo& device)
{
    return needs_kernel_width_hint(device) ? " -DPATHCL_KERNEL_WIDTH_HINT" : "";
}

} // namespace pathcl
