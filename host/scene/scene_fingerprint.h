// A 64-bit fingerprint of everything in a loaded scene that can change a render
// (geometry, attributes, materials, textures, lights, environment, camera): equal scenes
// give equal fingerprints on every machine. It keys cached results, such as `converge`'s
// reference image, so that editing the scene or any file it reads invalidates them.
#pragma once

#include <cstdint>
#include <string>

#include "scene/scene.h"

namespace pathcl {

std::uint64_t scene_fingerprint(const Scene& scene);

// The fingerprint as 16 hex digits.
std::string scene_fingerprint_hex(const Scene& scene);

} // namespace pathcl
