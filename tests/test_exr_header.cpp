// An EXR's headers are checked before OpenImageIO opens the file: what OpenEXR 3.1 and
// OpenImageIO 2.4 would trust (a channel's pixel type, an attribute's byte count, a string
// vector's strings, a preview's size, a chunk count) is refused with an error naming the
// file, and the files pathcl writes itself, single- and multi-part, pass.
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <system_error>
#include <unistd.h>
#include <vector>

#include <gtest/gtest.h>

#include "common/error.h"
#include "image/exr_header.h"
#include "image/image_io.h"

namespace pathcl::test_exr_header {
namespace {

namespace fs = std::filesystem;
using Bytes = std::string;

Bytes le32(std::int32_t v)
{
    Bytes b(4, '\0');
    std::memcpy(b.data(), &v, 4); // the suite runs on little-endian machines only
    return b;
}

Bytes attribute(const Bytes& name, const Bytes& type, const Bytes& value, std::int32_t claimed = -1)
{
    return name + '\0' + type + '\0' + le32(claimed >= 0 ? claimed : static_cast<std::int32_t>(value.size())) + value;
}

// An 8x1 scanline EXR, channels B, G and R of `pixel_type`, no compression, one line per block,
// with `extra` attributes in its header.
Bytes exr(std::int32_t pixel_type = 2, const Bytes& extra = "")
{
    Bytes channels;
    for (const char* c : {"B", "G", "R"})
        channels += Bytes(c) + '\0' + le32(pixel_type) + Bytes(4, '\0') + le32(1) + le32(1);
    channels += '\0';
    const Bytes window = le32(0) + le32(0) + le32(7) + le32(0);
    Bytes f = "\x76\x2f\x31\x01" + le32(2);
    f += attribute("channels", "chlist", channels);
    f += attribute("compression", "compression", Bytes(1, '\0'));
    f += attribute("dataWindow", "box2i", window);
    f += attribute("displayWindow", "box2i", window);
    f += attribute("lineOrder", "lineOrder", Bytes(1, '\0'));
    f += attribute("pixelAspectRatio", "float", Bytes("\x00\x00\x80\x3f", 4));
    f += attribute("screenWindowCenter", "v2f", Bytes(8, '\0'));
    f += attribute("screenWindowWidth", "float", Bytes("\x00\x00\x80\x3f", 4));
    f += extra + '\0';
    const std::uint64_t block = f.size() + 8;
    f += Bytes(reinterpret_cast<const char*>(&block), 8);
    f += le32(0) + le32(8 * 3 * 4) + Bytes(8 * 3 * 4, '\0'); // line 0: eight black float pixels
    return f;
}

// A 3x2 image of 4 samples a pixel, as pathcl writes them.
Image small_image()
{
    Image img;
    img.width = 3;
    img.height = 2;
    img.spp = 4;
    img.rgb.assign(18, 0.5f);
    img.variance.assign(18, 0.25f);
    return img;
}

class ExrHeader : public ::testing::Test {
protected:
    void SetUp() override
    {
        dir_ = fs::temp_directory_path() / ("pathcl-exr-header-" + std::to_string(::getpid()));
        fs::create_directories(dir_);
    }
    void TearDown() override
    {
        std::error_code ec;
        fs::remove_all(dir_, ec);
    }
    std::string file(const std::string& name, const Bytes& bytes)
    {
        const std::string p = (dir_ / name).string();
        std::ofstream(p, std::ios::binary) << bytes;
        return p;
    }
    // The error check_exr_headers gives, "" if none; read_image must refuse such a file
    // with the same error, before OpenImageIO sees it.
    std::string error_of(const std::string& path)
    {
        try {
            check_exr_headers(path);
        } catch (const Error& e) {
            try {
                (void)read_image(path);
                ADD_FAILURE() << path << ": read_image read it";
            } catch (const Error& read) {
                EXPECT_STREQ(read.what(), e.what());
            }
            return e.what();
        }
        return "";
    }
    // A partial render as pathcl writes it: part 0 the image, part 1 the film (uint
    // channels "a" and "b"), each header with its chunkCount.
    Bytes partial()
    {
        Image img = small_image();
        img.metadata["note"] = "a string attribute";
        img.film_channels = {"a", "b"};
        img.film.assign(12, 7u);
        const std::string p = (dir_ / "partial.exr").string();
        write_image(p, img);
        std::ifstream in(p, std::ios::binary);
        return Bytes(std::istreambuf_iterator<char>(in), {});
    }
    // `bytes` with the first `from` after `after` replaced by `to` (of the same length).
    static Bytes patched(Bytes bytes, const Bytes& after, const Bytes& from, const Bytes& to)
    {
        const std::size_t at = bytes.find(after + from);
        EXPECT_NE(at, Bytes::npos);
        if (at != Bytes::npos)
            bytes.replace(at + after.size(), from.size(), to);
        return bytes;
    }
    fs::path dir_;
};

TEST_F(ExrHeader, AcceptsAWellFormedFileThatOpenImageIoReads)
{
    const std::string p = file("valid.exr", exr());
    EXPECT_EQ(error_of(p), "");
    const Image img = read_image(p);
    EXPECT_EQ(img.width, 8u);
    EXPECT_EQ(img.height, 1u);
}

TEST_F(ExrHeader, AcceptsWhatPathclWritesWithAndWithoutAFilmPart)
{
    const Image img = small_image();
    const std::string single = (dir_ / "single.exr").string();
    write_image(single, img);
    EXPECT_EQ(error_of(single), "");
    EXPECT_EQ(error_of(file("multi.exr", partial())), "");
}

// OpenImageIO 2.4 aborts the process on a pixel type it does not know in a part after the
// first (found by tools/fuzz.sh partial): an Error instead, in any part.
TEST_F(ExrHeader, RefusesAnUnknownPixelType)
{
    const std::string p = file("type3.exr", exr(3));
    const std::string e = error_of(p);
    EXPECT_NE(e.find(p), std::string::npos) << e;
    EXPECT_NE(e.find("channel \"B\" has pixel type 3"), std::string::npos) << e;
    const std::string film = file("film-type3.exr", patched(partial(), Bytes("a") + '\0', le32(0), le32(3)));
    EXPECT_NE(error_of(film).find("channel \"a\" has pixel type 3"), std::string::npos);
}

// OpenEXR 3.1 allocates and fills an attribute's claimed byte count before it finds the
// file too short: 2 GB for a 400-byte file (found by tools/fuzz.sh partial).
TEST_F(ExrHeader, RefusesAnAttributeLongerThanTheFile)
{
    const std::string p = file("bomb.exr", exr(2, attribute("note", "string", "abc", 0x7fff0000)));
    EXPECT_NE(error_of(p).find("attribute \"note\" claims 2147418112 bytes"), std::string::npos);
}

// OpenEXR reads a box2i's 16 bytes whatever byte count it declares, then the next
// attribute from there: 1040 declared bytes hid a string attribute of 2 GB from a walk
// that skipped them (found by tools/fuzz.sh partial).
TEST_F(ExrHeader, RefusesAFixedSizeValueOfAnotherByteCount)
{
    const Bytes box = le32(0) + le32(0) + le32(7) + le32(0);
    const Bytes hidden = Bytes("note") + '\0' + "string" + '\0' + le32(0x7fff0000) + "x";
    const std::string e = error_of(file("box.exr", exr(2, attribute("window", "box2i", box + hidden))));
    const std::string claims = "claims " + std::to_string(box.size() + hidden.size()) + " bytes (the type has 16)";
    EXPECT_NE(e.find("attribute \"window\" of type \"box2i\" " + claims), std::string::npos) << e;
    EXPECT_EQ(error_of(file("box-good.exr", exr(2, attribute("window", "box2i", box)))), "");
}

// OpenEXR reads a channel list up to its empty name, and the next attribute from there.
TEST_F(ExrHeader, RefusesAChannelListThatEndsBeforeItsByteCount)
{
    const Bytes list = Bytes("B") + '\0' + le32(2) + Bytes(4, '\0') + le32(1) + le32(1) + '\0';
    const std::string e = error_of(file("list.exr", exr(2, attribute("more", "chlist", list + "abcd"))));
    EXPECT_NE(e.find("a channel list ends 4 bytes before its byte count"), std::string::npos) << e;
}

TEST_F(ExrHeader, RefusesAStringVectorWhoseStringsOverrunIt)
{
    const Bytes good = le32(3) + "abc" + le32(0);
    EXPECT_EQ(error_of(file("sv-good.exr", exr(2, attribute("names", "stringvector", good)))), "");
    const Bytes bad = le32(3) + "abc" + le32(0x7fff0000) + "d";
    EXPECT_NE(error_of(file("sv-bad.exr", exr(2, attribute("names", "stringvector", bad)))).find("string vector"),
              std::string::npos);
}

TEST_F(ExrHeader, RefusesAPreviewLargerThanItsBytes)
{
    const Bytes good = le32(2) + le32(1) + Bytes(8, '\x7f');
    EXPECT_EQ(error_of(file("preview-good.exr", exr(2, attribute("preview", "preview", good)))), "");
    const Bytes bad = le32(65536) + le32(65536) + Bytes(8, '\x7f');
    EXPECT_NE(error_of(file("preview-bad.exr", exr(2, attribute("preview", "preview", bad)))).find("preview image"),
              std::string::npos);
}

// A multi-part file's offset table has chunkCount entries, read before any pixel.
TEST_F(ExrHeader, RefusesAChunkCountTheFileCannotHold)
{
    const Bytes key = Bytes("chunkCount") + '\0' + "int" + '\0' + le32(4);
    const Bytes whole = partial();
    const std::size_t at = whole.find(key);
    ASSERT_NE(at, Bytes::npos);
    const Bytes count = whole.substr(at + key.size(), 4);
    const std::string e = error_of(file("chunks.exr", patched(whole, key, count, le32(0x10000000))));
    EXPECT_NE(e.find("a chunk count of 268435456"), std::string::npos) << e;
}

// Only the OpenEXR, Radiance HDR, PNG and JPEG readers are ever asked: OpenImageIO 2.4
// tries every reader it has on a file its extension's reader refuses, and its RLA reader
// aborted on a .exr file whose magic number a fuzzer had changed (tools/fuzz.sh partial).
TEST_F(ExrHeader, AFileOfAnotherFormatIsRefusedByItsFirstBytes)
{
    Bytes rla = exr();
    rla.replace(0, 4, Bytes("\x00\x00\x00\x00", 4));
    const std::string p = file("not-exr.exr", rla);
    try {
        (void)read_image(p);
        ADD_FAILURE() << "read";
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()), p + ": not an OpenEXR, Radiance HDR, PNG or JPEG image");
    }
}

TEST_F(ExrHeader, RefusesAHeaderCutShort)
{
    const Bytes whole = exr();
    // The last cut leaves out only the null byte that closes the header (then the offset
    // table's 8 bytes and the line's 8 + 96).
    for (std::size_t cut : {std::size_t(6), std::size_t(20), std::size_t(40), std::size_t(200), whole.size() - 113}) {
        const std::string e = error_of(file("cut.exr", whole.substr(0, cut)));
        EXPECT_NE(e.find("not a valid OpenEXR file"), std::string::npos) << cut << ": " << e;
    }
}

} // namespace
} // namespace pathcl::test_exr_header
