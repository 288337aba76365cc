// A scene compiled for the device as a default render would compile it, for tests that
// look at the arrays the kernels get.
#pragma once

#include "compile/compile_scene.h"
#include "compile/kernel_features.h"

namespace pathcl::test {

inline CompiledScene compile_default(const Scene& scene)
{
    return compile_scene(scene, kernel_features(scene, RenderOptions{}));
}

} // namespace pathcl::test
