// libFuzzer target: the command line's values. The input is an argument list (arguments
// separated by NUL bytes) given to the real `pathcl` command line (host/cli: CLI11's
// parsing, every command's checks of its flags and files) and run as main() runs it, in a
// per-process temporary directory holding a small valid scene (scene.gltf) and nothing
// else (the working directory while the input runs). No OpenCL platform is visible (OCL_ICD_VENDORS names none), so a
// command that gets as far as a device ends there with an error; arguments naming paths outside the directory ('/' in
// them) are skipped, so nothing outside it is read or written. A pathcl::Error (or CLI11's) is the expected rejection;
// a crash, a sanitizer report, a timeout or running out of memory is a finding. Built by -DPATHCL_FUZZ=ON, run by
// tools/fuzz.sh cli SECONDS.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <fcntl.h>
#include <unistd.h>

#include <CLI/CLI.hpp>

#include "cli/command_line.h"
#include "cli/usage_errors.h"
#include "fuzz_scratch.h"

namespace {

// One triangle lit by an emissive material, its buffer a data: URI.
const char* const kScene =
    R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
"meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "material": 0}]}],
"materials": [{"emissiveFactor": [1, 1, 1]}],
"accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0]}],
"bufferViews": [{"buffer": 0, "byteLength": 36}],
"buffers": [{"byteLength": 36, "uri": "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"}]})";

// The scratch directory, where each input runs, and the directory libFuzzer works in
// (its corpus and findings are relative paths), restored after each input.
int scratch_fd = -1, home_fd = -1;

void keep_only_the_scene(const std::string& dir)
{
    std::error_code ec;
    for (const auto& e : std::filesystem::directory_iterator(dir, ec))
        if (e.path().filename() != "scene.gltf")
            std::filesystem::remove_all(e.path(), ec);
}

} // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***)
{
    ::setenv("OCL_ICD_VENDORS", "/nonexistent-pathcl-fuzz", 1); // no OpenCL platform
    ::setenv("OCL_ICD_FILENAMES", "", 1);
    const std::string& dir = fuzz::scratch_directory("cli");
    fuzz::write_file(dir + "/scene.gltf", reinterpret_cast<const std::uint8_t*>(kScene),
                     std::char_traits<char>::length(kScene));
    scratch_fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    home_fd = ::open(".", O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (scratch_fd < 0 || home_fd < 0)
        std::abort();
    const int null = ::open("/dev/null", O_WRONLY | O_CLOEXEC); // the commands' summaries
    if (null >= 0)
        ::dup2(null, STDOUT_FILENO);
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    if (size > 4096)
        return 0;
    std::vector<std::string> args = {"pathcl"};
    std::string arg;
    for (std::size_t i = 0; i <= size; ++i) {
        if (i == size || data[i] == 0) {
            if (arg.find('/') != std::string::npos)
                return 0; // only names inside the scratch directory
            args.push_back(arg);
            arg.clear();
        } else {
            arg += static_cast<char>(data[i]);
        }
    }
    if (args.size() > 64)
        return 0;
    std::vector<char*> argv;
    for (std::string& a : args)
        argv.push_back(a.data());
    argv.push_back(nullptr);
    const int argc = static_cast<int>(args.size());
    // As main() does (host/cli/command_line.cpp), with the line a usage error gets.
    std::unique_ptr<pathcl::cli::CommandLine> line = pathcl::cli::make_command_line(argc, argv.data());
    if (::fchdir(scratch_fd) != 0)
        std::abort();
    try {
        line->app.parse(argc, argv.data());
        for (const pathcl::cli::Command& c : line->commands)
            if (c.app->parsed())
                c.run();
    } catch (const CLI::ParseError& e) {
        (void)pathcl::cli::usage_error(line->app, e);
    } catch (const std::exception&) {
    }
    keep_only_the_scene(fuzz::scratch_directory("cli"));
    if (::fchdir(home_fd) != 0)
        std::abort();
    return 0;
}
