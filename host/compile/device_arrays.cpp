#include "compile/device_arrays.h"

#include <algorithm>

#include "common/error.h"
#include "common/memory_limits.h"

namespace pathcl {
namespace {

template <typename T, typename Allocator>
cl::Buffer upload(const ClDevice& dev, const std::vector<T, Allocator>& data)
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

void check_device_memory(const ClDevice& dev, const SceneArrays& scene, std::size_t pixels)
{
    // In double: pixels x bytes per pixel may not fit 64 bits for an absurd size.
    double scene_bytes = 0.0, film_bytes = 0.0, largest = 0.0;
    const char* largest_name = "";
    auto add = [&](double& total, double bytes, const char* name) {
        total += bytes;
        if (bytes > largest) {
            largest = bytes;
            largest_name = name;
        }
    };
#define PATHCL_SCENE_BYTES(type, name)                                                                                 \
    add(scene_bytes, static_cast<double>(std::max<std::size_t>(1, scene.name.size())) * sizeof(type), #name);
    PATHCL_SCENE_ARRAYS(PATHCL_SCENE_BYTES)
#undef PATHCL_SCENE_BYTES
#define PATHCL_FILM_BYTES(type, name) add(film_bytes, static_cast<double>(pixels) * sizeof(type), #name);
    PATHCL_FILM_ARRAYS(PATHCL_FILM_BYTES)
#undef PATHCL_FILM_BYTES
    const DeviceInfo& d = dev.info;
    std::string device = "device " + std::to_string(d.index) + " (" + d.name + ")";
    std::string needs = "the render needs " + gib(scene_bytes + film_bytes) + " (the film of " +
                        std::to_string(pixels) + " pixels " + gib(film_bytes) + ", the scene " + gib(scene_bytes) + ")";
    if (scene_bytes + film_bytes > static_cast<double>(d.global_memory))
        throw Error(device + ": " + needs + ", more than its " + gib(static_cast<double>(d.global_memory)) +
                    " of memory");
    if (largest > static_cast<double>(d.max_allocation))
        throw Error(device + ": " + needs + "; its largest array, " + largest_name + ", needs " + gib(largest) +
                    ", more than the " + gib(static_cast<double>(d.max_allocation)) + " the device allocates at once");
}

DeviceArrays upload_arrays(const ClDevice& dev, const SceneArrays& scene, std::size_t pixels)
{
    check_device_memory(dev, scene, pixels);
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
