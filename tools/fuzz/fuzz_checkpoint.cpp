// libFuzzer target: the checkpoint reader and its checks (render/checkpoint.h) on
// arbitrary bytes (with their checksum appended unless they end in it), written to a file in a per-process temporary
// directory and read as the checkpoint of a 4 x 4 render; what is read is checked against the layouts of four renders
// (one batch, batches with a short last one, a sample range, adaptive), and a checkpoint that passes is restored into a
// film whose image and error estimate must then be finite: a value that is not, like a crash, a sanitizer report, a
// timeout or running out of memory, is a finding (abort). A pathcl::Error is the expected rejection. Built by
// -DPATHCL_FUZZ=ON, run by tools/fuzz.sh checkpoint SECONDS.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <string>
#include <vector>

#include "common/fnv1a.h"
#include "fuzz_scratch.h"
#include "render/checkpoint.h"
#include "render/render_metadata.h"

namespace {

constexpr std::uint32_t kSide = 4;

pathcl::RenderOptions options(std::uint32_t spp, std::uint32_t batch_spp, bool adaptive, std::uint32_t first,
                              std::uint32_t count)
{
    pathcl::RenderOptions o;
    o.width = o.height = kSide;
    o.sampler = pathcl::SamplerType::Independent;
    o.spp = spp;
    o.batch_spp = batch_spp;
    o.adaptive = adaptive;
    o.target_error = adaptive ? 0.01 : 0.0;
    o.sample_first = first;
    o.sample_count = count;
    return o;
}

void check_image(const pathcl::FilmAccumulator& film)
{
    const pathcl::Image img = film.image(kSide, kSide, 1);
    for (std::size_t i = 0; i < img.rgb.size(); ++i)
        if (!std::isfinite(img.rgb[i]) || !std::isfinite(img.variance[i])) {
            std::fprintf(stderr, "fuzz_checkpoint: a checked checkpoint made a pixel that is not finite\n");
            std::abort();
        }
    (void)pathcl::estimate_error(film, pathcl::SamplerType::Independent);
    (void)film.pixel_samples();
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    // An input whose last 8 bytes are not its checksum gets one appended: a checksum is
    // no defence (anyone can recompute it), and without it the fuzzer would never get
    // past the reader's first check.
    std::vector<std::uint8_t> bytes(data, data + size);
    std::uint64_t stored = 0;
    if (size >= 8)
        std::memcpy(&stored, data + size - 8, 8);
    if (size < 8 || stored != pathcl::fnv1a64(data, size - 8)) {
        const std::uint64_t sum = pathcl::fnv1a64(data, size);
        const auto* p = reinterpret_cast<const std::uint8_t*>(&sum);
        bytes.insert(bytes.end(), p, p + 8);
    }
    const std::string path = fuzz::scratch_directory("checkpoint") + "/checkpoint.bin";
    fuzz::write_file(path, bytes.data(), bytes.size());
    pathcl::RenderCheckpoint cp;
    try {
        cp = pathcl::read_checkpoint(path, kSide * kSide);
    } catch (const std::exception&) {
        return 0; // rejected: what a bad file should get
    }
    const pathcl::RenderOptions layouts[] = {options(16, 0, false, 0, 0), options(40, 16, false, 0, 0),
                                             options(64, 16, false, 16, 32), options(64, 16, true, 0, 0)};
    for (const pathcl::RenderOptions& o : layouts) {
        try {
            const pathcl::BatchPlan plan = pathcl::plan_batches(o);
            pathcl::check_checkpoint(cp, plan, kSide * kSide, o.adaptive);
            pathcl::FilmAccumulator film(kSide * kSide, plan.batch_spp);
            film.restore(cp.film);
            check_image(film);
        } catch (const std::exception&) {
        }
    }
    return 0;
}
