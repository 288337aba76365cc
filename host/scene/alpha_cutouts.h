// Which triangles glTF alpha can cut (alphaMode MASK or BLEND): the kernels ask about
// alpha only on those (Triangle.v0.w = TRIANGLE_ALPHA_TESTED), and a scene without any
// is compiled without the alpha code (FEATURE_ALPHA). Exporters often mark opaque
// materials BLEND; a triangle whose alpha cannot fall short of opaque anywhere (the
// factor times the least alpha of its base colour texture and of its vertex colours) is
// left opaque, so those cost nothing.
#pragma once

#include <vector>

#include "scene/scene.h"

namespace pathcl {

// One flag per scene triangle.
std::vector<bool> alpha_tested_triangles(const Scene& scene);

} // namespace pathcl
