// Binds a kernel's arguments in the order given: the one place pathcl calls setArg. The
// render kernels' arguments come from the generated list (compile/device_arrays.h).
#pragma once

#include <CL/opencl.hpp>

namespace pathcl {

template <class... Args>
void set_kernel_args(cl::Kernel& kernel, const Args&... args)
{
    cl_uint index = 0;
    (kernel.setArg(index++, args), ...);
}

} // namespace pathcl
