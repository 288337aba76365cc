// The image module, libpathcl_oiio.so: the only code that calls OpenImageIO, loaded on the
// first image read or written. Debian 12's OpenImageIO brings about 260 shared libraries,
// whose loading took each pathcl process about 0.3 s before its first line of work;
// linked this way, a process that touches no image (an error exit, `info`, `devices`,
// most tests) starts in milliseconds (docs/architecture.md).
//
// The module's functions report failure as a message (what went wrong, without the
// file's name, for the caller to prefix), never as an exception of their own; a callback
// passed in may throw through them. The module is built from the same tree as the
// program that loads it; kImageModuleAbi changes whenever this table or Image does, and
// the sizes of both are checked as well, so that a module from another build is refused.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "image/image.h"

namespace pathcl {

constexpr std::uint32_t kImageModuleAbi = 1;

// An image's size and layout from its header, before any pixel is decoded.
struct DecodedShape {
    int width = 0, height = 0, channels = 0;
    int bits = 0; // 8 or 16 per channel
};

struct ImageModule {
    // The EXR of image_io.h to `file`, read back whole once written.
    std::string (*write_exr)(const std::string& file, const Image& image);
    // An 8-bit sRGB PNG of width x height RGB values already through the display
    // transform (linear, clamped to [0, 1] after the sRGB curve), read back once written.
    std::string (*write_png)(const std::string& file, int width, int height, const float* shown_rgb);
    // read_image and read_film_part of image_io.h, given the reader for the file's first
    // bytes ("openexr", "hdr", "png" or "jpeg"), and only that one.
    std::string (*read_image)(const std::string& path, const char* format, Image& image);
    std::string (*read_film_part)(const std::string& path, const char* format, Image& image);
    // Decodes `format` ("png" or "jpeg") from memory, shape.channels values a pixel with
    // alpha unassociated, into pixels8 or (shape.bits 16) pixels16; `admit` sees the shape
    // before anything is decoded.
    std::string (*decode)(const unsigned char* bytes, std::size_t size, const char* format,
                          const std::function<void(const DecodedShape&)>& admit, DecodedShape& shape,
                          std::vector<std::uint8_t>& pixels8, std::vector<std::uint16_t>& pixels16);
};

// The module's table, loaded on the first call from the program's directory (or lib/pathcl
// of the folder above, or the build tree that made the program); throws
// pathcl::Error naming the file when it cannot be loaded.
const ImageModule& image_module();

// Runs `prelude` just before the module is first loaded, whichever image it is loaded
// for (a scene's texture, an output): rendering commands load the OpenCL implementations
// there (load_opencl_platforms), before the libraries the module brings. Set before any
// image is read or written.
void set_image_module_prelude(std::function<void()> prelude);

} // namespace pathcl

// The one symbol the module exports: its table, or nullptr where `abi` or the sizes the
// caller has of Image and ImageModule are not its own.
extern "C" const pathcl::ImageModule* pathcl_image_module(std::uint32_t abi, std::size_t image_size,
                                                          std::size_t module_size);
