#include "image/exr_header.h"

#include <cstdint>
#include <cstring>
#include <fstream>
#include <vector>

#include "common/error.h"

namespace pathcl {
namespace {

// The layout is that of the OpenEXR file format document ("OpenEXR File Layout"): the
// magic number, a version field whose low byte is 2 and whose bit 12 marks a multi-part
// file, then headers of attributes (name, type name, byte count, value), each header
// closed by an empty name; a multi-part file's list of headers is closed by an empty one.
constexpr unsigned char kMagic[4] = {0x76, 0x2f, 0x31, 0x01};
constexpr std::uint32_t kMultiPartBit = 0x1000;
constexpr std::size_t kMaxNameBytes = 255; // with the long-names bit; 31 without

std::int32_t le32(const unsigned char* p)
{
    const std::uint32_t u =
        std::uint32_t(p[0]) | std::uint32_t(p[1]) << 8 | std::uint32_t(p[2]) << 16 | std::uint32_t(p[3]) << 24;
    std::int32_t v;
    std::memcpy(&v, &u, sizeof v);
    return v;
}

class HeaderReader {
public:
    HeaderReader(const std::string& path) : path_(path), in_(path, std::ios::binary)
    {
        if (!in_)
            fail("cannot be read");
        in_.seekg(0, std::ios::end);
        size_ = static_cast<std::uint64_t>(in_.tellg());
        in_.seekg(0);
    }

    [[noreturn]] void fail(const std::string& what) const
    {
        throw Error(path_ + ": not a valid OpenEXR file: " + what);
    }

    std::uint64_t left() { return size_ - static_cast<std::uint64_t>(in_.tellg()); }

    void read(unsigned char* out, std::size_t n, const char* what)
    {
        if (n > left() || !in_.read(reinterpret_cast<char*>(out), static_cast<std::streamsize>(n)))
            fail(std::string("it ends inside ") + what);
    }

    // A null-terminated name of at most kMaxNameBytes bytes ("" closes a header).
    std::string name(const char* what)
    {
        std::string s;
        for (;;) {
            unsigned char c;
            read(&c, 1, what);
            if (c == 0)
                return s;
            if (s.size() == kMaxNameBytes)
                fail(std::string(what) + " longer than 255 bytes");
            s.push_back(static_cast<char>(c));
        }
    }

    std::vector<unsigned char> bytes(std::size_t n, const char* what)
    {
        std::vector<unsigned char> v(n);
        read(v.data(), n, what);
        return v;
    }

    void skip(std::uint64_t n) { in_.seekg(static_cast<std::streamoff>(n), std::ios::cur); }

private:
    std::string path_;
    std::ifstream in_;
    std::uint64_t size_ = 0;
};

// OpenEXR 3.1 reads a value of these types by its own size, whatever byte count the file
// declares, and goes on reading the next attribute from there: a box2i declared 1040
// bytes long hid a 2 GB string attribute from a walk that skipped 1040 bytes (found by
// tools/fuzz.sh partial). So each must declare exactly its size.
std::size_t fixed_size(const std::string& type)
{
    static const std::pair<const char*, std::size_t> kSizes[] = {{"box2f", 16},
                                                                 {"box2i", 16},
                                                                 {"chromaticities", 32},
                                                                 {"compression", 1},
                                                                 {"deepImageState", 1},
                                                                 {"double", 8},
                                                                 {"envmap", 1},
                                                                 {"float", 4},
                                                                 {"int", 4},
                                                                 {"keycode", 28},
                                                                 {"lineOrder", 1},
                                                                 {"m33d", 72},
                                                                 {"m33f", 36},
                                                                 {"m44d", 128},
                                                                 {"m44f", 64},
                                                                 {"rational", 8},
                                                                 {"tiledesc", 9},
                                                                 {"timecode", 8},
                                                                 {"v2d", 16},
                                                                 {"v2f", 8},
                                                                 {"v2i", 8},
                                                                 {"v3d", 24},
                                                                 {"v3f", 12},
                                                                 {"v3i", 12}};
    for (const auto& [name, size] : kSizes)
        if (type == name)
            return size;
    return 0;
}

// "chlist": channels of name, pixel type (int), pLinear, 3 reserved bytes and x and y
// sampling (ints), closed by an empty name.
void check_channel_list(HeaderReader& r, const std::vector<unsigned char>& v)
{
    std::size_t at = 0;
    for (;;) {
        const void* end = at < v.size() ? std::memchr(&v[at], 0, v.size() - at) : nullptr;
        if (!end)
            r.fail("a channel list is not closed within its byte count");
        const std::size_t name_end = static_cast<std::size_t>(static_cast<const unsigned char*>(end) - v.data());
        if (name_end == at) {
            // OpenEXR reads channels up to the empty name, not up to the byte count.
            if (name_end + 1 != v.size())
                r.fail("a channel list ends " + std::to_string(v.size() - name_end - 1) +
                       " bytes before its byte count");
            return;
        }
        const std::string channel(reinterpret_cast<const char*>(&v[at]), name_end - at);
        if (v.size() - name_end - 1 < 16)
            r.fail("channel " + quote(channel) + " is cut short by its list's byte count");
        const std::int32_t type = le32(&v[name_end + 1]);
        if (type < 0 || type > 2)
            r.fail("channel " + quote(channel) + " has pixel type " + std::to_string(type) +
                   " (0, 1 and 2 are uint, half and float)");
        at = name_end + 1 + 16;
    }
}

// "stringvector": strings of a byte count (int) and the bytes, filling the value.
void check_string_vector(HeaderReader& r, const std::string& attribute, const std::vector<unsigned char>& v)
{
    std::size_t at = 0;
    while (at < v.size()) {
        if (v.size() - at < 4)
            r.fail("string vector " + quote(attribute) + " ends inside a string's byte count");
        const std::int32_t n = le32(&v[at]);
        at += 4;
        if (n < 0 || static_cast<std::size_t>(n) > v.size() - at)
            r.fail("string vector " + quote(attribute) + " has a string of " + std::to_string(n) + " bytes in " +
                   std::to_string(v.size() - at) + " bytes that are left");
        at += static_cast<std::size_t>(n);
    }
}

} // namespace

void check_exr_headers(const std::string& path)
{
    HeaderReader r(path);
    unsigned char start[8];
    r.read(start, 8, "the magic number and version");
    if (std::memcmp(start, kMagic, 4) != 0)
        r.fail("no OpenEXR magic number");
    const bool multi_part = (static_cast<std::uint32_t>(le32(start + 4)) & kMultiPartBit) != 0;
    for (int part = 0;; ++part) {
        std::string attribute = r.name("an attribute name");
        if (attribute.empty()) {
            if (!multi_part || part > 0)
                return; // the end of the only header, or of the list of headers
            r.fail("the first header is empty");
        }
        for (; !attribute.empty(); attribute = r.name("an attribute name")) {
            const std::string type = r.name("an attribute type");
            unsigned char count[4];
            r.read(count, 4, "an attribute's byte count");
            const std::int32_t n = le32(count);
            if (n < 0 || static_cast<std::uint64_t>(n) > r.left())
                r.fail("attribute " + quote(attribute) + " claims " + std::to_string(n) + " bytes and the file has " +
                       std::to_string(r.left()) + " left");
            const std::size_t bytes = static_cast<std::size_t>(n);
            const std::size_t fixed = fixed_size(type);
            if ((fixed != 0 && bytes != fixed) || (type == "floatvector" && bytes % 4 != 0))
                r.fail("attribute " + quote(attribute) + " of type " + quote(type) + " claims " +
                       std::to_string(bytes) + " bytes" +
                       (fixed != 0 ? " (the type has " + std::to_string(fixed) + ")" : " (not whole floats)"));
            if (type == "chlist") {
                check_channel_list(r, r.bytes(bytes, "a channel list"));
            } else if (type == "stringvector") {
                check_string_vector(r, attribute, r.bytes(bytes, "a string vector"));
            } else if (type == "preview") {
                // Width and height (unsigned ints), then 4 bytes a pixel.
                const std::vector<unsigned char> v = r.bytes(bytes < 8 ? bytes : 8, "a preview image");
                const std::uint64_t pixels =
                    v.size() == 8 ? std::uint64_t(std::uint32_t(le32(&v[0]))) * std::uint32_t(le32(&v[4])) : 0;
                if (v.size() < 8 || 8 + 4 * pixels != bytes)
                    r.fail("preview image " + quote(attribute) + " does not fill its " + std::to_string(bytes) +
                           " bytes");
                r.skip(bytes - 8);
            } else if (multi_part && attribute == "chunkCount" && type == "int") {
                const std::vector<unsigned char> v = r.bytes(bytes, "a chunk count");
                // Each chunk has an 8-byte offset in the file's offset tables.
                const std::int32_t chunks = v.size() == 4 ? le32(v.data()) : -1;
                if (chunks < 0 || static_cast<std::uint64_t>(chunks) * 8 > r.left())
                    r.fail("a chunk count of " + std::to_string(chunks) + " in a file with " +
                           std::to_string(r.left()) + " bytes left");
            } else {
                r.skip(bytes);
            }
        }
        if (!multi_part)
            return;
    }
}

} // namespace pathcl
