#include "image/image_io.h"

#include <filesystem>

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imageio.h>

#include "common/error.h"
#include "common/staged_files.h"

namespace pathcl {
namespace {

namespace fs = std::filesystem;
using OIIO::ImageBuf;
using OIIO::ImageSpec;
using OIIO::TypeDesc;

} // namespace

void check_output_path(const std::string& path)
{
    std::string ext = lowercase_extension(path);
    if (ext != ".exr" && ext != ".png")
        throw Error(path + ": output must be .exr or .png");
    check_output_location(path);
}

void write_image_file(const std::string& file, const std::string& path, const Image& img)
{
    check_output_path(path);
    const std::size_t pixels = static_cast<std::size_t>(img.width) * img.height;
    if (pixels == 0 || img.rgb.size() != pixels * 3 || img.variance.size() != pixels * 3)
        throw Error(path + ": internal error: image buffers do not match " + std::to_string(img.width) + "x" +
                    std::to_string(img.height));
    const bool exr = lowercase_extension(path) == ".exr";
    const int w = static_cast<int>(img.width), h = static_cast<int>(img.height);

    ImageBuf out;
    if (exr) {
        ImageSpec spec(w, h, 6, TypeDesc::FLOAT);
        spec.channelnames = {"R", "G", "B", "variance.R", "variance.G", "variance.B"};
        spec.attribute("compression", "zip");
        spec.attribute("pathcl:spp", static_cast<int>(img.spp));
        out.reset(spec);
        std::vector<float> px(static_cast<std::size_t>(w) * h * 6);
        for (std::size_t i = 0; i < static_cast<std::size_t>(w) * h; ++i)
            for (int c = 0; c < 3; ++c) {
                px[i * 6 + c] = img.rgb[i * 3 + c];
                px[i * 6 + 3 + c] = img.variance[i * 3 + c];
            }
        out.set_pixels(OIIO::ROI::All(), TypeDesc::FLOAT, px.data());
    } else {
        ImageBuf linear(ImageSpec(w, h, 3, TypeDesc::FLOAT));
        linear.set_pixels(OIIO::ROI::All(), TypeDesc::FLOAT, img.rgb.data());
        ImageBuf srgb = OIIO::ImageBufAlgo::colorconvert(linear, "linear", "sRGB");
        out = OIIO::ImageBufAlgo::clamp(srgb, 0.0f, 1.0f);
        out.set_write_format(TypeDesc::UINT8);
    }
    if (out.has_error())
        throw Error(path + ": cannot prepare image: " + out.geterror());

    if (!out.write(file)) {
        std::error_code ec;
        fs::remove(file, ec);
        throw Error(path + ": cannot write: " + out.geterror());
    }
}

void write_image(const std::string& path, const Image& img)
{
    StagedFiles staged;
    write_image_file(staged.stage(path), path, img);
    staged.commit();
}

Image read_image(const std::string& path)
{
    ImageBuf in(path);
    if (!in.read(0, 0, true, TypeDesc::FLOAT))
        throw Error(path + ": cannot read image: " + in.geterror());
    const ImageSpec& spec = in.spec();
    auto channel = [&](const char* name) { return spec.channelindex(name); };
    int r = channel("R"), g = channel("G"), b = channel("B");
    if (r < 0 || g < 0 || b < 0)
        throw Error(path + ": image has no R, G, B channels");
    int vr = channel("variance.R"), vg = channel("variance.G"), vb = channel("variance.B");
    Image img;
    img.width = static_cast<std::uint32_t>(spec.width);
    img.height = static_cast<std::uint32_t>(spec.height);
    img.spp = static_cast<std::uint32_t>(spec.get_int_attribute("pathcl:spp", 0));
    std::size_t n = static_cast<std::size_t>(spec.width) * spec.height;
    std::vector<float> px(n * static_cast<std::size_t>(spec.nchannels));
    in.get_pixels(OIIO::ROI::All(), TypeDesc::FLOAT, px.data());
    img.rgb.resize(n * 3);
    img.variance.assign(n * 3, 0.0f);
    const int rgb[3] = {r, g, b}, var[3] = {vr, vg, vb};
    for (std::size_t i = 0; i < n; ++i)
        for (int c = 0; c < 3; ++c) {
            img.rgb[i * 3 + c] = px[i * static_cast<std::size_t>(spec.nchannels) + static_cast<std::size_t>(rgb[c])];
            if (var[c] >= 0)
                img.variance[i * 3 + c] =
                    px[i * static_cast<std::size_t>(spec.nchannels) + static_cast<std::size_t>(var[c])];
        }
    return img;
}

} // namespace pathcl
