#include "cli/version.h"

#include "cl/cl_runtime.h"

#ifndef PATHCL_VERSION
#error "PATHCL_VERSION is defined by CMakeLists.txt (the project's version)"
#endif
#ifndef PATHCL_COMMIT
#error "PATHCL_COMMIT is defined by CMakeLists.txt (the source tree's git commit, or unknown)"
#endif

namespace pathcl::cli {

std::string version_text()
{
    std::string text = "pathcl " PATHCL_VERSION " (commit " PATHCL_COMMIT ")\n";
    const std::vector<PlatformInfo> platforms = list_platforms();
    if (platforms.empty())
        return text + "OpenCL platforms: none found (an OpenCL driver, such as pocl-opencl-icd, provides one)";
    text += "OpenCL platforms:";
    for (const PlatformInfo& p : platforms)
        text += "\n  " + p.name + " | " + p.vendor + " | " + p.version + " | " + std::to_string(p.devices) +
                (p.devices == 1 ? " device" : " devices");
    return text;
}

} // namespace pathcl::cli
