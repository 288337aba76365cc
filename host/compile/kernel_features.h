// The one feature mask a render's program is compiled with (kernels/features.h): the
// effects the scene uses and the render's model options. Everything else that depends on
// a feature (which arrays are filled, which tables are built) reads this mask.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

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

// The features `options.specialization` asks for: the scene's, or every scene feature.
KernelFeatures kernel_features(const Scene& scene, const RenderOptions& options);

// The render program's build options: the feature define, and fast math when asked for.
std::string program_build_options(const KernelFeatures& features, const RenderOptions& options);

// The features' names, in mask order ("area-lights", "glossy", ...).
std::vector<std::string> feature_names(std::uint32_t mask);

} // namespace pathcl
