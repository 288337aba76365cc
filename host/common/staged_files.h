// Output files written under temporary names beside their targets and renamed into place
// only when every one of them is complete, so a failure anywhere (a full disk, the second
// of two -o files) leaves every existing file the user has untouched and no partial file.
// An output replaces only a regular file (never a FIFO, a device such as /dev/null, a
// socket or a directory). A temporary file is locked while its process lives, so that
// one left by a process killed outright (SIGKILL, a power cut) is removed by the next
// write to the same target.
#pragma once

#include <string>
#include <vector>

namespace pathcl {

// The extension of path in lower case, with its dot (".exr"); "" when it has none.
std::string lowercase_extension(const std::string& path);

// Throws pathcl::Error naming path when its directory does not exist or cannot be
// written into, or path exists and is anything but a regular file (a directory, a FIFO, a
// device): the checks every output makes before any work is done.
void check_output_location(const std::string& path);

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
    // that choose the format by extension see the right one): created empty and locked
    // here, after the temporaries of target left by dead processes are removed.
    std::string stage(const std::string& target);

    // Renames every staged file onto its target; throws pathcl::Error naming the file if
    // a target is no longer a regular file or a rename fails (the files renamed before it
    // stay renamed).
    void commit();

private:
    struct Staged {
        std::string tmp, target;
        int lock_fd; // open on tmp, holding its lock
    };
    std::vector<Staged> files_;
};

} // namespace pathcl
