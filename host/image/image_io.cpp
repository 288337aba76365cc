#include "image/image_io.h"

#include <algorithm>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <memory>
#include <unistd.h>

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imageio.h>

#include "common/error.h"
#include "common/muted_stderr.h"
#include "common/staged_files.h"
#include "image/exr_header.h"

namespace pathcl {
namespace {

namespace fs = std::filesystem;
using OIIO::ImageBuf;
using OIIO::ImageSpec;
using OIIO::TypeDesc;

// Whether `file` is on disk whole (its first `parts` parts): flushed (fsync reports a write the kernel could not
// complete) and read back to the last pixel. The image writers do not all report a failed
// write (libpng's can leave a 0-byte file and succeed), so the renamed file is never
// trusted blindly.
bool written_completely(const std::string& file, int width, int height, int parts)
{
    MutedStderr muted;
    int fd = ::open(file.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0)
        return false;
    bool synced = ::fsync(fd) == 0;
    ::close(fd);
    if (!synced)
        return false;
    auto in = OIIO::ImageInput::open(file);
    if (!in || in->spec().width != width || in->spec().height != height)
        return false;
    bool ok = true;
    for (int part = 0; part < parts && ok; ++part) {
        ok = in->seek_subimage(part, 0);
        if (!ok)
            break;
        std::vector<float> px(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) *
                              static_cast<std::size_t>(in->spec().nchannels));
        ok = in->read_image(part, 0, 0, in->spec().nchannels, TypeDesc::FLOAT, px.data());
    }
    (void)in->geterror(); // clear OIIO's per-thread error, so it is not printed later
    return ok;
}

// The reader for a file's first bytes (image_format_of). Given any other file,
// ImageInput::open tries every reader it has, and some abort the process on a bad file
// (the RLA reader's "Invalid colour channel type", found by tools/fuzz.sh partial on a
// .exr file that was not one).
const char* readable_format(const std::string& path)
{
    unsigned char b[8] = {};
    std::ifstream in(path, std::ios::binary);
    in.read(reinterpret_cast<char*>(b), sizeof b);
    return image_format_of(b, static_cast<std::size_t>(in.gcount()));
}

// Opens an image to be read whole: a regular file (a FIFO would block) of at most
// kMaxImagePixels, kMaxImageRowBytes a row and kMaxImageBytes in all, checked from its
// header before any pixel is decoded. Read through
// ImageInput, not ImageBuf: ImageBuf goes through OIIO's shared image cache, which keeps
// the header of a file by name, so a file that changed since was decoded into a buffer
// sized by the stale header (a heap overflow found by tools/fuzz.sh images).
std::unique_ptr<OIIO::ImageInput> open_image(const std::string& path)
{
    std::error_code ec;
    if (!fs::is_regular_file(path, ec))
        throw Error(path + (fs::exists(path, ec) ? ": is not a regular file" : ": no such file"));
    const char* format = readable_format(path);
    if (!format)
        throw Error(path + ": not an OpenEXR, Radiance HDR, PNG or JPEG image");
    if (std::strcmp(format, "openexr") == 0)
        check_exr_headers(path); // what OpenEXR and OpenImageIO would trust (image/exr_header.h)
    // That format's reader alone, never OpenImageIO's search through all of them.
    std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::create(format);
    ImageSpec opened;
    if (!in || !in->open(path, opened)) {
        const std::string why = in ? in->geterror() : OIIO::geterror();
        throw Error(path + ": cannot read image: " + one_line(why));
    }
    const ImageSpec& spec = in->spec();
    if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0 ||
        static_cast<std::size_t>(spec.width) > kMaxImagePixels / static_cast<std::size_t>(spec.height))
        throw Error(path + ": unsupported image size " + std::to_string(spec.width) + "x" +
                    std::to_string(spec.height) + " (at most " + std::to_string(kMaxImagePixels) + " pixels)");
    // OpenImageIO reads rows in chunks and sized its buffer for 256 rows whatever the
    // image's height: a 1-row EXR 8.6 million pixels wide asked for 26 GB (found by
    // tools/fuzz.sh images). So a row is bounded, and so is the whole image at every
    // channel decoded as float.
    const std::size_t row_bytes = static_cast<std::size_t>(spec.width) * static_cast<std::size_t>(spec.nchannels) * 4;
    if (row_bytes > kMaxImageRowBytes || static_cast<std::size_t>(spec.height) > kMaxImageBytes / row_bytes)
        throw Error(path + ": unsupported image size " + std::to_string(spec.width) + "x" +
                    std::to_string(spec.height) + " with " + std::to_string(spec.nchannels) + " channels (at most " +
                    std::to_string(kMaxImageRowBytes) + " bytes a row and " + std::to_string(kMaxImageBytes) +
                    " in all, as float)");
    return in;
}

// The EXR: part 0 the image (float), part 1 "film" (uint32) where the image has one.
void write_exr(const std::string& file, const std::string& path, const Image& img)
{
    const std::size_t pixels = static_cast<std::size_t>(img.width) * img.height;
    const int w = static_cast<int>(img.width), h = static_cast<int>(img.height);
    const bool counts = !img.samples.empty();
    if (counts && img.samples.size() != pixels)
        throw Error(path + ": internal error: per-pixel sample counts do not match the image");
    const std::size_t film_channels = img.film_channels.size();
    if (img.film.size() != pixels * film_channels)
        throw Error(path + ": internal error: the film part does not match the image");
    const int channels = counts ? 7 : 6;
    std::vector<ImageSpec> specs(film_channels > 0 ? 2 : 1);
    ImageSpec& spec = specs[0];
    spec = ImageSpec(w, h, channels, TypeDesc::FLOAT);
    spec.channelnames = {"R", "G", "B", "variance.R", "variance.G", "variance.B"};
    if (counts)
        spec.channelnames.push_back("samples");
    spec.attribute("compression", "zip");
    spec.attribute("pathcl:spp", static_cast<int>(img.spp));
    for (const auto& [key, value] : img.metadata)
        spec.attribute("pathcl:" + key, value);
    if (film_channels > 0) {
        spec.attribute("name", "image");
        specs[1] = ImageSpec(w, h, static_cast<int>(film_channels), TypeDesc::UINT);
        specs[1].channelnames = img.film_channels;
        specs[1].attribute("compression", "zip");
        specs[1].attribute("name", "film");
    }
    std::vector<float> px(pixels * static_cast<std::size_t>(channels));
    for (std::size_t i = 0; i < pixels; ++i) {
        float* p = &px[i * static_cast<std::size_t>(channels)];
        for (int c = 0; c < 3; ++c) {
            p[c] = img.rgb[i * 3 + c];
            p[3 + c] = img.variance[i * 3 + c];
        }
        if (counts)
            p[6] = static_cast<float>(img.samples[i]); // exact below 2^24
    }
    std::string why;
    {
        auto out = OIIO::ImageOutput::create(file);
        bool ok = out && out->open(file, static_cast<int>(specs.size()), specs.data()) &&
                  out->write_image(TypeDesc::FLOAT, px.data());
        if (ok && film_channels > 0)
            ok = out->open(file, specs[1], OIIO::ImageOutput::AppendSubimage) &&
                 out->write_image(TypeDesc::UINT, img.film.data());
        if (out && !out->close())
            ok = false;
        if (!ok)
            why = out ? one_line(out->geterror()) : one_line(OIIO::geterror());
    }
    if (why.empty() && !written_completely(file, w, h, static_cast<int>(specs.size())))
        why = "the file on disk is incomplete (is the disk full?)";
    if (!why.empty()) {
        std::error_code ec;
        fs::remove(file, ec);
        throw Error(path + ": cannot write: " + why);
    }
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
        write_exr(file, path, img);
        return;
    }
    ImageBuf out;
    {
        std::vector<float> shown(img.rgb.size());
        for (std::size_t i = 0; i < shown.size(); ++i)
            shown[i] = display_value(img.rgb[i], display);
        ImageBuf linear(ImageSpec(w, h, 3, TypeDesc::FLOAT));
        linear.set_pixels(OIIO::ROI::All(), TypeDesc::FLOAT, shown.data());
        ImageBuf srgb = OIIO::ImageBufAlgo::colorconvert(linear, "linear", "sRGB");
        out = OIIO::ImageBufAlgo::clamp(srgb, 0.0f, 1.0f);
        out.set_write_format(TypeDesc::UINT8);
    }
    if (out.has_error())
        throw Error(path + ": cannot prepare image: " + out.geterror());

    if (!out.write(file) || !written_completely(file, w, h, 1)) {
        std::string why = out.has_error() ? out.geterror() : "the file on disk is incomplete (is the disk full?)";
        std::error_code ec;
        fs::remove(file, ec);
        throw Error(path + ": cannot write: " + why);
    }
}

void write_image(const std::string& path, const Image& img, const DisplayTransform& display)
{
    StagedFiles staged;
    write_image_file(staged.stage(path), path, img, display);
    staged.commit();
}

Image read_image(const std::string& path)
{
    MutedStderr muted; // image libraries' own lines; their errors reach us by geterror()
    std::unique_ptr<OIIO::ImageInput> in = open_image(path);
    const ImageSpec spec = in->spec();
    auto channel = [&](const char* name) { return spec.channelindex(name); };
    int r = channel("R"), g = channel("G"), b = channel("B");
    if (r < 0 || g < 0 || b < 0)
        throw Error(path + ": image has no R, G, B channels");
    int vr = channel("variance.R"), vg = channel("variance.G"), vb = channel("variance.B");
    int counts = channel("samples");
    Image img;
    img.width = static_cast<std::uint32_t>(spec.width);
    img.height = static_cast<std::uint32_t>(spec.height);
    img.spp = static_cast<std::uint32_t>(spec.get_int_attribute("pathcl:spp", 0));
    for (const OIIO::ParamValue& p : spec.extra_attribs) {
        std::string name = p.name().string();
        if (name.rfind("pathcl:", 0) == 0 && name != "pathcl:spp" && p.type() == TypeDesc::STRING)
            img.metadata[name.substr(7)] = p.get_string();
    }
    std::size_t n = static_cast<std::size_t>(spec.width) * spec.height;
    std::vector<float> px(n * static_cast<std::size_t>(spec.nchannels));
    if (!in->read_image(0, 0, 0, spec.nchannels, TypeDesc::FLOAT, px.data()))
        throw Error(path + ": cannot read image: " + one_line(in->geterror()));
    img.rgb.resize(n * 3);
    img.variance.assign(n * 3, 0.0f);
    if (counts >= 0)
        img.samples.resize(n);
    const int rgb[3] = {r, g, b}, var[3] = {vr, vg, vb};
    for (std::size_t i = 0; i < n; ++i) {
        const float* p = &px[i * static_cast<std::size_t>(spec.nchannels)];
        for (int c = 0; c < 3; ++c) {
            img.rgb[i * 3 + c] = p[rgb[c]];
            if (var[c] >= 0)
                img.variance[i * 3 + c] = p[var[c]];
        }
        if (counts >= 0) {
            float k = p[counts];
            if (!(k >= 0.0f && k <= 16777216.0f))
                throw Error(path + ": pixel " + std::to_string(i) + " has a bad sample count");
            img.samples[i] = static_cast<std::uint32_t>(k);
        }
    }
    return img;
}

void read_film_part(const std::string& path, Image& img)
{
    MutedStderr muted;
    std::unique_ptr<OIIO::ImageInput> in = open_image(path);
    if (!in->seek_subimage(1, 0))
        throw Error(path + ": has no film part: not a partial render (--sample-range)");
    const ImageSpec& spec = in->spec();
    if (spec.width != static_cast<int>(img.width) || spec.height != static_cast<int>(img.height) ||
        spec.get_string_attribute("name") != "film" || spec.nchannels <= 0)
        throw Error(path + ": its film part does not match its image");
    const std::size_t pixels = static_cast<std::size_t>(img.width) * img.height;
    const std::size_t channels = static_cast<std::size_t>(spec.nchannels);
    if (channels > kMaxFilmChannels || pixels > kMaxFilmBytes / 4 / channels)
        throw Error(path + ": its film part is too large (" + std::to_string(channels) + " channels of " +
                    std::to_string(pixels) + " pixels; at most " + std::to_string(kMaxFilmBytes) + " bytes)");
    // Written by pathcl: scanlines whose data window starts at the origin. A tool that
    // re-saves the file may have tiled it (oiiotool --tile): tiles are read as well.
    if (spec.deep || spec.depth != 1 || spec.x != 0 || spec.y != 0 || spec.z != 0)
        throw Error(path + ": its film part is not a flat image whose data window starts at 0,0 (" +
                    (spec.deep ? std::string("deep data")
                               : "origin " + std::to_string(spec.x) + "," + std::to_string(spec.y) + "," +
                                     std::to_string(spec.z) + ", depth " + std::to_string(spec.depth)) +
                    ")");
    const bool tiled = spec.tile_width > 0;
    if (tiled && (spec.tile_height <= 0 || spec.tile_depth > 1 ||
                  static_cast<std::size_t>(spec.tile_height) * img.width * channels * 4 > kMaxFilmBandBytes))
        throw Error(path + ": its film part has tiles of " + std::to_string(spec.tile_width) + "x" +
                    std::to_string(spec.tile_height) + "x" + std::to_string(spec.tile_depth) +
                    " pixels, too large a row of them to read (at most " + std::to_string(kMaxFilmBandBytes) +
                    " bytes)");
    img.film_channels = spec.channelnames;
    img.film.assign(pixels * channels, 0u);
    // A band of rows at a time (a row of tiles): what OpenImageIO buffers stays small
    // whatever the width.
    const int rows = tiled ? spec.tile_height : 16;
    for (int y = 0; y < spec.height; y += rows) {
        const int y1 = std::min(spec.height, y + rows);
        std::uint32_t* band = img.film.data() + static_cast<std::size_t>(y) * img.width * channels;
        const bool ok = tiled
                            ? in->read_tiles(1, 0, 0, spec.width, y, y1, 0, 1, 0, spec.nchannels, TypeDesc::UINT, band)
                            : in->read_scanlines(1, 0, y, y1, 0, 0, spec.nchannels, TypeDesc::UINT, band);
        if (!ok)
            throw Error(path + ": cannot read its film part: " + one_line(in->geterror()));
    }
}

} // namespace pathcl
