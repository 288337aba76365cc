// What `pathcl --version` prints: the version, the commit the binary was built from and
// the OpenCL platforms this machine offers.
#pragma once

#include <string>

namespace pathcl::cli {

// "pathcl 0.1.0 (commit 0123456789ab)", then one line per OpenCL platform (or one saying
// there is none); no trailing line break.
std::string version_text();

} // namespace pathcl::cli
