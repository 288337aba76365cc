#include "common/file_identity.h"

#include <filesystem>
#include <sys/stat.h>

#include "common/error.h"

namespace pathcl {

namespace fs = std::filesystem;

bool same_file(const std::string& a, const std::string& b)
{
    struct stat sa {
    }, sb{};
    const bool has_a = ::stat(a.c_str(), &sa) == 0, has_b = ::stat(b.c_str(), &sb) == 0;
    if (has_a && has_b)
        return sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
    if (has_a != has_b)
        return false; // one exists, the other does not
    // Made absolute first: the canonical form of a relative path whose first component does
    // not exist stays relative ("r.ply", where "./r.ply" becomes "/dir/r.ply").
    std::error_code ea, eb;
    const fs::path ca = fs::weakly_canonical(fs::absolute(a, ea), ea),
                   cb = fs::weakly_canonical(fs::absolute(b, eb), eb);
    return !ea && !eb && ca == cb;
}

void check_distinct_files(const std::vector<NamedFile>& inputs, const std::vector<NamedFile>& outputs,
                          const std::function<bool(const NamedFile&, const NamedFile&)>& allowed)
{
    for (std::size_t o = 0; o < outputs.size(); ++o) {
        const NamedFile& out = outputs[o];
        for (const NamedFile& in : inputs)
            if (same_file(out.path, in.path) && !(allowed && allowed(out, in)))
                throw Error(out.path + ": is an input of this render (" + in.role + " " + in.path +
                            "); choose another " + out.role);
        for (std::size_t p = 0; p < o; ++p)
            if (same_file(out.path, outputs[p].path))
                throw Error(out.path + ": is both the " + outputs[p].role + " " + outputs[p].path + " and the " +
                            out.role + " of this render; choose another " + out.role);
    }
}

} // namespace pathcl
