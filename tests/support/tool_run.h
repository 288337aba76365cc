// Runs the real `pathcl` binary in a fresh directory per test (removed afterwards), with
// stdout and stderr captured to files there: the fixture of the end-to-end tool tests.
#pragma once

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

namespace pathcl::test {

// The lines of a text (an output file, stdout), without their line breaks.
inline std::vector<std::string> lines_of(const std::string& text)
{
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);)
        lines.push_back(line);
    return lines;
}

class ToolRun : public ::testing::Test {
protected:
    void SetUp() override
    {
        dir_ =
            std::filesystem::temp_directory_path() / ("pathcl-tools-" + std::to_string(::getpid()) + "-" +
                                                      ::testing::UnitTest::GetInstance()->current_test_info()->name());
        std::filesystem::remove_all(dir_);
        std::filesystem::create_directories(dir_);
    }
    void TearDown() override
    {
        std::error_code ec;
        std::filesystem::remove_all(dir_, ec);
    }
    // Runs the binary with `args` in dir_, after the shell assignments `env` (such as
    // "POCL_DEVICES='pthread pthread'"); returns the exit status (-1: no normal exit).
    int run(const std::string& args, const std::string& env = "") const
    {
        std::string cmd = "cd '" + dir_.string() + "' && " + env + " '" + std::string(PATHCL_BINARY) + "' " + args +
                          " >stdout.txt 2>stderr.txt";
        int rc = std::system(cmd.c_str());
        return rc != -1 && WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
    }
    // Runs the binary once per element of `args`, all at once (separate processes), each
    // with its output in stdout-<i>.txt and stderr-<i>.txt; returns how many failed.
    int run_parallel(const std::vector<std::string>& args) const
    {
        std::string cmd = "cd '" + dir_.string() + "' && failed=0";
        for (std::size_t i = 0; i < args.size(); ++i)
            cmd += "; ('" + std::string(PATHCL_BINARY) + "' " + args[i] + " >stdout-" + std::to_string(i) +
                   ".txt 2>stderr-" + std::to_string(i) + ".txt) & p" + std::to_string(i) + "=$!";
        for (std::size_t i = 0; i < args.size(); ++i)
            cmd += "; wait $p" + std::to_string(i) + " || failed=$((failed + 1))";
        cmd += "; exit $failed";
        int rc = std::system(cmd.c_str());
        return rc != -1 && WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
    }
    // A file of dir_ as text ("stdout.txt", "stderr.txt", an output).
    std::string text(const std::string& name) const
    {
        std::ifstream in(dir_ / name, std::ios::binary);
        return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    }
    std::filesystem::path dir_;
};

} // namespace pathcl::test
