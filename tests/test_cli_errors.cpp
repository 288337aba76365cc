// The real `pathcl` binary on bad input: exit status exactly 2, exactly one stderr line
// "pathcl: error: ..." naming the offending file, and no output file written (an existing
// one left byte-identical). Every case here fails before rendering; the render options
// are tiny anyway so that a regression cannot make this test slow.
#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <sstream>
#include <string>

#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

namespace pathcl::test_cli_errors {
namespace {

namespace fs = std::filesystem;

const std::string kBinary = PATHCL_BINARY;
const std::string kCornell = std::string(PATHCL_SOURCE_DIR) + "/scenes/cornell-box.gltf";
const std::string kTiny = " --width 4 --height 4 --spp 1";

// Single-quoted for /bin/sh.
std::string quoted(const std::string& s)
{
    std::string q = "'";
    for (char c : s)
        q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}

std::string read_file(const fs::path& p)
{
    std::ifstream in(p, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

void write_file(const fs::path& p, const std::string& text)
{
    std::ofstream out(p, std::ios::binary);
    out << text;
}

struct RunResult {
    int status = -1; // exit status, -1 when the process did not exit normally
    std::string out, err;
};

// The names of the plain files in `dir` (not recursive) and of its subdirectories.
std::set<std::string> listing(const fs::path& dir)
{
    std::set<std::string> names;
    for (const fs::directory_entry& e : fs::directory_iterator(dir))
        names.insert(e.path().filename().string());
    return names;
}

// A glTF with one triangle whose only buffer lives in `bin_uri`.
std::string gltf_with_external_buffer(const std::string& bin_uri)
{
    return R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
 "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
 "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                "min": [0, 0, 0], "max": [1, 1, 0]}],
 "bufferViews": [{"buffer": 0, "byteLength": 36}],
 "buffers": [{"uri": ")" +
           bin_uri + R"(", "byteLength": 36}]}
)";
}

// Each test works in its own directory: `work` holds scenes and outputs, `capture` holds
// the redirected stdout/stderr (so that `work` shows exactly what the binary created).
class Cli : public ::testing::Test {
protected:
    void SetUp() override
    {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        root_ = fs::temp_directory_path() / ("pathcl-cli-" + std::to_string(::getpid()) + "-" + info->name());
        fs::remove_all(root_);
        work_ = root_ / "work";
        capture_ = root_ / "capture";
        fs::create_directories(work_);
        fs::create_directories(capture_);
    }

    void TearDown() override
    {
        std::error_code ec;
        fs::remove_all(root_, ec);
    }

    RunResult run(const std::string& args) const { return run_limited("", args); }

    // The binary (or a copy of it elsewhere) run after the shell commands `prelude`
    // (limits, traps) in the same shell.
    RunResult run_limited(const std::string& prelude, const std::string& args,
                          const std::string& binary = kBinary) const
    {
        fs::path out = capture_ / "stdout.txt", err = capture_ / "stderr.txt";
        std::string cmd = "cd " + quoted(work_.string()) + " && " + prelude + quoted(binary) + " " + args + " >" +
                          quoted(out.string()) + " 2>" + quoted(err.string());
        int rc = std::system(cmd.c_str());
        RunResult r;
        r.status = rc != -1 && WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
        r.out = read_file(out);
        r.err = read_file(err);
        return r;
    }

    // The common contract of a failing run.
    void expect_clean_failure(const RunResult& r, const std::string& offending_name) const
    {
        EXPECT_EQ(r.status, 2) << "stderr: " << r.err;
        EXPECT_EQ(r.err.rfind("pathcl: error: ", 0), 0u) << "stderr: " << r.err;
        EXPECT_FALSE(r.err.empty());
        if (!r.err.empty()) {
            EXPECT_EQ(r.err.back(), '\n') << "stderr: " << r.err;
        }
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "stderr is not exactly one line: " << r.err;
        EXPECT_NE(r.err.find(offending_name), std::string::npos)
            << "stderr does not name " << offending_name << ": " << r.err;
    }

    fs::path root_, work_, capture_;
};

// (a) a missing scene file
TEST_F(Cli, MissingSceneFile)
{
    RunResult r = run("render " + quoted((work_ / "no-such-scene.gltf").string()) + " -o out.exr" + kTiny);
    expect_clean_failure(r, "no-such-scene.gltf");
    EXPECT_EQ(listing(work_), std::set<std::string>{}) << "an output file was created";
}

// (b) an invalid glTF file: broken JSON
TEST_F(Cli, InvalidJsonScene)
{
    write_file(work_ / "broken.gltf", "{ \"asset\": { \"version\": \"2.0\" }, \"nodes\": [ ");
    RunResult r = run("render broken.gltf -o out.exr" + kTiny);
    expect_clean_failure(r, "broken.gltf");
    EXPECT_EQ(listing(work_), std::set<std::string>{"broken.gltf"}) << "an output file was created";
}

// (b') an invalid glTF file: valid JSON whose mesh names an accessor that does not exist
TEST_F(Cli, SceneWithMissingAccessor)
{
    write_file(work_ / "bad-accessor.gltf", R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
 "nodes": [{"mesh": 0}], "meshes": [{"primitives": [{"attributes": {"POSITION": 7}}]}]})");
    RunResult r = run("render bad-accessor.gltf -o out.exr" + kTiny);
    expect_clean_failure(r, "bad-accessor.gltf");
    EXPECT_EQ(listing(work_), std::set<std::string>{"bad-accessor.gltf"}) << "an output file was created";
}

// (c) a buffer URI that points at a missing .bin: the message names the .bin
TEST_F(Cli, MissingBufferFile)
{
    write_file(work_ / "needs-bin.gltf", gltf_with_external_buffer("missing-data.bin"));
    RunResult r = run("render needs-bin.gltf -o out.exr" + kTiny);
    expect_clean_failure(r, "missing-data.bin");
    EXPECT_EQ(listing(work_), std::set<std::string>{"needs-bin.gltf"}) << "an output file was created";
}

// (d) an output with an unsupported extension
TEST_F(Cli, UnsupportedOutputExtension)
{
    RunResult r = run("render " + quoted(kCornell) + " -o picture.jpg" + kTiny);
    expect_clean_failure(r, "picture.jpg");
    EXPECT_EQ(listing(work_), std::set<std::string>{}) << "an output file was created";
}

// (d'') an image module beside the program that is not one (a broken installation): the
// error names it, and comes before the render (no kernel was built into the empty
// cache). Broken variant seen to fail: the module loaded only when the image was written.
TEST_F(Cli, ABrokenImageModuleIsNamedBeforeTheRender)
{
    const fs::path bin = root_ / "bin";
    fs::create_directories(bin);
    fs::copy_file(kBinary, bin / "pathcl");
    write_file(bin / "libpathcl_oiio.so", "not a shared library");
    const fs::path cache = root_ / "cache";
    fs::create_directories(cache);
    RunResult r = run_limited("PATHCL_CACHE_DIR=" + quoted(cache.string()) + " ",
                              "render " + quoted(kCornell) + " -o out.png" + kTiny, (bin / "pathcl").string());
    expect_clean_failure(r, (bin / "libpathcl_oiio.so").string() + ": cannot load pathcl's image module");
    EXPECT_EQ(listing(work_), std::set<std::string>{}) << "an output file was created";
    EXPECT_EQ(listing(cache), std::set<std::string>{}) << "the render began";
}

// (d') a bad output next to a good one: nothing is written at all
TEST_F(Cli, UnsupportedSecondOutputWritesNeitherOutput)
{
    RunResult r = run("render " + quoted(kCornell) + " -o good.exr -o picture.jpg" + kTiny);
    expect_clean_failure(r, "picture.jpg");
    EXPECT_EQ(listing(work_), std::set<std::string>{}) << "an output file was created";
}

// (e) an output in a directory that does not exist
TEST_F(Cli, OutputDirectoryDoesNotExist)
{
    RunResult r = run("render " + quoted(kCornell) + " -o no-such-dir/out.exr" + kTiny);
    expect_clean_failure(r, "no-such-dir/out.exr");
    EXPECT_EQ(listing(work_), std::set<std::string>{}) << "the directory or an output file was created";
}

// An existing output file survives a failing run byte for byte.
TEST_F(Cli, ExistingOutputIsUnchangedWhenTheSceneIsMissing)
{
    const std::string before = "not an image: pathcl must leave this file alone\n";
    write_file(work_ / "out.exr", before);
    RunResult r = run("render no-such-scene.gltf -o out.exr" + kTiny);
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_EQ(read_file(work_ / "out.exr"), before);
    EXPECT_EQ(listing(work_), std::set<std::string>{"out.exr"}) << "a stray file was created";
}

TEST_F(Cli, ExistingOutputIsUnchangedWhenTheSceneIsInvalid)
{
    const std::string before = "not an image: pathcl must leave this file alone\n";
    write_file(work_ / "out.png", before);
    write_file(work_ / "needs-bin.gltf", gltf_with_external_buffer("missing-data.bin"));
    RunResult r = run("render needs-bin.gltf -o out.png" + kTiny);
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_EQ(read_file(work_ / "out.png"), before);
    EXPECT_EQ(listing(work_), (std::set<std::string>{"needs-bin.gltf", "out.png"})) << "a stray file was created";
}

// Usage errors (CLI11's parse errors) follow the same contract.
// A write that fails after the render (the second -o lands in /proc, where no file can
// be created): one line naming it, and the first output, which was complete, still does
// not replace the user's existing file: outputs are committed together or not at all.
TEST_F(Cli, FailedSecondWriteLeavesTheFirstOutputUntouched)
{
    write_file(work_ / "keep.exr", "the user's earlier render");
    RunResult r = run("render " + quoted(kCornell) + " -o keep.exr -o /proc/pathcl-cannot-write.png" + kTiny);
    expect_clean_failure(r, "pathcl-cannot-write.png");
    EXPECT_EQ(read_file(work_ / "keep.exr"), "the user's earlier render");
    EXPECT_EQ(listing(work_), std::set<std::string>{"keep.exr"}) << "a temporary file was left behind";
}

// A full disk, simulated by a file-size limit (SIGXFSZ ignored, so the write fails with
// EFBIG as it would with ENOSPC): one line naming the output, the user's files unchanged,
// no temporary file. Guards the read-back check: the PNG writer reports no error and left
// 0-byte files in place of both outputs before it.
TEST_F(Cli, FullDiskLeavesExistingOutputsIntactAndNoTemporaryFiles)
{
    const std::string render = "render " + quoted(kCornell) + " --width 64 --height 64 --spp 1 -o ";
    // First unlimited, so that the kernel caches (pathcl's, PoCL's) need no writing after.
    ASSERT_EQ(run(render + quoted((capture_ / "warm.png").string())).status, 0);
    for (const char* name : {"keep.png", "keep.exr"}) {
        write_file(work_ / name, "the user's earlier render");
        RunResult r = run_limited("trap '' XFSZ; ulimit -f 2;", render + name);
        expect_clean_failure(r, name);
        EXPECT_EQ(read_file(work_ / name), "the user's earlier render");
        EXPECT_EQ(listing(work_), std::set<std::string>{name}) << "a temporary file was left behind";
        fs::remove(work_ / name);
    }
}

// An output that is one of the render's inputs (a texture of the scene, the environment
// map) is refused before anything is rendered, and the input stays as it was.
TEST_F(Cli, OutputEqualToAnInputIsRefused)
{
    const fs::path scenes = fs::path(PATHCL_SOURCE_DIR) / "scenes";
    fs::copy(scenes / "textured.gltf", work_ / "textured.gltf");
    fs::copy(scenes / "textures", work_ / "textures");
    const std::string texture = read_file(work_ / "textures" / "tiles-base.png");
    RunResult r = run("render textured.gltf -o textures/tiles-base.png" + kTiny);
    expect_clean_failure(r, "tiles-base.png");
    EXPECT_NE(r.err.find("is an input of this render"), std::string::npos) << r.err;
    EXPECT_EQ(read_file(work_ / "textures" / "tiles-base.png"), texture);

    ASSERT_EQ(run("render textured.gltf -o env.exr" + kTiny).status, 0);
    const std::string env = read_file(work_ / "env.exr");
    r = run("render " + quoted(kCornell) + " --env env.exr -o ./env.exr" + kTiny);
    expect_clean_failure(r, "env.exr");
    EXPECT_EQ(read_file(work_ / "env.exr"), env);
}

// A scene with nothing to light it renders black, as it should, but says so in one warning
// line; light from the command line (--background) silences it. Broken variant seen to
// fail: no warning (the black image came without a word).
TEST_F(Cli, SceneWithoutLightWarnsThatTheImageIsBlack)
{
    write_file(work_ / "dark.gltf", gltf_with_external_buffer("tri.bin"));
    const float tri[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    write_file(work_ / "tri.bin", std::string(reinterpret_cast<const char*>(tri), sizeof tri));
    RunResult r = run("render dark.gltf -o dark.exr" + kTiny);
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.err, "pathcl: warning: dark.gltf: has no light (no emissive material, punctual light or environment) "
                     "and no unlit material: the image is black (--background R,G,B or --env FILE adds light)\n");
    r = run("render dark.gltf -o lit.exr --background 1,1,1" + kTiny);
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.err, "");
}

// An image that does not fit the device is refused before anything is allocated, naming
// what it needs and the device's limit (it was OpenCL error -61 from clCreateBuffer, or a
// crash inside the driver). The device reports 1 GiB (POCL_MEMORY_LIMIT): the host has
// room for the film, the device has not.
TEST_F(Cli, ImageLargerThanTheDeviceIsOneLineError)
{
    RunResult r = run_limited("POCL_MEMORY_LIMIT=1 ",
                              "render " + quoted(kCornell) + " -o out.exr --spp 1 --width 4096 --height 4096");
    expect_clean_failure(r, "device 0");
    EXPECT_NE(r.err.find("the film of 16777216 pixels"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("GiB"), std::string::npos) << r.err;
    EXPECT_EQ(listing(work_), std::set<std::string>{}) << "an output file was created";
}

TEST_F(Cli, UnknownSamplerIsOneLineError)
{
    RunResult r = run("render " + quoted(kCornell) + " -o out.exr --sampler bogus" + kTiny);
    expect_clean_failure(r, "--sampler");
    EXPECT_EQ(listing(work_), std::set<std::string>{}) << "an output file was created";
}

// Camera flags that make no camera fail before rendering, naming the flag.
TEST_F(Cli, ApertureWithoutFocusDistance)
{
    RunResult r = run("render " + quoted(kCornell) + " -o out.exr --aperture 0.01" + kTiny);
    expect_clean_failure(r, "--aperture: needs --focus-distance");
    EXPECT_EQ(listing(work_), std::set<std::string>{}) << "an output file was created";
}

TEST_F(Cli, CameraIndexPastTheLastCameraNode)
{
    RunResult r = run("render " + quoted(kCornell) + " -o out.exr --camera 1" + kTiny);
    expect_clean_failure(r, "--camera: there is no camera node 1");
    EXPECT_EQ(listing(work_), std::set<std::string>{}) << "an output file was created";
}

TEST_F(Cli, VariantTheSceneDoesNotHave)
{
    RunResult r = run("render " + quoted(kCornell) + " -o out.exr --variant gold" + kTiny);
    expect_clean_failure(r, "--variant: there is no material variant \"gold\"");
}

TEST_F(Cli, LookAtEqualToLookFrom)
{
    RunResult r = run("render " + quoted(kCornell) + " -o out.exr --look-from 1,2,3 --look-at 1,2,3" + kTiny);
    expect_clean_failure(r, "--look-at");
    EXPECT_EQ(listing(work_), std::set<std::string>{}) << "an output file was created";
}

TEST_F(Cli, RayLogMustBePly)
{
    RunResult r = run("render " + quoted(kCornell) + " -o out.exr --ray-log rays.txt" + kTiny);
    expect_clean_failure(r, "rays.txt");
    EXPECT_EQ(listing(work_), std::set<std::string>{}) << "an output file was created";
}

TEST_F(Cli, SamplePlotMustBePng)
{
    RunResult r = run("samples --sampler sobol --spp 16 -o points.jpg");
    expect_clean_failure(r, "points.jpg");
    r = run("samples --sampler sobol --spp 16 -o points.exr");
    expect_clean_failure(r, "points.exr");
    r = run("samples --sampler sobol --spp 16 --dims 3,3 -o points.png");
    expect_clean_failure(r, "--dims");
    EXPECT_EQ(listing(work_), std::set<std::string>{}) << "an output file was created";
}

TEST_F(Cli, RenderHelpExitsZero)
{
    RunResult r = run("render --help");
    EXPECT_EQ(r.status, 0) << r.err;
}

TEST_F(Cli, DevicesListsDeviceZero)
{
    RunResult r = run("devices");
    EXPECT_EQ(r.status, 0) << r.out << r.err;
    bool found = false;
    std::istringstream lines(r.out);
    for (std::string line; std::getline(lines, line);)
        found = found || line.rfind("0: ", 0) == 0;
    EXPECT_TRUE(found) << "no line starts with \"0: \":\n" << r.out;
}

// Strings from files and flags are quoted escaped and shortened: a variant name with a
// line break keeps the error on one line. Broken variant seen to fail: two lines.
TEST_F(Cli, AQuotedNameWithALineBreakKeepsTheErrorOnOneLine)
{
    RunResult r = run("render " + quoted(kCornell) + " -o out.exr --variant \"$(printf 'gold\\nand silver')\"" + kTiny);
    expect_clean_failure(r, "there is no material variant \"gold\\nand silver\"");
    std::string long_name(5000, 'x');
    r = run("render " + quoted(kCornell) + " -o out.exr --variant " + long_name + kTiny);
    expect_clean_failure(r, "\"" + std::string(80, 'x') + "\"... (5000 bytes)");
    EXPECT_LT(r.err.size(), 300u) << r.err;
}

// A film larger than the process may allocate under its address-space limit (`ulimit
// -v`; a cgroup's memory.max is read the same way) is refused before any device is
// set up, naming the limit. 4096 x 4096 needs 6.75 GiB; the limit is 3 GB. Broken
// variant seen to fail: admission compared with the machine's memory and the render died
// of "std::bad_alloc".
TEST_F(Cli, AFilmBeyondTheProcesssMemoryLimitIsRefusedNamingIt)
{
#if defined(__SANITIZE_ADDRESS__)
    GTEST_SKIP() << "AddressSanitizer reserves terabytes of address space: no ulimit -v under it";
#else
    RunResult r = run_limited("ulimit -v 3000000;",
                              "render " + quoted(kCornell) + " -o out.exr --width 4096 --height 4096 --spp 1");
    expect_clean_failure(r, "the film needs 6.75 GiB of host memory, more than the room left under the process's "
                            "address-space limit");
    EXPECT_EQ(listing(work_), std::set<std::string>{}) << "an output file was created";
#endif
}

// A study's ladder and targets are checked as given, and a study too large to run is
// refused with what it would take, before the reference is rendered. Broken variants
// seen to fail: "4,2,1" and "1,1" were sorted and deduplicated, "1,,2" read as 1,2,
// "nan" passed as a target, and 2000 x 2000 values planned 4,000,000 settings and
// started.
TEST_F(Cli, ConvergeLaddersTargetsAndPlansAreChecked)
{
    const std::string converge = "converge " + quoted(kCornell) + " -o study --width 4 --height 4 ";
    for (const char* ladder : {"4,2,1", "1,1", "1,,2", "0,1"}) {
        RunResult r = run(converge + "--vary strategy=mis --spp-ladder " + ladder);
        expect_clean_failure(r, "--spp-ladder");
    }
    RunResult r = run(converge + "--vary strategy=mis --spp-ladder 1,2 --targets 0.01,nan");
    expect_clean_failure(r, "--targets: \"nan\"");
    std::string many_a = "--vary max-bounces=0", many_b = " --vary stratified-bounces=0";
    for (int i = 1; i < 2000; ++i) {
        many_a += "," + std::to_string(i);
        many_b += "," + std::to_string(i);
    }
    r = run(converge + many_a + many_b);
    expect_clean_failure(r, "2000 max-bounces x 2000 stratified-bounces make 4000000 settings");
    r = run(converge + "--vary max-bounces=1,2,3,4,5,6,7,8,9,10,11,12,13,14,15,16 --spp-ladder 1,2,3,4,5,6,7,8,9,10 "
                       "--seeds 1000");
    expect_clean_failure(r, "make 160000 renders");
    EXPECT_EQ(listing(work_), std::set<std::string>{}) << "the study directory was created";
}

// A budget given as NaN is neither a budget nor none: refused as itself, not as a
// --max-spp that "caps no budgeted render". Broken variant seen to fail: the errors named
// --max-spp.
TEST_F(Cli, NanBudgetsAreRefusedAsThemselves)
{
    RunResult r = run("render " + quoted(kCornell) + " -o out.exr --time nan --max-spp 4 --width 4 --height 4");
    expect_clean_failure(r, "--time: must be a finite number");
    r = run("render " + quoted(kCornell) + " -o out.exr --target-error nan --max-spp 4 --width 4 --height 4");
    expect_clean_failure(r, "--target-error: must be a finite");
    EXPECT_EQ(listing(work_), std::set<std::string>{}) << "an output file was created";
}

// Each of --background and --env-strength finite, their product not: refused, where it
// rendered NaN and Inf samples and exited 0 (seen to fail before the product was checked).
TEST_F(Cli, BackgroundTimesStrengthBeyondFloatIsRefused)
{
    RunResult r =
        run("render " + quoted(kCornell) + " -o out.exr --background 1e38,1e38,1e38 --env-strength 1e10" + kTiny);
    expect_clean_failure(r, "--background: the environment's radiance (colour 1e+38 x strength 1e+10)");
    EXPECT_EQ(listing(work_), std::set<std::string>{}) << "an output file was created";
}

// compare's images of two sizes: the error names both files. Broken variant seen to
// fail: "images differ in size" named neither.
TEST_F(Cli, CompareOfTwoSizesNamesBothFiles)
{
    ASSERT_EQ(run("render " + quoted(kCornell) + " -o a.exr" + kTiny).status, 0);
    ASSERT_EQ(run("render " + quoted(kCornell) + " -o b.exr --width 8 --height 4 --spp 1").status, 0);
    RunResult r = run("compare a.exr b.exr");
    expect_clean_failure(r, "b.exr: is 8x4, a.exr 4x4");
}

TEST_F(Cli, PathclPlatformNarrowsTheDevicesOrIsAOneLineError)
{
    // PATHCL_PLATFORM (host/cl/cl_runtime.cpp) aims every command, and the device tests,
    // at the platforms whose name contains it, ignoring case; one that matches none is an
    // error, not an empty list.
    RunResult all = run("devices");
    ASSERT_EQ(all.status, 0) << all.err;
    const std::size_t bar = all.out.find(" | ");
    ASSERT_NE(bar, std::string::npos) << all.out;
    const std::string platform = all.out.substr(3, bar - 3); // "0: <platform> | ..."
    std::string shouted = platform;
    std::transform(shouted.begin(), shouted.end(), shouted.begin(),
                   [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
    RunResult one = run_limited("PATHCL_PLATFORM='" + shouted + "' ", "devices");
    EXPECT_EQ(one.status, 0) << one.err;
    std::istringstream lines(one.out);
    std::size_t listed = 0;
    for (std::string line; std::getline(lines, line); ++listed)
        EXPECT_NE(line.find(": " + platform + " | "), std::string::npos) << line;
    EXPECT_GT(listed, 0u);
    RunResult none = run_limited("PATHCL_PLATFORM=no-such-platform ", "devices");
    expect_clean_failure(none, "PATHCL_PLATFORM=no-such-platform");
}

} // namespace
} // namespace pathcl::test_cli_errors
