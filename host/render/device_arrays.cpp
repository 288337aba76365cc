#include "render/device_arrays.h"

#include <algorithm>

namespace pathcl {
namespace {

template <typename T>
cl::Buffer upload(const ClDevice& dev, const std::vector<T>& data)
{
    // OpenCL has no empty buffer: an array the scene does not use is one zeroed element.
    static const T zero{};
    const T* src = data.empty() ? &zero : data.data();
    std::size_t bytes = std::max<std::size_t>(1, data.size()) * sizeof(T);
    cl::Buffer b(dev.context, CL_MEM_READ_ONLY, bytes);
    dev.queue.enqueueWriteBuffer(b, CL_TRUE, 0, bytes, src);
    return b;
}

template <typename T>
cl::Buffer allocate(const ClDevice& dev, std::size_t count)
{
    return cl::Buffer(dev.context, CL_MEM_READ_WRITE, std::max<std::size_t>(1, count) * sizeof(T));
}

} // namespace

DeviceArrays upload_arrays(const ClDevice& dev, const SceneArrays& scene, std::size_t pixels)
{
    DeviceArrays a;
#define PATHCL_UPLOAD(type, name) a.name = upload(dev, scene.name);
    PATHCL_SCENE_ARRAYS(PATHCL_UPLOAD)
#undef PATHCL_UPLOAD
#define PATHCL_ALLOCATE(type, name) a.name = allocate<type>(dev, pixels);
    PATHCL_FILM_ARRAYS(PATHCL_ALLOCATE)
#undef PATHCL_ALLOCATE
    return a;
}

} // namespace pathcl
