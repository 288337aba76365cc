// Per-pixel host work on every core: the film's readback sums, totals and image
// (render/film.*) take about 0.15 s a million pixels on one core, which a GPU waits for.
#pragma once

#include <cstddef>
#include <functional>

namespace pathcl {

// Calls fn(begin, end) on disjoint chunks that cover [0, count), on OpenImageIO's thread
// pool, and returns when all have run; inline, as one chunk, when count is small. For
// loops whose elements are independent: each element's arithmetic is what a serial loop
// does, so the results are the same bit for bit however the chunks fall. fn must not throw.
void parallel_chunks(std::size_t count, const std::function<void(std::size_t begin, std::size_t end)>& fn);

} // namespace pathcl
