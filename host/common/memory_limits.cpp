#include "common/memory_limits.h"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <sys/resource.h>
#include <unistd.h>

#include "common/error.h"
#include "common/text_fields.h"

namespace pathcl {
namespace {

// A whole number of bytes from a one-line file ("max" or absent: none).
bool read_bytes(const std::string& path, double& bytes)
{
    std::ifstream in(path);
    std::string text;
    if (!(in >> text))
        return false;
    auto v = parse_whole_number(text);
    if (!v)
        return false;
    bytes = static_cast<double>(*v);
    return true;
}

// The room left under the cgroup limits of this process, at every level of its
// hierarchy; false when there is no limit (or no cgroup file system).
bool cgroup_room(double& room, std::string& what)
{
    std::ifstream in("/proc/self/cgroup");
    std::string line;
    bool limited = false;
    while (std::getline(in, line)) {
        // "0::/path" (v2), "N:memory:/path" or "N:...,memory,...:/path" (v1).
        const std::size_t a = line.find(':'), b = a == std::string::npos ? a : line.find(':', a + 1);
        if (b == std::string::npos)
            continue;
        const std::string controllers = line.substr(a + 1, b - a - 1);
        std::string path = line.substr(b + 1);
        const bool v2 = controllers.empty();
        bool memory = v2;
        for (const std::string& c : split_commas(controllers))
            memory = memory || c == "memory";
        if (!memory)
            continue;
        const std::string root = v2 ? "/sys/fs/cgroup" : "/sys/fs/cgroup/memory";
        for (;;) {
            double limit = 0.0, used = 0.0;
            const std::string dir = root + (path == "/" ? "" : path);
            if (read_bytes(dir + (v2 ? "/memory.max" : "/memory.limit_in_bytes"), limit) && limit < 1e18) {
                read_bytes(dir + (v2 ? "/memory.current" : "/memory.usage_in_bytes"), used);
                const double left = std::max(0.0, limit - used);
                if (!limited || left < room) {
                    room = left;
                    what = "the room left under its control group's memory limit (" + gib(limit) + ", " + gib(used) +
                           " in use)";
                    limited = true;
                }
            }
            if (path.empty() || path == "/")
                break;
            const std::size_t slash = path.rfind('/');
            path = slash == 0 || slash == std::string::npos ? "/" : path.substr(0, slash);
        }
    }
    return limited;
}

} // namespace

std::string gib(double bytes)
{
    char text[32];
    std::snprintf(text, sizeof text, "%.2f GiB", bytes / 1073741824.0);
    return text;
}

MemoryLimit memory_limit()
{
    MemoryLimit m;
    const long pages = ::sysconf(_SC_PHYS_PAGES), page = ::sysconf(_SC_PAGE_SIZE);
    m.bytes = pages > 0 && page > 0 ? static_cast<double>(pages) * static_cast<double>(page) : 1e18;
    m.what = "this machine's " + gib(m.bytes) + " of memory";
    struct rlimit as {};
    if (::getrlimit(RLIMIT_AS, &as) == 0 && as.rlim_cur != RLIM_INFINITY) {
        // The address space mapped now (libraries, the OpenCL runtime) counts against it.
        double mapped = 0.0;
        std::ifstream statm("/proc/self/statm");
        if (statm >> mapped)
            mapped *= static_cast<double>(page > 0 ? page : 4096);
        const double left = std::max(0.0, static_cast<double>(as.rlim_cur) - mapped);
        if (left < m.bytes) {
            m.bytes = left;
            m.what = "the room left under the process's address-space limit (ulimit -v " +
                     gib(static_cast<double>(as.rlim_cur)) + ", " + gib(mapped) + " mapped)";
        }
    }
    double room = 0.0;
    std::string what;
    if (cgroup_room(room, what) && room < m.bytes) {
        m.bytes = room;
        m.what = what;
    }
    return m;
}

void check_memory_for(double bytes, const std::string& what)
{
    const MemoryLimit m = memory_limit();
    if (bytes > m.bytes)
        throw Error(what + " needs " + gib(bytes) + " of host memory, more than " + m.what);
}

} // namespace pathcl
