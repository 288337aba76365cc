// Per-pixel host work on every core: the film's readback sums, totals and image
// (render/film.*) take about 0.15 s a million pixels on one core, which a GPU waits for.
#pragma once

#include <cstddef>
#include <functional>

namespace pathcl {

// Calls fn(begin, end) on disjoint chunks that cover [0, count), on every core (the
// threads of a SharedWork, common/shared_work.h), and returns when all have run; inline,
// as one chunk, when count is small. For loops whose elements are independent: each
// element's arithmetic is what a serial loop does, so the results are the same bit for
// bit however the chunks fall. fn must not throw.
void parallel_chunks(std::size_t count, const std::function<void(std::size_t begin, std::size_t end)>& fn);

// The threads parallel_chunks uses from now on (0, the default: one a core).
void set_parallel_threads(unsigned threads);

} // namespace pathcl
