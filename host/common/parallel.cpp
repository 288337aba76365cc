#include "common/parallel.h"

#include <OpenImageIO/parallel.h>

namespace pathcl {

void parallel_chunks(std::size_t count, const std::function<void(std::size_t, std::size_t)>& fn)
{
    // Below this a chunk's work (~20 us) is near the cost of handing it to a thread.
    constexpr std::size_t kMinChunk = 16384;
    if (count <= kMinChunk) {
        if (count > 0)
            fn(0, count);
        return;
    }
    OIIO::parallel_for_chunked(0, static_cast<std::int64_t>(count), static_cast<std::int64_t>(kMinChunk),
                               [&fn](std::int64_t begin, std::int64_t end) {
                                   fn(static_cast<std::size_t>(begin), static_cast<std::size_t>(end));
                               });
}

} // namespace pathcl
