// Image files: EXR keeps radiance, variance and sample count exactly; PNG is sRGB-encoded
// and clamped; a failed write leaves an existing file untouched; a file that changed is
// read anew.
#include <filesystem>
#include <fstream>
#include <system_error>
#include <vector>

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include "common/error.h"
#include "image/image_io.h"

namespace pathcl::test_image_io {
namespace {

namespace fs = std::filesystem;

fs::path temp_dir_path()
{
    return fs::temp_directory_path() / ("pathcl-image-io-" + std::to_string(::getpid()));
}

fs::path temp_dir()
{
    fs::path d = temp_dir_path();
    fs::create_directories(d);
    return d;
}

// This process's folder goes when its tests are done (it was left in the temporary
// folder, one per run).
class TempDirCleanup : public ::testing::Environment {
public:
    void TearDown() override
    {
        std::error_code ec;
        fs::remove_all(temp_dir_path(), ec);
    }
};
const ::testing::Environment* const kTempDirCleanup = ::testing::AddGlobalTestEnvironment(new TempDirCleanup);

Image gradient(std::uint32_t w, std::uint32_t h)
{
    Image img;
    img.width = w;
    img.height = h;
    img.spp = 17;
    for (std::uint32_t i = 0; i < w * h * 3; ++i) {
        img.rgb.push_back(0.01f * static_cast<float>(i) + 1e-3f);
        img.variance.push_back(0.5f * static_cast<float>(i) + 123.0f);
    }
    return img;
}

TEST(ImageIo, ExrRoundTripKeepsRadianceVarianceAndSpp)
{
    fs::path p = temp_dir() / "round.exr";
    Image a = gradient(7, 5);
    a.rgb[4] = 1e6f; // no clamping of bright samples
    write_image(p.string(), a);
    Image b = read_image(p.string());
    EXPECT_EQ(b.width, 7u);
    EXPECT_EQ(b.height, 5u);
    EXPECT_EQ(b.spp, 17u);
    EXPECT_EQ(a.rgb, b.rgb);
    EXPECT_EQ(a.variance, b.variance);
}

// OpenImageIO's shared image cache keeps a header per file name; a reader going through it
// decoded the second image into a buffer sized by the first one's header.
TEST(ImageIo, ReadsAFileAgainAfterItChanged)
{
    fs::path p = temp_dir() / "changes.exr";
    write_image(p.string(), gradient(3, 2));
    EXPECT_EQ(read_image(p.string()).width, 3u);
    Image big = gradient(40, 30);
    write_image(p.string(), big);
    Image b = read_image(p.string());
    EXPECT_EQ(b.width, 40u);
    EXPECT_EQ(b.height, 30u);
    EXPECT_EQ(b.rgb, big.rgb);
}

TEST(ImageIo, PngIsSrgbEncodedAndClamped)
{
    fs::path p = temp_dir() / "srgb.png";
    Image a;
    a.width = 3;
    a.height = 1;
    a.spp = 1;
    a.rgb = {0.5f, 0.5f, 0.5f, 2.0f, -1.0f, 0.0031308f, 0.0f, 1.0f, 0.2140f};
    a.variance.assign(9, 0.0f);
    write_image(p.string(), a);
    OIIO::ImageBuf buf(p.string());
    ASSERT_TRUE(buf.read(0, 0, true, OIIO::TypeDesc::UINT8));
    unsigned char px[9];
    buf.get_pixels(OIIO::ROI::All(), OIIO::TypeDesc::UINT8, px);
    EXPECT_NEAR(px[0], 188, 1); // sRGB(0.5) = 0.7354
    EXPECT_EQ(px[3], 255);      // clamped above
    EXPECT_EQ(px[4], 0);        // clamped below
    EXPECT_NEAR(px[5], 10, 1);  // the linear segment: 12.92 * 0.0031308 = 0.04045
    EXPECT_NEAR(px[8], 128, 1); // sRGB(0.214) = 0.5
}

TEST(ImageIo, FailedWriteLeavesExistingFileIntact)
{
    fs::path dir = temp_dir();
    fs::path p = dir / "keep.exr";
    {
        std::ofstream f(p);
        f << "precious";
    }
    Image broken = gradient(4, 4);
    broken.rgb.resize(3); // inconsistent: too few pixels -> must not replace the file
    EXPECT_THROW(write_image(p.string(), broken), Error);
    std::ifstream f(p);
    std::string content;
    f >> content;
    EXPECT_EQ(content, "precious");
    for (const auto& e : fs::directory_iterator(dir))
        EXPECT_EQ(e.path().filename().string().find(".tmp"), std::string::npos) << "left behind " << e.path();
}

TEST(ImageIo, RejectsUnknownExtensionAndMissingDirectory)
{
    EXPECT_THROW(check_output_path("/tmp/x.jpg"), Error);
    EXPECT_THROW(check_output_path("/nonexistent-dir-pathcl/x.exr"), Error);
    EXPECT_NO_THROW(check_output_path((temp_dir() / "ok.png").string()));
}

// The 8-bit values of a one-row PNG of the given radiances written through `display`.
std::vector<unsigned char> png_bytes(const std::vector<float>& radiance, const DisplayTransform& display)
{
    Image img;
    img.width = static_cast<std::uint32_t>(radiance.size());
    img.height = 1;
    for (float r : radiance)
        for (int c = 0; c < 3; ++c) {
            img.rgb.push_back(r);
            img.variance.push_back(0.0f);
        }
    fs::path p = temp_dir() / "display.png";
    write_image(p.string(), img, display);
    // Read through ImageInput: ImageBuf's cache would return the previous file's pixels.
    auto in = OIIO::ImageInput::open(p.string());
    std::vector<unsigned char> px(radiance.size() * 3);
    EXPECT_TRUE(in && in->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT8, px.data()));
    return px;
}

TEST(ImageIo, PngExposureScalesRadianceByPowersOfTwo)
{
    // +1 stop shows 0.25 as 0.5 and 0.1 as 0.2, byte for byte; -2 stops shows 2 as 0.5.
    EXPECT_EQ(png_bytes({0.25f, 0.1f}, {1.0, ToneCurve::Clip}), png_bytes({0.5f, 0.2f}, {}));
    EXPECT_EQ(png_bytes({2.0f}, {-2.0, ToneCurve::Clip}), png_bytes({0.5f}, {}));
    EXPECT_NE(png_bytes({0.25f}, {1.0, ToneCurve::Clip}), png_bytes({0.25f}, {}));
}

TEST(ImageIo, FilmicToneCurveRollsHighlightsOffWhereClipSaturates)
{
    // Clip: 1 and 4 are both white. Filmic: below white, distinct, increasing, and the
    // curve's own values (f(1) = 2.54 / 3.16, f(4) = 40.28 / 41.38).
    std::vector<unsigned char> clip = png_bytes({1.0f, 4.0f}, {});
    EXPECT_EQ(clip[0], 255);
    EXPECT_EQ(clip[3], 255);
    std::vector<unsigned char> filmic = png_bytes({1.0f, 4.0f}, {0.0, ToneCurve::Filmic});
    EXPECT_LT(filmic[0], filmic[3]);
    EXPECT_LT(filmic[3], 255);
    EXPECT_EQ(png_bytes({2.54f / 3.16f, 40.28f / 41.38f}, {}), filmic);
    EXPECT_FLOAT_EQ(display_value(1.0f, {0.0, ToneCurve::Filmic}), 2.54f / 3.16f);
    EXPECT_EQ(display_value(0.0f, {0.0, ToneCurve::Filmic}), 0.0f);
}

} // namespace
} // namespace pathcl::test_image_io
