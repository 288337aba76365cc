// Output files written under temporary names beside their targets and renamed into place
// only when every one of them is complete, so a failure anywhere (a full disk, the second
// of two -o files) leaves every existing file the user has untouched and no partial file.
#pragma once

#include <string>
#include <vector>

namespace pathcl {

// The extension of path in lower case, with its dot (".exr"); "" when it has none.
std::string lowercase_extension(const std::string& path);

// Throws pathcl::Error naming path when its directory does not exist or path itself is
// a directory: the checks every output makes before any work is done.
void check_output_location(const std::string& path);

// Throws pathcl::Error when `output` names the same file as one of `inputs` (by identity,
// so links and other spellings count): a render never overwrites what it reads.
void check_not_an_input(const std::string& output, const std::vector<std::string>& inputs);

// Removes every staged temporary file now; async-signal-safe (only unlink), for a signal
// handler that is about to end the process.
void remove_staged_files_on_signal();

class StagedFiles {
public:
    StagedFiles() = default;
    StagedFiles(const StagedFiles&) = delete;
    StagedFiles& operator=(const StagedFiles&) = delete;
    ~StagedFiles(); // removes whatever was staged and not committed

    // A temporary path in target's directory, ending in target's extension (so writers
    // that choose the format by extension see the right one).
    std::string stage(const std::string& target);

    // Renames every staged file onto its target; throws pathcl::Error naming the file if
    // a rename fails (the files renamed before it stay renamed).
    void commit();

private:
    std::vector<std::pair<std::string, std::string>> files_; // (temporary, target)
};

} // namespace pathcl
