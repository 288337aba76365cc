#include "common/parallel.h"

#include <atomic>

#include "common/shared_work.h"

namespace pathcl {
namespace {

std::atomic<unsigned> parallel_threads{0};

} // namespace

void parallel_chunks(std::size_t count, const std::function<void(std::size_t, std::size_t)>& fn)
{
    // Below this a chunk's work (~20 us) is near the cost of handing it to a thread.
    constexpr std::size_t kMinChunk = 16384;
    if (count <= kMinChunk) {
        if (count > 0)
            fn(0, count);
        return;
    }
    SharedWork::for_pieces(count, kMinChunk, parallel_threads.load(std::memory_order_relaxed), fn);
}

void set_parallel_threads(unsigned threads)
{
    parallel_threads.store(threads, std::memory_order_relaxed);
}

} // namespace pathcl
