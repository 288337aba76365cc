// Hostile glTF files through load_gltf (host only): files a scene must not make pathcl read
// (URIs leaving the scene's directory, absolute paths, links leading out, directories,
// FIFOs, the working-directory fallback), GLB containers whose chunks run past the end,
// JSON nested deep enough to overflow a recursive parser, node graphs that are not trees,
// values that overflow single precision, and images that would decode to gigabytes. Each
// is a one-line pathcl::Error naming the file, within the test's time limit. Next to each
// test: what it guards against.
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

#include <gtest/gtest.h>

#include "image/image_module.h"
#include "scene/gltf_loader.h"
#include "support/expect_error.h"

namespace pathcl::test_gltf_hostile_files {
namespace {

namespace fs = std::filesystem;
using test::contains;
using test::error_of;

class Dir {
public:
    Dir()
    {
        const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
        root_ = fs::temp_directory_path() / ("pathcl-hostile-" + std::to_string(::getpid()) + "-" + info->name());
        fs::remove_all(root_);
        fs::create_directories(root_ / "scene");
    }
    ~Dir() { fs::remove_all(root_); }
    const fs::path& root() const { return root_; }
    fs::path scene() const { return root_ / "scene"; }

private:
    fs::path root_;
};

void write_file(const fs::path& p, const std::string& bytes)
{
    std::ofstream out(p, std::ios::binary);
    out << bytes;
}

// One triangle: three float positions, 36 bytes.
std::string triangle_bytes()
{
    const float p[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    return std::string(reinterpret_cast<const char*>(p), sizeof p);
}

// A glTF with one triangle whose buffer is `buffer` (a uri member, or nothing for a GLB's
// BIN chunk), `extra_scene` inserted into the scene object and `nodes` as the node list.
std::string gltf_text(const std::string& buffer, const std::string& nodes = R"([{"mesh": 0}])",
                      const std::string& roots = "[0]", const std::string& extra = "")
{
    return R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": )" + roots + R"(}], "nodes": )" + nodes +
           R"(, "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
 "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                "min": [0, 0, 0], "max": [1, 1, 0]}],
 "bufferViews": [{"buffer": 0, "byteLength": 36}],
 "buffers": [{"byteLength": 36)" +
           buffer + "}]" + extra + "}";
}

std::string uri(const std::string& u)
{
    return R"(, "uri": ")" + u + "\"";
}

// Control: a buffer beside the scene and one in a subdirectory load.
TEST(GltfHostileFiles, BuffersInsideTheScenesDirectoryLoad)
{
    Dir d;
    fs::create_directory(d.scene() / "sub");
    write_file(d.scene() / "sub" / "tri.bin", triangle_bytes());
    write_file(d.scene() / "a.gltf", gltf_text(uri("sub/tri.bin")));
    EXPECT_EQ(load_gltf((d.scene() / "a.gltf").string()).triangles.size(), 1u);
    write_file(d.scene() / "b.gltf", gltf_text(uri("sub/../sub/tri.bin")));
    EXPECT_EQ(load_gltf((d.scene() / "b.gltf").string()).triangles.size(), 1u);
}

// Guards the confined file callbacks (without them the file outside is read).
TEST(GltfHostileFiles, BufferUriLeavingTheScenesDirectoryIsRefused)
{
    Dir d;
    write_file(d.root() / "tri.bin", triangle_bytes());
    fs::path file = d.scene() / "up.gltf";
    write_file(file, gltf_text(uri("../tri.bin")));
    std::string msg = error_of([&] { load_gltf(file.string()); });
    EXPECT_EQ(msg.rfind(file.string() + ": ", 0), 0u) << msg;
    EXPECT_TRUE(contains(msg, "../tri.bin: leaves the scene's directory")) << msg;
}

TEST(GltfHostileFiles, AbsoluteBufferUriIsRefused)
{
    Dir d;
    fs::path file = d.scene() / "abs.gltf";
    write_file(file, gltf_text(uri("/etc/passwd")));
    std::string msg = error_of([&] { load_gltf(file.string()); });
    EXPECT_TRUE(contains(msg, "/etc/passwd: is an absolute path")) << msg;
}

TEST(GltfHostileFiles, LinkLeadingOutOfTheScenesDirectoryIsRefused)
{
    Dir d;
    write_file(d.root() / "tri.bin", triangle_bytes());
    fs::create_symlink(d.root() / "tri.bin", d.scene() / "link.bin");
    fs::path file = d.scene() / "link.gltf";
    write_file(file, gltf_text(uri("link.bin")));
    std::string msg = error_of([&] { load_gltf(file.string()); });
    EXPECT_TRUE(contains(msg, "link.bin: leaves the scene's directory")) << msg;
}

// Guards the refusal of tinygltf's "./uri" candidate (without it the working
// directory's file is read and one triangle loads).
TEST(GltfHostileFiles, MissingBufferIsNotReadFromTheWorkingDirectory)
{
    Dir d;
    fs::create_directory(d.root() / "cwd");
    write_file(d.root() / "cwd" / "tri.bin", triangle_bytes());
    fs::path file = d.scene() / "missing.gltf";
    write_file(file, gltf_text(uri("tri.bin")));
    fs::path before = fs::current_path();
    fs::current_path(d.root() / "cwd");
    std::string msg = error_of([&] { load_gltf(file.string()); });
    fs::current_path(before);
    EXPECT_TRUE(contains(msg, "tri.bin: no such file in the scene's directory")) << msg;
}

// Guards the regular-file checks (without them and O_NONBLOCK, opening the FIFO blocks
// until the test's timeout).
TEST(GltfHostileFiles, BufferUriNamingADirectoryOrAFifoIsRefused)
{
    Dir d;
    fs::create_directory(d.scene() / "dir.bin");
    ASSERT_EQ(::mkfifo((d.scene() / "fifo.bin").c_str(), 0600), 0);
    for (const char* name : {"dir.bin", "fifo.bin"}) {
        fs::path file = d.scene() / (std::string(name) + ".gltf");
        write_file(file, gltf_text(uri(name)));
        std::string msg = error_of([&] { load_gltf(file.string()); });
        EXPECT_TRUE(contains(msg, std::string(name) + ": is not a regular file")) << msg;
    }
}

// A GLB: header, JSON chunk (padded with spaces), BIN chunk; `bin_length_delta` lies
// about the BIN chunk's length, `version` and `total_delta` about the header.
std::string glb(const std::string& json_text, const std::string& bin, std::int64_t bin_length_delta = 0,
                std::uint32_t version = 2, std::int64_t total_delta = 0)
{
    std::string json = json_text;
    while (json.size() % 4)
        json += ' ';
    auto u32 = [](std::uint64_t v) {
        std::string s(4, '\0');
        for (int i = 0; i < 4; ++i)
            s[static_cast<std::size_t>(i)] = static_cast<char>((v >> (8 * i)) & 0xff);
        return s;
    };
    std::uint64_t total = 12 + 8 + json.size() + 8 + bin.size();
    return "glTF" + u32(version) + u32(static_cast<std::uint64_t>(static_cast<std::int64_t>(total) + total_delta)) +
           u32(json.size()) + "JSON" + json +
           u32(static_cast<std::uint64_t>(static_cast<std::int64_t>(bin.size()) + bin_length_delta)) +
           std::string("BIN\0", 4) + bin;
}

// Guards check_glb (without it the glTF library reads past its buffer when a chunk runs
// past the end, as AddressSanitizer reports).
TEST(GltfHostileFiles, MalformedGlbContainersAreRefused)
{
    Dir d;
    fs::path good = d.scene() / "good.glb";
    write_file(good, glb(gltf_text(""), triangle_bytes()));
    EXPECT_EQ(load_gltf(good.string()).triangles.size(), 1u); // control
    struct Case {
        std::string bytes, expected;
    } cases[] = {
        {glb(gltf_text(""), triangle_bytes(), 8), "runs past the end of the file"},
        {glb(gltf_text(""), triangle_bytes(), 0x7fffffff), "runs past the end of the file"},
        {glb(gltf_text(""), triangle_bytes(), 0, 1), "GLB version 1"},
        {glb(gltf_text(""), triangle_bytes(), 0, 2, 4), "the GLB header says"},
        {glb(gltf_text(""), triangle_bytes()).substr(0, 30), "the GLB header says"},
        {std::string("glTF\2\0\0\0", 8), "not a GLB file"},
    };
    for (const Case& c : cases) {
        fs::path file = d.scene() / "bad.glb";
        write_file(file, c.bytes);
        std::string msg = error_of([&] { load_gltf(file.string()); });
        EXPECT_EQ(msg.rfind(file.string() + ": ", 0), 0u) << msg;
        EXPECT_TRUE(contains(msg, c.expected)) << msg;
    }
}

// Guards check_json_nesting (without it the stack overflows in the glTF library's
// recursive conversion of extras: SIGSEGV).
TEST(GltfHostileFiles, DeeplyNestedJsonIsRefused)
{
    Dir d;
    const std::size_t depth = 100000;
    std::string nested = std::string(depth, '[') + std::string(depth, ']');
    write_file(d.scene() / "tri.bin", triangle_bytes());
    fs::path file = d.scene() / "deep.gltf";
    write_file(file, gltf_text(uri("tri.bin"), R"([{"mesh": 0}])", "[0]", R"(, "extras": )" + nested));
    std::string msg = error_of([&] { load_gltf(file.string()); });
    EXPECT_TRUE(contains(msg, "JSON nested deeper than 256 levels")) << msg;
    // Control: brackets inside a string are text, not nesting.
    write_file(file, gltf_text(uri("tri.bin"), R"([{"mesh": 0}])", "[0]", R"(, "extras": {"a": ")" + nested + "\"}"));
    EXPECT_EQ(load_gltf(file.string()).triangles.size(), 1u);
}

// Guards check_forest (without it the walk visits 2^39 nodes and runs out of time and
// memory).
TEST(GltfHostileFiles, NodeWithTwoParentsIsRefusedAtOnce)
{
    Dir d;
    write_file(d.scene() / "tri.bin", triangle_bytes());
    std::string nodes = "[";
    for (int i = 0; i < 40; ++i)
        nodes += "{\"mesh\": 0, \"children\": [" + std::to_string(i + 1) + ", " + std::to_string(i + 1) + "]}, ";
    nodes += R"({"mesh": 0}])";
    fs::path file = d.scene() / "dag.gltf";
    write_file(file, gltf_text(uri("tri.bin"), nodes));
    std::string msg = error_of([&] { load_gltf(file.string()); });
    EXPECT_TRUE(contains(msg, "node 1 is a child of node 0 and of node 0 (a glTF node has at most one parent)")) << msg;

    write_file(file, gltf_text(uri("tri.bin"), R"([{"mesh": 0}, {"children": [0]}])", "[0, 1]"));
    msg = error_of([&] { load_gltf(file.string()); });
    EXPECT_TRUE(contains(msg, "root node 0 is a child of node 1")) << msg;

    write_file(file, gltf_text(uri("tri.bin"), R"([{"mesh": 0}])", "[0, 0]"));
    msg = error_of([&] { load_gltf(file.string()); });
    EXPECT_TRUE(contains(msg, "lists root node 0 twice")) << msg;
}

// Guards the single-precision checks (without them the light's radiance is inf on the
// device).
TEST(GltfHostileFiles, LightValuesThatOverflowSinglePrecisionAreRefused)
{
    Dir d;
    write_file(d.scene() / "tri.bin", triangle_bytes());
    auto light_scene = [&](const std::string& light, const std::string& node_extras) {
        return gltf_text(
            uri("tri.bin"),
            R"([{"mesh": 0}, {"extensions": {"KHR_lights_punctual": {"light": 0}})" + node_extras + "}]", "[0, 1]",
            R"(, "extensionsUsed": ["KHR_lights_punctual"], "extensions": {"KHR_lights_punctual": {"lights": [)" +
                light + "]}}");
    };
    fs::path file = d.scene() / "light.gltf";
    write_file(file, light_scene(R"({"type": "point", "intensity": 1e39})", ""));
    EXPECT_TRUE(contains(error_of([&] { load_gltf(file.string()); }), "overflows single precision"));
    write_file(file, light_scene(R"({"type": "point", "intensity": 10, "extras": {"radius": 1e-40}})", ""));
    EXPECT_TRUE(contains(error_of([&] { load_gltf(file.string()); }), "radiance overflows"));
    write_file(file, light_scene(R"({"type": "point", "intensity": 10, "extras": {"radius": 0.01}})", ""));
    EXPECT_EQ(load_gltf(file.string()).lights.size(), 1u); // control
}

std::string be32(std::uint32_t v)
{
    return std::string{static_cast<char>(v >> 24), static_cast<char>(v >> 16), static_cast<char>(v >> 8),
                       static_cast<char>(v)};
}

// A PNG chunk: length, type and data, CRC-32 of type and data (as PNG defines it).
std::string png_chunk(const std::string& type_and_data)
{
    std::uint32_t crc = 0xffffffffu;
    for (unsigned char c : type_and_data) {
        crc ^= c;
        for (int k = 0; k < 8; ++k)
            crc = (crc >> 1) ^ (0xedb88320u & (0u - (crc & 1u)));
    }
    return be32(static_cast<std::uint32_t>(type_and_data.size() - 4)) + type_and_data + be32(crc ^ 0xffffffffu);
}

// A PNG whose header claims width x height RGBA8 texels (40 GB for 100000^2) and whose
// pixel data is an empty zlib stream: a decoder that trusts the header allocates first.
std::string png_claiming(std::uint32_t width, std::uint32_t height)
{
    return std::string("\x89PNG\r\n\x1a\n", 8) +
           png_chunk("IHDR" + be32(width) + be32(height) + std::string("\x08\x06\x00\x00\x00", 5)) +
           png_chunk(std::string("IDAT\x78\x9c\x03\x00\x00\x00\x00\x01", 12)) + png_chunk("IEND");
}

// Guards keep_encoded_image and the header check (decoding every image at load fails on
// the unused one; trusting the header allocates 40 GB).
TEST(GltfHostileFiles, OnlyUsedImagesAreDecodedAndHugeOnesAreRefusedFromTheHeader)
{
    Dir d;
    write_file(d.scene() / "tri.bin", triangle_bytes());
    write_file(d.scene() / "huge.png", png_claiming(100000, 100000));
    fs::path file = d.scene() / "images.gltf";
    write_file(file, gltf_text(uri("tri.bin"), R"([{"mesh": 0}])", "[0]", R"(, "images": [{"uri": "huge.png"}])"));
    EXPECT_EQ(load_gltf(file.string()).images.size(), 0u); // not used: not decoded, no error

    std::string used = gltf_text(uri("tri.bin"), R"([{"mesh": 0}])", "[0]",
                                 R"(, "images": [{"uri": "huge.png"}], "textures": [{"source": 0}],
                                  "materials": [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}])");
    used.replace(used.find(R"("attributes")"), 0, R"("material": 0, )");
    write_file(file, used);
    std::string msg = error_of([&] { load_gltf(file.string()); });
    EXPECT_TRUE(contains(msg, "unsupported image size 100000x100000")) << msg;
}

// The memory an image's decoding takes (the decoder's copy and the RGBA image) is
// admitted against what the process may still take, its address-space limit included,
// before it is allocated: a one-line error naming the image and the limit. Run in a
// child process under RLIMIT_AS (`ulimit -v`) 256 MiB above what it has mapped, with an
// 8192 x 8192 RGBA8 image (256 MiB decoded, as much again for the decoder's copy).
// Broken variant seen to fail: the admission counted the machine's memory only, and the
// decode ended in std::bad_alloc, which names nothing.
TEST(GltfHostileFiles, AnImageWhoseDecodingExceedsTheProcesssLimitIsRefused)
{
#if defined(__SANITIZE_ADDRESS__)
    GTEST_SKIP() << "AddressSanitizer reserves terabytes of address space: no RLIMIT_AS under it";
#else
    Dir d;
    write_file(d.scene() / "tri.bin", triangle_bytes());
    write_file(d.scene() / "big.png", png_claiming(8192, 8192));
    std::string used = gltf_text(uri("tri.bin"), R"([{"mesh": 0}])", "[0]",
                                 R"(, "images": [{"uri": "big.png"}], "textures": [{"source": 0}],
                                  "materials": [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}])");
    used.replace(used.find(R"("attributes")"), 0, R"("material": 0, )");
    const fs::path file = d.scene() / "big.gltf";
    write_file(file, used);
    const pid_t pid = ::fork();
    ASSERT_GE(pid, 0);
    if (pid == 0) {
        (void)image_module(); // its libraries (OpenImageIO's) are the program's, not the image's
        double mapped = 0.0;
        std::ifstream("/proc/self/statm") >> mapped;
        struct rlimit limit {};
        limit.rlim_cur = limit.rlim_max =
            static_cast<rlim_t>(mapped * static_cast<double>(::sysconf(_SC_PAGE_SIZE))) + (rlim_t(256) << 20);
        if (::setrlimit(RLIMIT_AS, &limit) != 0)
            ::_exit(4);
        try {
            load_gltf(file.string());
            ::_exit(3);
        } catch (const Error& e) {
            const std::string m = e.what();
            ::_exit(contains(m, "big.gltf: ") && contains(m, "big.png") && contains(m, "address-space limit") ? 0 : 1);
        } catch (...) {
            ::_exit(2);
        }
    }
    int status = 0;
    ASSERT_EQ(::waitpid(pid, &status, 0), pid);
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 0) << "1: an error that does not name the image and the limit; 2: not a "
                                         "pathcl::Error (std::bad_alloc); 3: loaded; 4: setrlimit failed";
#endif
}

// Indices inside extensions, read by tinygltf into an int: 2^32 wrapped to 0 and named
// the first variant (or accessor). Each is checked in the JSON as every other index is.
// Broken variant seen to fail: the variant index 2^32 selected variant 0 and the file
// loaded.
TEST(GltfHostileFiles, ExtensionIndicesBeyondIntAreRefused)
{
    Dir d;
    const std::string variants = R"(, "extensionsUsed": ["KHR_materials_variants"], "materials": [{}, {}],
 "extensions": {"KHR_materials_variants": {"variants": [{"name": "a"}, {"name": "b"}]}})";
    std::string text = gltf_text(uri("tri.bin"), R"([{"mesh": 0}])", "[0]", variants);
    const std::string prim = R"({"attributes": {"POSITION": 0}})";
    text.replace(text.find(prim), prim.size(),
                 R"({"attributes": {"POSITION": 0}, "material": 0, "extensions": {"KHR_materials_variants":
                     {"mappings": [{"material": 1, "variants": [4294967296]}]}}})");
    write_file(d.scene() / "tri.bin", triangle_bytes());
    write_file(d.scene() / "variant.gltf", text);
    std::string msg = error_of([&] { load_gltf((d.scene() / "variant.gltf").string()); });
    EXPECT_TRUE(contains(msg, "variant.gltf: meshes[0].primitives[0].extensions.KHR_materials_variants.mappings[0]."
                              "variants[0] is 4294967296, which names none of the 2 KHR_materials_variants variants"))
        << msg;

    std::string instanced = gltf_text(uri("tri.bin"),
                                      R"([{"mesh": 0, "extensions": {"EXT_mesh_gpu_instancing": {"attributes":
                                          {"TRANSLATION": 4294967296}}}}])",
                                      "[0]", R"(, "extensionsUsed": ["EXT_mesh_gpu_instancing"])");
    write_file(d.scene() / "instances.gltf", instanced);
    msg = error_of([&] { load_gltf((d.scene() / "instances.gltf").string()); });
    EXPECT_TRUE(contains(msg, "nodes[0].extensions.EXT_mesh_gpu_instancing.attributes.TRANSLATION is 4294967296"))
        << msg;
}

} // namespace
} // namespace pathcl::test_gltf_hostile_files
