#include "common/staged_files.h"

#include <algorithm>
#include <cctype>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <unistd.h>

#include "common/error.h"

namespace pathcl {

namespace fs = std::filesystem;

namespace {

// The staged names a signal handler may have to remove: fixed storage, so the handler
// reads it without allocating; a slot is published by setting its flag last.
constexpr int kSignalSlots = 16;
char g_slot_path[kSignalSlots][4096];
volatile std::sig_atomic_t g_slot_used[kSignalSlots];

int claim_slot(const std::string& path)
{
    if (path.size() >= sizeof g_slot_path[0])
        return -1;
    for (int i = 0; i < kSignalSlots; ++i)
        if (!g_slot_used[i]) {
            std::memcpy(g_slot_path[i], path.c_str(), path.size() + 1);
            g_slot_used[i] = 1;
            return i;
        }
    return -1;
}

void release_slot(const std::string& path)
{
    for (int i = 0; i < kSignalSlots; ++i)
        if (g_slot_used[i] && path == g_slot_path[i])
            g_slot_used[i] = 0;
}

} // namespace

void remove_staged_files_on_signal()
{
    for (int i = 0; i < kSignalSlots; ++i)
        if (g_slot_used[i])
            ::unlink(g_slot_path[i]);
}

void check_not_an_input(const std::string& output, const std::vector<std::string>& inputs)
{
    std::error_code ec;
    if (!fs::exists(output, ec))
        return; // a file that does not exist yet was not read
    for (const std::string& input : inputs)
        if (fs::equivalent(output, input, ec))
            throw Error(output + ": is an input of this render (" + input + "); choose another output");
}

std::string lowercase_extension(const std::string& path)
{
    std::string ext = fs::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext;
}

void check_output_location(const std::string& path)
{
    fs::path dir = fs::path(path).parent_path();
    std::error_code ec;
    if (!dir.empty() && !fs::is_directory(dir, ec))
        throw Error(path + ": directory " + dir.string() + " does not exist");
    if (fs::is_directory(path, ec))
        throw Error(path + ": is a directory");
}

StagedFiles::~StagedFiles()
{
    std::error_code ec;
    for (const auto& [tmp, target] : files_) {
        fs::remove(tmp, ec);
        release_slot(tmp);
    }
}

std::string StagedFiles::stage(const std::string& target)
{
    fs::path t(target);
    fs::path tmp = t.parent_path() / ("." + t.filename().string() + ".tmp" + std::to_string(::getpid()) + "-" +
                                      std::to_string(files_.size()) + t.extension().string());
    files_.emplace_back(tmp.string(), target);
    claim_slot(tmp.string());
    return tmp.string();
}

void StagedFiles::commit()
{
    while (!files_.empty()) {
        auto [tmp, target] = files_.front();
        std::error_code ec;
        fs::rename(tmp, target, ec);
        if (!ec)
            release_slot(tmp);
        if (ec)
            throw Error(target + ": cannot write: " + ec.message()); // the destructor removes the rest
        files_.erase(files_.begin());
    }
}

} // namespace pathcl
