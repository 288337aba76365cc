#include "image/image_module.h"

#include <dlfcn.h>
#include <filesystem>
#include <functional>
#include <system_error>
#include <utility>

#include "common/error.h"

namespace pathcl {
namespace {

namespace fs = std::filesystem;

constexpr const char* kModuleName = "libpathcl_oiio.so";

// Where the module may be: beside the program (the build tree, a portable bundle), in
// lib/pathcl of the folder above (an installed pathcl), or where the build that made the
// program put it (the test programs, one folder below).
std::vector<fs::path> module_candidates()
{
    std::vector<fs::path> paths;
    std::error_code ec;
    const fs::path program = fs::read_symlink("/proc/self/exe", ec);
    if (!ec) {
        paths.push_back(program.parent_path() / kModuleName);
        paths.push_back(program.parent_path().parent_path() / "lib" / "pathcl" / kModuleName);
    }
#ifdef PATHCL_IMAGE_MODULE_BUILT
    paths.emplace_back(PATHCL_IMAGE_MODULE_BUILT);
#endif
    return paths;
}

// set_image_module_prelude's function, or empty.
std::function<void()>& module_prelude()
{
    static std::function<void()> prelude;
    return prelude;
}

const ImageModule& load_module()
{
    if (module_prelude())
        module_prelude()();
    std::string tried;
    for (const fs::path& path : module_candidates()) {
        std::error_code ec;
        if (!fs::is_regular_file(path, ec)) {
            tried += (tried.empty() ? "" : ", ") + path.string();
            continue;
        }
        // Never unloaded: OpenImageIO's threads and caches live until the process ends.
        void* handle = ::dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
        if (!handle) {
            std::string why = one_line(::dlerror());
            if (why.rfind(path.string() + ": ", 0) == 0)
                why.erase(0, path.string().size() + 2); // dlerror names the file too
            throw Error(path.string() + ": cannot load pathcl's image module: " + why);
        }
        auto entry = reinterpret_cast<decltype(&pathcl_image_module)>(::dlsym(handle, "pathcl_image_module"));
        const ImageModule* module = entry ? entry(kImageModuleAbi, sizeof(Image), sizeof(ImageModule)) : nullptr;
        if (!module)
            throw Error(path.string() + ": is not the image module of this pathcl (another build's?)");
        return *module;
    }
    throw Error(std::string("pathcl's image module ") + kModuleName +
                " (which reads and writes images) is missing: looked for " + tried);
}

} // namespace

void set_image_module_prelude(std::function<void()> prelude)
{
    module_prelude() = std::move(prelude);
}

const ImageModule& image_module()
{
    static const ImageModule& module = load_module(); // thread-safe; tried again after a throw
    return module;
}

} // namespace pathcl
