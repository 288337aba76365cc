#include "cl/kernel_source.h"

#include <map>
#include <optional>
#include <set>
#include <sstream>

#include "cl/embedded_kernels.h"
#include "common/error.h"

namespace pathcl {
namespace {

// The path of a line `#include "path"` (whitespace allowed around the #), else nothing.
// Includes with <> are left alone: only host-side parts of shared headers use them.
std::optional<std::string> quoted_include(const std::string& line)
{
    std::size_t i = line.find_first_not_of(" \t");
    if (i == std::string::npos || line[i] != '#')
        return std::nullopt;
    i = line.find_first_not_of(" \t", i + 1);
    if (i == std::string::npos || line.compare(i, 7, "include") != 0)
        return std::nullopt;
    i = line.find_first_not_of(" \t", i + 7);
    if (i == std::string::npos || line[i] != '"')
        return std::nullopt;
    std::size_t close = line.find('"', i + 1);
    if (close == std::string::npos)
        return std::nullopt;
    return line.substr(i + 1, close - i - 1);
}

class Assembler {
public:
    explicit Assembler(std::map<std::string, std::string> files) : files_(std::move(files)) {}

    std::string run(const std::string& root, const std::string& text)
    {
        included_.insert(root);
        append(root, text);
        return out_;
    }

private:
    void append(const std::string& name, const std::string& text)
    {
        stack_.push_back(name);
        out_ += "#line 1 \"" + name + "\"\n";
        std::istringstream in(text);
        std::string line;
        for (int number = 1; std::getline(in, line); ++number) {
            std::optional<std::string> include = quoted_include(line);
            if (!include) {
                out_ += line;
                out_ += '\n';
                continue;
            }
            const std::string target = *include;
            for (const std::string& open : stack_)
                if (open == target)
                    throw Error("kernel source " + name + ":" + std::to_string(number) + ": includes \"" + target +
                                "\", which includes it back (an include cycle)");
            auto file = files_.find(target);
            if (file == files_.end())
                throw Error("kernel source " + name + ":" + std::to_string(number) + ": includes \"" + target +
                            "\", which is not a file of the kernel tree");
            if (!included_.insert(target).second) {
                out_ += '\n'; // already included: the line stays, empty
                continue;
            }
            append(target, file->second);
            out_ += "#line " + std::to_string(number + 1) + " \"" + name + "\"\n";
        }
        stack_.pop_back();
    }

    std::map<std::string, std::string> files_;
    std::set<std::string> included_;
    std::vector<std::string> stack_;
    std::string out_;
};

void apply_patch(std::map<std::string, std::string>& files, const KernelPatch& patch)
{
    auto file = files.find(patch.file);
    if (file == files.end())
        throw Error("kernel patch: " + patch.file + " is not a file of the kernel tree");
    std::string& text = file->second;
    std::size_t at = text.find(patch.find);
    if (at == std::string::npos || text.find(patch.find, at + 1) != std::string::npos)
        throw Error("kernel patch: the text to replace occurs " +
                    std::string(at == std::string::npos ? "nowhere" : "more than once") + " in " + patch.file);
    text.replace(at, patch.find.size(), patch.replace);
}

} // namespace

std::vector<std::string> kernel_file_names()
{
    std::vector<std::string> names;
    for (const EmbeddedFile& f : embedded_kernel_files())
        names.push_back(f.name);
    return names;
}

std::string assemble_kernel_source(const ProgramSource& source)
{
    std::map<std::string, std::string> files;
    for (const EmbeddedFile& f : embedded_kernel_files())
        files[f.name] = f.text;
    for (const KernelPatch& patch : source.patches)
        apply_patch(files, patch);
    std::string root_text = source.text;
    if (root_text.empty()) {
        auto root = files.find(source.root);
        if (root == files.end())
            throw Error("kernel source: " + source.root + " is not a file of the kernel tree");
        root_text = root->second;
    }
    return Assembler(std::move(files)).run(source.root, root_text);
}

} // namespace pathcl
