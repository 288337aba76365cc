// Seconds of the steady clock since a time point: how pathcl, its benchmarks and its
// tools time what they run.
#pragma once

#include <chrono>

namespace pathcl {

inline double seconds_since(std::chrono::steady_clock::time_point t)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

} // namespace pathcl
