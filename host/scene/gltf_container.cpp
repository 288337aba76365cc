#include "scene/gltf_container.h"

#include <cstdint>
#include <cstring>

#include "common/error.h"

namespace pathcl {
namespace {

std::uint32_t le32(const unsigned char* p)
{
    return std::uint32_t(p[0]) | std::uint32_t(p[1]) << 8 | std::uint32_t(p[2]) << 16 | std::uint32_t(p[3]) << 24;
}

constexpr std::uint32_t kChunkJson = 0x4E4F534A; // later chunks (BIN, unknown types) are only bounds-checked

} // namespace

bool is_glb(const unsigned char* bytes, std::size_t size)
{
    return size >= 4 && std::memcmp(bytes, "glTF", 4) == 0;
}

std::string_view check_glb(const unsigned char* bytes, std::size_t size, const std::string& what)
{
    if (size < 20 || !is_glb(bytes, size))
        throw Error(what + ": not a GLB file (shorter than its 20-byte headers or no \"glTF\" magic)");
    if (le32(bytes + 4) != 2)
        throw Error(what + ": GLB version " + std::to_string(le32(bytes + 4)) + " (only version 2 is read)");
    if (le32(bytes + 8) != size)
        throw Error(what + ": the GLB header says " + std::to_string(le32(bytes + 8)) + " bytes, the file has " +
                    std::to_string(size));
    std::size_t at = 12;
    for (int chunk = 0; at < size; ++chunk) {
        if (size - at < 8)
            throw Error(what + ": GLB chunk " + std::to_string(chunk) + "'s header runs past the end of the file");
        std::size_t length = le32(bytes + at);
        std::uint32_t type = le32(bytes + at + 4);
        if (length > size - at - 8)
            throw Error(what + ": GLB chunk " + std::to_string(chunk) + " (" + std::to_string(length) +
                        " bytes) runs past the end of the file");
        if (chunk == 0 && type != kChunkJson)
            throw Error(what + ": the first GLB chunk is not JSON");
        if (chunk == 0)
            check_json_nesting(bytes + at + 8, length, what);
        at += 8 + length;
    }
    return {reinterpret_cast<const char*>(bytes) + 20, le32(bytes + 12)};
}

void check_json_nesting(const unsigned char* text, std::size_t size, const std::string& what)
{
    std::size_t depth = 0;
    bool in_string = false, escaped = false;
    for (std::size_t i = 0; i < size; ++i) {
        unsigned char c = text[i];
        if (in_string) {
            if (escaped)
                escaped = false;
            else if (c == '\\')
                escaped = true;
            else if (c == '"')
                in_string = false;
        } else if (c == '"') {
            in_string = true;
        } else if (c == '[' || c == '{') {
            if (++depth > kMaxJsonDepth)
                throw Error(what + ": JSON nested deeper than " + std::to_string(kMaxJsonDepth) + " levels");
        } else if ((c == ']' || c == '}') && depth > 0) {
            --depth;
        }
    }
}

} // namespace pathcl
