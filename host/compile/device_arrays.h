// The device arrays of a render on the host, generated from the one list both sides share
// (kernels/data_arrays.h): the compiled scene's vectors, one device's buffers, and the
// bind call that gives every render kernel the same arguments in the list's order. No
// buffer is bound by position anywhere else.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include <CL/opencl.hpp>

#include "cl/cl_runtime.h"
#include "cl/kernel_args.h"
#include "common/default_init_allocator.h"
#include "data_arrays.h"
#include "types.h"

namespace pathcl {

// The vector a scene array is kept in: std::vector, but for the light tree's nodes, which
// the tree's build writes on every core, one that resizes without zeroing.
template <class T>
struct SceneVector {
    using vector = std::vector<T>;
};
template <>
struct SceneVector<LightTreeNode> {
    using vector = UninitializedVector<LightTreeNode>;
};

// One vector per scene array; an empty vector is uploaded as one zeroed element.
struct SceneArrays {
#define PATHCL_SCENE_VECTOR(type, name) SceneVector<type>::vector name;
    PATHCL_SCENE_ARRAYS(PATHCL_SCENE_VECTOR)
#undef PATHCL_SCENE_VECTOR
};

// Every array on one device: the scene's, uploaded, and the film's, allocated.
struct DeviceArrays {
#define PATHCL_DEVICE_BUFFER(type, name) cl::Buffer name;
    PATHCL_SCENE_ARRAYS(PATHCL_DEVICE_BUFFER)
    PATHCL_FILM_ARRAYS(PATHCL_DEVICE_BUFFER)
#undef PATHCL_DEVICE_BUFFER
};

// Throws pathcl::Error naming the bytes needed and the device's limits when the arrays
// (the scene's and the film's for `pixels` pixels) exceed the device's memory or one of
// them its largest buffer: a clean refusal before allocating, instead of an OpenCL error
// or a crash inside the driver.
void check_device_memory(const ClDevice& dev, const SceneArrays& scene, std::size_t pixels);

// Uploads the scene arrays and allocates film arrays for `pixels` pixels (blocking), after
// check_device_memory.
DeviceArrays upload_arrays(const ClDevice& dev, const SceneArrays& scene, std::size_t pixels);

// Sets the arguments of a kernel that takes the generated parameter list
// (PATHCL_KERNEL_PARAMS): every array of the list in order, then `rest` (the render
// kernels' FrameParams; a test kernel's own arguments).
template <class... Rest>
void bind_kernel(cl::Kernel& kernel, const DeviceArrays& a, const Rest&... rest)
{
#define PATHCL_ARGUMENT(type, name) a.name,
    set_kernel_args(kernel, PATHCL_SCENE_ARRAYS(PATHCL_ARGUMENT) PATHCL_FILM_ARRAYS(PATHCL_ARGUMENT) rest...);
#undef PATHCL_ARGUMENT
}

} // namespace pathcl
