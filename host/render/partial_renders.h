// Sample ranges: one render split by its sample indices over processes or machines
// (`pathcl render --sample-range FIRST:COUNT`, e.g. the tasks of a Slurm array) and merged
// back (`pathcl merge`). A range is made of whole batches (render/batches.h) and its EXR
// carries its film's exact state (render/film_channels.h); the states add exactly
// (render/exact_sum.h), so merging the ranges of a render in any order and grouping gives
// the uninterrupted render's image bit for bit, on one kind of device.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "image/image.h"

namespace pathcl {

struct SampleRange {
    std::uint32_t first = 0, count = 0;
};

// "FIRST:COUNT" (COUNT >= 1); throws pathcl::Error "--sample-range: ..." otherwise.
SampleRange parse_sample_range(const std::string& text);
// "0:256,512:256": the ranges in order, neighbours joined.
std::string format_sample_ranges(std::vector<SampleRange> ranges);

// Reads the partial renders at `paths` and adds them. Each must be a range of the same
// render (the same scene, size, seed, options and spp), finished (not stopped early), and
// no two may share a sample. When their ranges make the whole render the result is its
// image (without a film part); otherwise a partial render of their union, itself
// mergeable. Throws pathcl::Error naming the file at fault.
Image merge_partial_renders(const std::vector<std::string>& paths);

} // namespace pathcl
