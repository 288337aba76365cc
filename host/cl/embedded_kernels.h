// The kernel tree (kernels/**/*.cl and *.h) compiled into the binary by
// tools/embed_kernels.cmake, each file named by its path relative to kernels/.
#pragma once

#include <vector>

namespace pathcl {

struct EmbeddedFile {
    const char* name; // e.g. "integrator/megakernel.cl"
    const char* text;
};

const std::vector<EmbeddedFile>& embedded_kernel_files();

} // namespace pathcl
