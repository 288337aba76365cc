// Reading an environment map's image at load time (from the scene's extras or a front
// end's override), so that a Scene holds everything a render needs.
#pragma once

#include <string>

#include "scene/scene.h"

namespace pathcl {

// Sets env to the equirectangular image at `path` (EXR, HDR or any image OpenImageIO
// reads): present, path, size and texels; strength and rotation are kept. Throws
// pathcl::Error naming the file when it cannot be read.
void read_environment_image(SceneEnvironment& env, const std::string& path);

} // namespace pathcl
