// Image files, read and written by OpenImageIO in the image module (image/image_module.h). EXR: linear float RGB plus
// the per-sample variance as channels variance.R/G/B, the sample count as attribute "pathcl:spp" (and, where pixels
// differ, per pixel as channel "samples"), Image::metadata as string attributes
// "pathcl:<key>", and a partial render's film state as a second part. PNG: the same
// radiance through a DisplayTransform (exposure and tone curve; by default clamped to
// [0, 1]), sRGB-encoded to 8 bits. Files are written under a temporary name in the target
// directory and renamed, so a failed write never leaves a partial file and never destroys
// an existing one.
#pragma once

#include <cstddef>
#include <string>

#include "image/display.h"
#include "image/image.h"

namespace pathcl {

// Throws pathcl::Error unless `path` ends in .exr or .png and its directory exists.
void check_output_path(const std::string& path);

void write_image(const std::string& path, const Image& image, const DisplayTransform& display = {});

// The image for `path` written to `file` (a temporary name from StagedFiles: the caller
// renames it), in the format path's extension names; `display` applies to PNG only.
void write_image_file(const std::string& file, const std::string& path, const Image& image,
                      const DisplayTransform& display = {});

// Images read whole (an environment map, a render to compare) may have at most 2^27
// pixels (16384 x 8192, 1.5 GiB as float RGB); the size is checked from the header.
constexpr std::size_t kMaxImagePixels = std::size_t(1) << 27;
// And at most this much as float, all channels: a row (65536 pixels of 4 channels, or
// 4096 of 64) and the whole image.
constexpr std::size_t kMaxImageRowBytes = std::size_t(1) << 20;
constexpr std::size_t kMaxImageBytes = std::size_t(1) << 31;

// The OpenImageIO format plugin an image's first bytes name: "openexr", "hdr" (Radiance),
// "png" or "jpeg"; nullptr for anything else. The only readers pathcl lets OpenImageIO use.
const char* image_format_of(const unsigned char* bytes, std::size_t size);

// Reads an EXR written by write_image (variance channels optional: zero if absent), or
// any image OpenImageIO reads, from a regular file of at most kMaxImagePixels pixels.
// The film part of a partial render is not read (read_film_part).
Image read_image(const std::string& path);

// A film part is read whole too: at most this many channels and bytes (a 4K partial
// render's is 2.5 GB).
constexpr std::size_t kMaxFilmChannels = 256;
constexpr std::size_t kMaxFilmBytes = std::size_t(1) << 33;
// It is read a band of rows at a time (a row of tiles, when tiled) of at most this many bytes.
constexpr std::size_t kMaxFilmBandBytes = std::size_t(1) << 28;

// Reads an EXR's "film" part (Image::film_channels, Image::film) into `image`, which
// read_image returned for the same path, stored as scanlines or as tiles; throws
// pathcl::Error naming the path when the file has none or it does not match the image.
void read_film_part(const std::string& path, Image& image);

} // namespace pathcl
