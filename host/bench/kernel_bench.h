// Kernel microbenchmarks (`pathcl bench --kernels`): each stage of a render timed on its
// own on one device, in its own unit: camera rays, closest-hit and any-hit traversal of
// primary, diffuse-bounce and shadow rays, whole path samples, film accumulation, the BVH
// build, and the program build cold and from the cache.
#pragma once

#include <string>
#include <vector>

#include "render/render_options.h"
#include "scene/scene.h"

namespace pathcl {

struct KernelFigure {
    std::string stage; // e.g. "closest hit, diffuse rays"
    std::string unit;  // e.g. "Mrays/s"
    double min = 0.0, median = 0.0, max = 0.0;
};

// Times every stage `runs` times (after one warm-up) at options' image size, sampler and
// bounces, on options.devices[0]; one run of a kernel is `passes` launches.
std::vector<KernelFigure> bench_kernels(const Scene& scene, const RenderOptions& options, int runs, int passes = 8);

} // namespace pathcl
