// A render's state between two passes, written to disk so that `render --resume` continues
// where a render stopped (Ctrl-C, a time budget, kill -9 after the last checkpoint) and
// ends with the image the uninterrupted render would have given, bit for bit: the double
// sums of the whole batches done, and each device's own float film of the batch in
// progress, exactly as the device holds it. The key names everything the image depends
// on (scene contents, options, batch layout, devices); a checkpoint with another key is
// refused. The file is this machine's binary layout (little-endian, IEEE), with a
// checksum; it is written atomically.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "render/batches.h"
#include "render/film.h"
#include "types.h"

namespace pathcl {

struct RenderCheckpoint {
    std::string key;
    std::uint32_t batch = 0;    // the batch in progress
    std::uint32_t pass = 0;     // its passes done (0: it has not started)
    std::uint32_t spp_done = 0; // sample indices per pixel done, over all batches
    double samples = 0.0;       // camera samples done (for the samples/s of the summary)
    FilmAccumulator::State film;
    std::vector<std::vector<FilmPixel>> device_films; // per device, the batch in progress
    std::vector<std::vector<pcl_uint>> device_bad;    // per device, its bad-sample counts
    std::vector<pcl_uint> active;                     // adaptive sampling's mask, or empty
};

// Writes `cp` to `path` atomically (a temporary beside it, flushed to disk, renamed):
// the previous checkpoint stays whole until the new one is. Throws pathcl::Error naming
// the path on failure, leaving no temporary file.
void write_checkpoint(const std::string& path, const RenderCheckpoint& cp);

// The key of a checkpoint is at most this long (a render's is a few hundred bytes).
constexpr std::size_t kMaxCheckpointKeyBytes = 1 << 16;

// The most bytes a checkpoint of a render of `pixels` pixels can have: more is not one
// of its checkpoints.
std::uint64_t max_checkpoint_bytes(std::size_t pixels);

// Reads the checkpoint of a render of `pixels` pixels (a file larger than such a
// checkpoint can be is refused from its size, before it is read); throws pathcl::Error
// naming the path when it is not one, is truncated or its checksum fails.
RenderCheckpoint read_checkpoint(const std::string& path, std::size_t pixels);

// The first "; "-separated field in which two render keys differ, as an error says it:
// its "seed 0", this render's "seed 7".
std::string key_difference(const std::string& checkpoint_key, const std::string& render_key);

// Checks that `cp` is a state of the render laid out by `plan` over `pixels` pixels
// (adaptive: with a mask of active pixels) before anything of it is used: the batch and
// pass within the plan's, the counters as those make them, the films of the image's size
// with finite values and counts within the samples taken. A checkpoint is a file anyone
// may have written (its checksum guards against damage, not against intent). Throws
// ParameterError("resume", ...) saying what does not fit.
void check_checkpoint(const RenderCheckpoint& cp, const BatchPlan& plan, std::size_t pixels, bool adaptive);

} // namespace pathcl
