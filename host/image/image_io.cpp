#include "image/image_io.h"

#include <cstring>
#include <filesystem>
#include <fstream>
#include <vector>

#include "common/error.h"
#include "common/staged_files.h"
#include "image/exr_header.h"
#include "image/image_module.h"

namespace pathcl {
namespace {

namespace fs = std::filesystem;

// The reader for a file's first bytes (image_format_of). Given any other file,
// OpenImageIO's ImageInput::open tries every reader it has, and some abort the process on
// a bad file (the RLA reader's "Invalid colour channel type", found by tools/fuzz.sh
// partial on a .exr file that was not one).
const char* readable_format(const std::string& path)
{
    unsigned char b[8] = {};
    std::ifstream in(path, std::ios::binary);
    in.read(reinterpret_cast<char*>(b), sizeof b);
    return image_format_of(b, static_cast<std::size_t>(in.gcount()));
}

// What a file must be before the image module opens it: a regular file (a FIFO would
// block) in a format pathcl reads, and for an EXR, headers that OpenEXR and OpenImageIO
// can trust (image/exr_header.h). Returns the reader's name.
const char* check_readable(const std::string& path)
{
    std::error_code ec;
    if (!fs::is_regular_file(path, ec))
        throw Error(path + (fs::exists(path, ec) ? ": is not a regular file" : ": no such file"));
    const char* format = readable_format(path);
    if (!format)
        throw Error(path + ": not an OpenEXR, Radiance HDR, PNG or JPEG image");
    if (std::strcmp(format, "openexr") == 0)
        check_exr_headers(path);
    return format;
}

// Throws pathcl::Error("path: why") for the module's message `why`, removing `file` first
// when one is named (a write that failed).
void fail_unless_empty(const std::string& why, const std::string& path, const std::string& file = {})
{
    if (why.empty())
        return;
    if (!file.empty()) {
        std::error_code ec;
        fs::remove(file, ec);
    }
    throw Error(path + ": " + one_line(why));
}

} // namespace

const char* image_format_of(const unsigned char* b, std::size_t size)
{
    static const unsigned char png[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    if (size >= 4 && b[0] == 0x76 && b[1] == 0x2f && b[2] == 0x31 && b[3] == 0x01)
        return "openexr";
    if (size >= 2 && b[0] == '#' && b[1] == '?')
        return "hdr";
    if (size >= 8 && std::memcmp(b, png, 8) == 0)
        return "png";
    if (size >= 3 && b[0] == 0xff && b[1] == 0xd8 && b[2] == 0xff)
        return "jpeg";
    return nullptr;
}

void check_output_path(const std::string& path)
{
    std::string ext = lowercase_extension(path);
    if (ext != ".exr" && ext != ".png")
        throw Error(path + ": output must be .exr or .png");
    check_output_location(path);
}

void write_image_file(const std::string& file, const std::string& path, const Image& img,
                      const DisplayTransform& display)
{
    check_output_path(path);
    const std::size_t pixels = static_cast<std::size_t>(img.width) * img.height;
    if (pixels == 0 || img.rgb.size() != pixels * 3 || img.variance.size() != pixels * 3)
        throw Error(path + ": internal error: image buffers do not match " + std::to_string(img.width) + "x" +
                    std::to_string(img.height));
    const bool exr = lowercase_extension(path) == ".exr";
    const int w = static_cast<int>(img.width), h = static_cast<int>(img.height);

    if (exr) {
        const bool counts = !img.samples.empty();
        if (counts && img.samples.size() != pixels)
            throw Error(path + ": internal error: per-pixel sample counts do not match the image");
        if (img.film.size() != pixels * img.film_channels.size())
            throw Error(path + ": internal error: the film part does not match the image");
        fail_unless_empty(image_module().write_exr(file, img), path, file);
        return;
    }
    std::vector<float> shown(img.rgb.size());
    for (std::size_t i = 0; i < shown.size(); ++i)
        shown[i] = display_value(img.rgb[i], display);
    fail_unless_empty(image_module().write_png(file, w, h, shown.data()), path, file);
}

void write_image(const std::string& path, const Image& img, const DisplayTransform& display)
{
    StagedFiles staged;
    write_image_file(staged.stage(path), path, img, display);
    staged.commit();
}

Image read_image(const std::string& path)
{
    const char* format = check_readable(path);
    Image img;
    fail_unless_empty(image_module().read_image(path, format, img), path);
    return img;
}

void read_film_part(const std::string& path, Image& img)
{
    const char* format = check_readable(path);
    fail_unless_empty(image_module().read_film_part(path, format, img), path);
}

} // namespace pathcl
