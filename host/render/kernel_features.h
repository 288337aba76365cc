// The one feature mask a render's program is compiled with (kernels/features.h): the
// effects the scene uses and the render's model options. Everything else that depends on
// a feature (which arrays are filled, which tables are built) reads this mask.
#pragma once

#include <cstdint>
#include <string>

#include "features.h"
#include "render/render_options.h"
#include "scene/scene.h"

namespace pathcl {

struct KernelFeatures {
    std::uint32_t mask = 0; // FEATURE_* bits

    bool has(std::uint32_t feature) const { return (mask & feature) != 0; }
    // The build option that carries the mask: -DPATHCL_FEATURES=<mask>u.
    std::string define() const;
};

KernelFeatures kernel_features(const Scene& scene, const RenderOptions& options);

} // namespace pathcl
