// The image module (image/image_module.h): every call pathcl makes to OpenImageIO, built as
// libpathcl_oiio.so and loaded when an image is first read or written.
#include <algorithm>
#include <fcntl.h>
#include <memory>
#include <string>
#include <unistd.h>
#include <vector>

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imageio.h>

#include "common/muted_stderr.h"
#include "image/image_io.h"
#include "image/image_module.h"

namespace pathcl {
namespace {

using OIIO::ImageBuf;
using OIIO::ImageSpec;
using OIIO::TypeDesc;

// Whether `file` is on disk whole (its first `parts` parts): flushed (fsync reports a
// write the kernel could not complete) and read back to the last pixel. The image writers
// do not all report a failed write (libpng's can leave a 0-byte file and succeed), so the
// file is never trusted blindly.
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

// Opens an image to be read whole with `format`'s reader alone (never OpenImageIO's search
// through all of them, some of which abort the process on a bad file): at most
// kMaxImagePixels, kMaxImageRowBytes a row and kMaxImageBytes in all, checked from its
// header before any pixel is decoded. Read through ImageInput, not ImageBuf: ImageBuf
// goes through OIIO's shared image cache, which keeps the header of a file by name, so a
// file that changed since was decoded into a buffer sized by the stale header (a heap
// overflow found by tools/fuzz.sh images).
std::unique_ptr<OIIO::ImageInput> open_image(const std::string& path, const char* format, std::string& why)
{
    std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::create(format);
    ImageSpec opened;
    if (!in || !in->open(path, opened)) {
        why = "cannot read image: " + (in ? in->geterror() : OIIO::geterror());
        return nullptr;
    }
    const ImageSpec& spec = in->spec();
    if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0 ||
        static_cast<std::size_t>(spec.width) > kMaxImagePixels / static_cast<std::size_t>(spec.height)) {
        why = "unsupported image size " + std::to_string(spec.width) + "x" + std::to_string(spec.height) +
              " (at most " + std::to_string(kMaxImagePixels) + " pixels)";
        return nullptr;
    }
    // OpenImageIO reads rows in chunks and sized its buffer for 256 rows whatever the
    // image's height: a 1-row EXR 8.6 million pixels wide asked for 26 GB (found by
    // tools/fuzz.sh images). So a row is bounded, and so is the whole image at every
    // channel decoded as float.
    const std::size_t row_bytes = static_cast<std::size_t>(spec.width) * static_cast<std::size_t>(spec.nchannels) * 4;
    if (row_bytes > kMaxImageRowBytes || static_cast<std::size_t>(spec.height) > kMaxImageBytes / row_bytes) {
        why = "unsupported image size " + std::to_string(spec.width) + "x" + std::to_string(spec.height) + " with " +
              std::to_string(spec.nchannels) + " channels (at most " + std::to_string(kMaxImageRowBytes) +
              " bytes a row and " + std::to_string(kMaxImageBytes) + " in all, as float)";
        return nullptr;
    }
    return in;
}

// Part 0 the image (float), part 1 "film" (uint32) where the image has one.
std::string write_exr(const std::string& file, const Image& img)
{
    const std::size_t pixels = static_cast<std::size_t>(img.width) * img.height;
    const int w = static_cast<int>(img.width), h = static_cast<int>(img.height);
    const bool counts = !img.samples.empty();
    const std::size_t film_channels = img.film_channels.size();
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
            why = out ? out->geterror() : OIIO::geterror();
    }
    if (why.empty() && !written_completely(file, w, h, static_cast<int>(specs.size())))
        why = "the file on disk is incomplete (is the disk full?)";
    return why.empty() ? why : "cannot write: " + why;
}

std::string write_png(const std::string& file, int w, int h, const float* shown)
{
    ImageBuf out;
    {
        ImageBuf linear(ImageSpec(w, h, 3, TypeDesc::FLOAT));
        linear.set_pixels(OIIO::ROI::All(), TypeDesc::FLOAT, shown);
        ImageBuf srgb = OIIO::ImageBufAlgo::colorconvert(linear, "linear", "sRGB");
        out = OIIO::ImageBufAlgo::clamp(srgb, 0.0f, 1.0f);
        out.set_write_format(TypeDesc::UINT8);
    }
    if (out.has_error())
        return "cannot prepare image: " + out.geterror();
    if (!out.write(file) || !written_completely(file, w, h, 1))
        return "cannot write: " +
               (out.has_error() ? out.geterror() : "the file on disk is incomplete (is the disk full?)");
    return {};
}

std::string read_image(const std::string& path, const char* format, Image& img)
{
    MutedStderr muted; // image libraries' own lines; their errors reach us by geterror()
    std::string why;
    std::unique_ptr<OIIO::ImageInput> in = open_image(path, format, why);
    if (!in)
        return why;
    const ImageSpec spec = in->spec();
    auto channel = [&](const char* name) { return spec.channelindex(name); };
    int r = channel("R"), g = channel("G"), b = channel("B");
    if (r < 0 || g < 0 || b < 0)
        return "image has no R, G, B channels";
    int vr = channel("variance.R"), vg = channel("variance.G"), vb = channel("variance.B");
    int counts = channel("samples");
    img = Image{};
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
        return "cannot read image: " + in->geterror();
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
                return "pixel " + std::to_string(i) + " has a bad sample count";
            img.samples[i] = static_cast<std::uint32_t>(k);
        }
    }
    return {};
}

std::string read_film_part(const std::string& path, const char* format, Image& img)
{
    MutedStderr muted;
    std::string why;
    std::unique_ptr<OIIO::ImageInput> in = open_image(path, format, why);
    if (!in)
        return why;
    if (!in->seek_subimage(1, 0))
        return "has no film part: not a partial render (--sample-range)";
    const ImageSpec& spec = in->spec();
    if (spec.width != static_cast<int>(img.width) || spec.height != static_cast<int>(img.height) ||
        spec.get_string_attribute("name") != "film" || spec.nchannels <= 0)
        return "its film part does not match its image";
    const std::size_t pixels = static_cast<std::size_t>(img.width) * img.height;
    const std::size_t channels = static_cast<std::size_t>(spec.nchannels);
    if (channels > kMaxFilmChannels || pixels > kMaxFilmBytes / 4 / channels)
        return "its film part is too large (" + std::to_string(channels) + " channels of " + std::to_string(pixels) +
               " pixels; at most " + std::to_string(kMaxFilmBytes) + " bytes)";
    // Written by pathcl: scanlines whose data window starts at the origin. A tool that
    // re-saves the file may have tiled it (oiiotool --tile): tiles are read as well.
    if (spec.deep || spec.depth != 1 || spec.x != 0 || spec.y != 0 || spec.z != 0)
        return "its film part is not a flat image whose data window starts at 0,0 (" +
               (spec.deep ? std::string("deep data")
                          : "origin " + std::to_string(spec.x) + "," + std::to_string(spec.y) + "," +
                                std::to_string(spec.z) + ", depth " + std::to_string(spec.depth)) +
               ")";
    const bool tiled = spec.tile_width > 0;
    if (tiled && (spec.tile_height <= 0 || spec.tile_depth > 1 ||
                  static_cast<std::size_t>(spec.tile_height) * img.width * channels * 4 > kMaxFilmBandBytes))
        return "its film part has tiles of " + std::to_string(spec.tile_width) + "x" +
               std::to_string(spec.tile_height) + "x" + std::to_string(spec.tile_depth) +
               " pixels, too large a row of them to read (at most " + std::to_string(kMaxFilmBandBytes) + " bytes)";
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
            return "cannot read its film part: " + in->geterror();
    }
    return {};
}

std::string decode(const unsigned char* bytes, std::size_t size, const char* format,
                   const std::function<void(const DecodedShape&)>& admit, DecodedShape& shape,
                   std::vector<std::uint8_t>& pixels8, std::vector<std::uint16_t>& pixels16)
{
    MutedStderr muted; // libpng prints its errors too; OpenImageIO hands them to us
    OIIO::Filesystem::IOMemReader reader(bytes, size);
    auto in = OIIO::ImageInput::create(format);
    if (!in || !in->set_ioproxy(&reader))
        return std::string("OpenImageIO cannot read ") + format + " from memory";
    ImageSpec config, spec;
    config.attribute("oiio:UnassociatedAlpha", 1); // keep colours as stored, not premultiplied
    if (!in->open(std::string("image.") + format, spec, config))
        return std::string("cannot decode the ") + format + " image: " + in->geterror();
    shape = DecodedShape{spec.width, spec.height, spec.nchannels, spec.format.size() > 1 ? 16 : 8};
    admit(shape);
    const std::size_t values = static_cast<std::size_t>(shape.width) * static_cast<std::size_t>(shape.height) *
                               static_cast<std::size_t>(shape.channels);
    bool ok;
    if (shape.bits == 16) {
        pixels16.resize(values);
        ok = in->read_image(0, 0, 0, shape.channels, TypeDesc::UINT16, pixels16.data());
    } else {
        pixels8.resize(values);
        ok = in->read_image(0, 0, 0, shape.channels, TypeDesc::UINT8, pixels8.data());
    }
    if (!ok)
        return std::string("cannot decode the ") + format + " image: " + in->geterror();
    return {};
}

const ImageModule kModule{write_exr, write_png, read_image, read_film_part, decode};

} // namespace
} // namespace pathcl

extern "C" __attribute__((visibility("default"))) const pathcl::ImageModule*
pathcl_image_module(std::uint32_t abi, std::size_t image_size, std::size_t module_size)
{
    const bool same = abi == pathcl::kImageModuleAbi && image_size == sizeof(pathcl::Image) &&
                      module_size == sizeof(pathcl::ImageModule);
    return same ? &pathcl::kModule : nullptr;
}
