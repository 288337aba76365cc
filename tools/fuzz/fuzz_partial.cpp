// libFuzzer target: partial renders (render/partial_renders.h) on arbitrary bytes,
// written to an EXR file in a per-process temporary directory and merged as `pathcl
// merge` merges them: the image part, its metadata, the film part (scanlines or tiles)
// and its state, each checked before use. A merge that succeeds must give finite pixels;
// one that does not, like a crash, a sanitizer report, a timeout or running out of
// memory, is a finding (abort). A pathcl::Error is the expected rejection. Built by
// -DPATHCL_FUZZ=ON, run by tools/fuzz.sh partial SECONDS.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

#include "fuzz_scratch.h"
#include "render/partial_renders.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const std::string path = fuzz::scratch_directory("partial") + "/partial.exr";
    fuzz::write_file(path, data, size);
    try {
        const pathcl::Image merged = pathcl::merge_partial_renders({path});
        for (std::size_t i = 0; i < merged.rgb.size(); ++i)
            if (!std::isfinite(merged.rgb[i]) || !std::isfinite(merged.variance[i])) {
                std::fprintf(stderr, "fuzz_partial: a merged partial render has a pixel that is not finite\n");
                std::abort();
            }
    } catch (const std::exception&) {
        // Rejected: what a bad file should get.
    }
    try {
        // The same samples twice: always refused, never counted twice.
        (void)pathcl::merge_partial_renders({path, path});
        std::fprintf(stderr, "fuzz_partial: a partial render merged with itself\n");
        std::abort();
    } catch (const std::exception&) {
    }
    std::remove(path.c_str());
    return 0;
}
