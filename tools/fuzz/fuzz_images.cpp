// libFuzzer target: the image decoders on arbitrary bytes. Every input goes through both
// - pathcl::decode_image, the PNG/JPEG decoder of glTF textures (in memory), and
// - pathcl::read_environment_image, the environment-map reader (EXR, HDR or whatever
//   OpenImageIO reads), on a file in a per-process temporary directory whose extension
//   follows the bytes' signature (.exr, .png, .jpg; .hdr otherwise).
// A pathcl::Error or any other std::exception is the expected rejection; a crash, a
// sanitizer report, a timeout or running out of memory is a finding. Built by
// -DPATHCL_FUZZ=ON, run by tools/fuzz.sh images SECONDS.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <exception>
#include <string>

#include "fuzz_scratch.h"
#include "scene/environment_image.h"
#include "scene/gltf_images.h"

namespace {

bool starts_with(const std::uint8_t* data, std::size_t size, const char* magic, std::size_t n)
{
    return size >= n && std::memcmp(data, magic, n) == 0;
}

const char* extension_for(const std::uint8_t* data, std::size_t size)
{
    if (starts_with(data, size, "\x76\x2f\x31\x01", 4))
        return ".exr";
    if (starts_with(data, size, "\x89PNG", 4))
        return ".png";
    if (starts_with(data, size, "\xff\xd8\xff", 3))
        return ".jpg";
    return ".hdr";
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    try {
        pathcl::SceneImage image = pathcl::decode_image(data, size, "fuzz");
        (void)image;
    } catch (const std::exception&) {
        // Rejected: what a bad image should get.
    }
    // One name per extension for every input: a changed file under a name already read is
    // what OpenImageIO's per-name image cache once read with a stale header.
    const std::string path = fuzz::scratch_directory("images") + "/environment" + extension_for(data, size);
    fuzz::write_file(path, data, size);
    try {
        pathcl::SceneEnvironment env;
        pathcl::read_environment_image(env, path);
    } catch (const std::exception&) {
    }
    std::remove(path.c_str());
    return 0;
}
