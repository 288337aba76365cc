// How much memory this process may still take: the least of the machine's physical
// memory, the room left under its address-space limit (RLIMIT_AS, `ulimit -v`) and the
// room left under its control group's memory limit (cgroup v2 memory.max, v1
// memory.limit_in_bytes, at every level of its hierarchy). Admission checks (a film, a
// scene's triangles and instances, its textures) compare what they will allocate with
// this, so that a limit a service sets ends a command with an error that names it, not
// with std::bad_alloc or the out-of-memory killer.
#pragma once

#include <string>

namespace pathcl {

struct MemoryLimit {
    double bytes = 0.0; // what may still be allocated
    std::string what;   // the limit that sets it, for an error: "this machine's 23.4 GiB of memory"
};

MemoryLimit memory_limit();

// Throws pathcl::Error "WHAT needs N GiB of host memory, more than LIMIT" when `bytes`
// exceeds memory_limit().
void check_memory_for(double bytes, const std::string& what);

// "1.25 GiB".
std::string gib(double bytes);

} // namespace pathcl
