// The render options device tests start from: the library's defaults with the
// independent sampler, whose per-sample variance is the variance of the mean times spp.
// The tests' error bounds and the committed references assume that; the tests that check
// the other samplers set them explicitly.
#pragma once

#include "render/render_options.h"

namespace pathcl::test {

inline RenderOptions independent_options()
{
    RenderOptions o;
    o.sampler = SamplerType::Independent;
    return o;
}

} // namespace pathcl::test
