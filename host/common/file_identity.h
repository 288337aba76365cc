// Which names on a command line (and in a scene) are the same file: an output must never
// be an input, nor two outputs one file, however they are spelled ("./out.exr" and
// "$PWD/out.exr", a link, a hard link, "dir/../out.exr").
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace pathcl {

// A file a command reads or writes, and the part it plays ("-o", "--checkpoint", "the
// scene", "--resume", a texture of the scene): what an error names it by.
struct NamedFile {
    std::string path, role;
};

// Whether a and b name the same file: the same device and inode when both exist, else
// the same canonical path (links and ".." resolved as far as the path exists).
bool same_file(const std::string& a, const std::string& b);

// Throws pathcl::Error naming both when an output is the same file as an input or as
// another output, except where allowed(output, input) says that output may be that input
// (a render resumed from its checkpoint keeps writing it).
void check_distinct_files(const std::vector<NamedFile>& inputs, const std::vector<NamedFile>& outputs,
                          const std::function<bool(const NamedFile&, const NamedFile&)>& allowed = {});

} // namespace pathcl
