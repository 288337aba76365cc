// The source of a device program, assembled from the kernel tree embedded in the binary
// (host/cl/embedded_kernels.h). Kernel files include what they use with
// `#include "dir/file.cl"` (paths relative to kernels/); assembly replaces each include by
// the file's text the first time it is reached and drops it after that (as if every file
// had an include guard), and emits #line directives so that compiler diagnostics name
// the real file and line. The order in which files are embedded therefore never matters.
#pragma once

#include <string>
#include <vector>

namespace pathcl {

// A test-only mutation of a kernel file: its one occurrence of `find` replaced by
// `replace`, for the tests that prove a check fails on a deliberately broken kernel (no
// production kernel file holds test branches). A patch whose text is not found exactly
// once is an error, so a patch cannot silently stop applying.
struct KernelPatch {
    std::string file; // path under kernels/, e.g. "closure/bsdf_eval.cl"
    std::string find;
    std::string replace;
};

struct ProgramSource {
    std::string root = "program.cl"; // the kernel file to start from, or the name of `text`
    std::string text;                // when not empty: the root's own source (test kernels)
    std::vector<KernelPatch> patches;
    // false: compile even when pathcl's binary cache (or the driver's) has it, and store
    // nothing (cold timings).
    bool use_cache = true;
};

// The assembled source; throws pathcl::Error for an include of a file that is not in the
// tree, an include cycle, or a patch that does not apply.
std::string assemble_kernel_source(const ProgramSource& source);

// Every embedded kernel file's path under kernels/.
std::vector<std::string> kernel_file_names();

} // namespace pathcl
