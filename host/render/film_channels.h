// A film's exact state (FilmAccumulator::State) as the 32-bit channels of an EXR's "film"
// part (Image::film_channels, Image::film), and back: what a partial render carries so
// that `pathcl merge` can add it to the others exactly. Per pixel 74 channels, 296 bytes:
// the exact sums of L and L^2 and of the whole batches' means and their squares, R, G and
// B each in six 32-bit words ("sum.R.0" the least significant), then "samples" and
// "pixel_batches". The state's two scalars go into the image's metadata.
#pragma once

#include <string>

#include "image/image.h"
#include "render/film.h"

namespace pathcl {

void store_film_state(const FilmAccumulator::State& state, Image& image);

// Throws pathcl::Error naming `path` when a channel or a metadata entry is missing or
// malformed.
FilmAccumulator::State load_film_state(const Image& image, const std::string& path);

} // namespace pathcl
