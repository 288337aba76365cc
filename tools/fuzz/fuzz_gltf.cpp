// libFuzzer target: the glTF loader (pathcl::load_gltf) on arbitrary bytes, written to a
// scene file in a per-process temporary directory: scene.glb when the bytes start with the
// GLB magic "glTF", else scene.gltf. A pathcl::Error or any other std::exception is the
// expected rejection of a bad file; a crash, a sanitizer report, a timeout or running out
// of memory is a finding. Built by -DPATHCL_FUZZ=ON, run by tools/fuzz.sh gltf SECONDS.
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <exception>
#include <string>

#include "fuzz_scratch.h"
#include "scene/gltf_loader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const bool glb = size >= 4 && std::memcmp(data, "glTF", 4) == 0;
    const std::string path = fuzz::scratch_directory("gltf") + (glb ? "/scene.glb" : "/scene.gltf");
    fuzz::write_file(path, data, size);
    try {
        pathcl::Scene scene = pathcl::load_gltf(path);
        (void)scene;
    } catch (const std::exception&) {
        // Rejected: what a bad file should get.
    }
    return 0;
}
