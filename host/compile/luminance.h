// Luminance of linear Rec. 709 RGB (the weights of its Y row): what the light samplers and
// --triangle-sampling auto weigh a light's power by.
#pragma once

#include <glm/vec3.hpp>

namespace pathcl {

inline double luminance(const glm::vec3& c)
{
    return 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z;
}

} // namespace pathcl
