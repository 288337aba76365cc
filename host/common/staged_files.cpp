#include "common/staged_files.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <unistd.h>

#include "common/error.h"

namespace pathcl {

namespace fs = std::filesystem;

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
    for (const auto& [tmp, target] : files_)
        fs::remove(tmp, ec);
}

std::string StagedFiles::stage(const std::string& target)
{
    fs::path t(target);
    fs::path tmp = t.parent_path() / ("." + t.filename().string() + ".tmp" + std::to_string(::getpid()) + "-" +
                                      std::to_string(files_.size()) + t.extension().string());
    files_.emplace_back(tmp.string(), target);
    return tmp.string();
}

void StagedFiles::commit()
{
    while (!files_.empty()) {
        auto [tmp, target] = files_.front();
        std::error_code ec;
        fs::rename(tmp, target, ec);
        if (ec)
            throw Error(target + ": cannot write: " + ec.message()); // the destructor removes the rest
        files_.erase(files_.begin());
    }
}

} // namespace pathcl
