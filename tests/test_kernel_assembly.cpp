// Assembly of the device program's source from the embedded kernel tree
// (host/cl/kernel_source.h): includes resolved once, #line directives naming the real
// files, clear errors for missing includes, cycles and patches that do not apply, and
// every kernel file opening with a comment that says what it holds.
#include <filesystem>
#include <fstream>
#include <iterator>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "cl/embedded_kernels.h"
#include "cl/kernel_source.h"
#include "common/error.h"
#include "support/expect_error.h"

namespace pathcl::test_kernel_assembly {
namespace {

std::size_t count(const std::string& text, const std::string& what)
{
    std::size_t n = 0;
    for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1))
        ++n;
    return n;
}

ProgramSource root(const std::string& text)
{
    ProgramSource s;
    s.root = "tests/root.cl";
    s.text = text;
    return s;
}

TEST(KernelAssembly, IncludesAreResolvedOnceWithLineDirectives)
{
    std::string out = assemble_kernel_source(root("#include \"util/hash.cl\"\n#include \"util/hash.cl\"\nint x;\n"));
    EXPECT_EQ(count(out, "static inline uint hash_u32("), 1u) << "included twice";
    EXPECT_EQ(count(out, "#line 1 \"util/hash.cl\""), 1u);
    EXPECT_EQ(out.find("#line 1 \"tests/root.cl\""), 0u);
    // After the included file, diagnostics count the root's lines again from line 2.
    EXPECT_NE(out.find("#line 2 \"tests/root.cl\"\n\nint x;\n"), std::string::npos) << out.substr(out.size() - 200);
    EXPECT_EQ(count(out, "#include"), 0u);
}

TEST(KernelAssembly, TheRenderProgramHoldsEveryKernel)
{
    std::string out = assemble_kernel_source(ProgramSource{});
    for (const char* kernel : {"generate_camera_rays", "trace_paths", "clear_film", "sampler_points"})
        EXPECT_EQ(count(out, std::string("PATHCL_KERNEL void ") + kernel + "("), 1u) << kernel;
}

TEST(KernelAssembly, EveryKernelIsDeclaredWithPathclKernel)
{
    // PATHCL_KERNEL (util/compat.h) carries the per-device workaround attributes
    // (host/cl/device_workarounds.h); a kernel declared with a bare __kernel would miss
    // them. Test kernels included.
    std::vector<std::pair<std::string, std::string>> files;
    for (const EmbeddedFile& f : embedded_kernel_files())
        files.emplace_back(f.name, f.text);
    for (const auto& entry : std::filesystem::directory_iterator(std::string(PATHCL_SOURCE_DIR) + "/tests/kernels"))
        files.emplace_back(entry.path().string(),
                           std::string(std::istreambuf_iterator<char>(std::ifstream(entry.path()).rdbuf()), {}));
    std::size_t kernels = 0;
    for (const auto& [name, text] : files) {
        kernels += count(text, "PATHCL_KERNEL void ");
        if (name != "util/compat.h") {
            EXPECT_EQ(count(text, "__kernel"), 0u) << name;
        }
    }
    EXPECT_GT(kernels, 30u);
}

TEST(KernelAssembly, MissingIncludesAndCyclesAreErrors)
{
    EXPECT_TRUE(
        test::contains(test::error_of([&] { assemble_kernel_source(root("\n#include \"util/nothing.cl\"\n")); }),
                       "tests/root.cl:2: includes \"util/nothing.cl\", which is not a file of the kernel tree"));
    EXPECT_TRUE(test::contains(test::error_of([&] { assemble_kernel_source(root("#include \"tests/root.cl\"\n")); }),
                               "an include cycle"));
    ProgramSource unknown;
    unknown.root = "nothing.cl";
    EXPECT_TRUE(test::contains(test::error_of([&] { assemble_kernel_source(unknown); }),
                               "nothing.cl is not a file of the kernel tree"));
}

TEST(KernelAssembly, PatchesApplyExactlyOnceOrFail)
{
    ProgramSource s = root("#include \"util/hash.cl\"\n");
    s.patches = {{"util/hash.cl", "x *= 0x7feb352du;", "x *= 3u;"}};
    std::string out = assemble_kernel_source(s);
    EXPECT_EQ(count(out, "x *= 3u;"), 1u);
    EXPECT_EQ(count(out, "0x7feb352du"), 0u);
    s.patches = {{"util/hash.cl", "no such text", ""}};
    EXPECT_TRUE(test::contains(test::error_of([&] { assemble_kernel_source(s); }), "occurs nowhere in util/hash.cl"));
    s.patches = {{"util/hash.cl", "x ^= x >> 16;", ""}}; // twice in hash_u32
    EXPECT_TRUE(
        test::contains(test::error_of([&] { assemble_kernel_source(s); }), "occurs more than once in util/hash.cl"));
    s.patches = {{"util/none.cl", "a", "b"}};
    EXPECT_TRUE(test::contains(test::error_of([&] { assemble_kernel_source(s); }),
                               "util/none.cl is not a file of the kernel tree"));
}

TEST(KernelAssembly, EveryKernelFileOpensWithWhatItHolds)
{
    for (const EmbeddedFile& f : embedded_kernel_files()) {
        std::string text = f.text;
        EXPECT_EQ(text.rfind("/* ", 0), 0u) << f.name << " does not open with a comment";
        std::size_t end = text.find("*/");
        EXPECT_GT(end, 40u) << f.name << ": the opening comment is too short to say what the file holds";
    }
}

} // namespace
} // namespace pathcl::test_kernel_assembly
