#include "common/staged_files.h"

#include <filesystem>
#include <unistd.h>

#include "common/error.h"

namespace pathcl {

namespace fs = std::filesystem;

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
