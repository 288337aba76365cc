// import_environment: the uri is resolved, made canonical and compared, component by
// component, with the canonical scene directory, so neither ".." nor a link leads out.
#include "scene/gltf_environment.h"

#include <algorithm>
#include <filesystem>

#include <tiny_gltf.h>

#include "common/error.h"
#include "scene/environment_image.h"
#include "scene/gltf_values.h"

namespace pathcl {

SceneEnvironment import_environment(const tinygltf::Value& extras, const std::string& base_dir,
                                    const std::string& source)
{
    SceneEnvironment environment;
    if (!extras.IsObject() || !extras.Has("environment"))
        return environment;
    const tinygltf::Value& env = extras.Get("environment");
    if (!env.IsObject() || !env.Has("uri") || !env.Get("uri").IsString())
        throw Error(source + ": scene extras.environment needs a string \"uri\"");
    namespace fs = std::filesystem;
    std::string uri = env.Get("uri").Get<std::string>();
    fs::path dir = fs::weakly_canonical(fs::path(base_dir.empty() ? "." : base_dir));
    fs::path file = fs::weakly_canonical(dir / uri);
    auto [d, f] = std::mismatch(dir.begin(), dir.end(), file.begin(), file.end());
    if (d != dir.end() || fs::path(uri).is_absolute())
        throw Error(source + ": environment uri '" + uri + "' leaves the scene's directory");
    read_environment_image(environment, file.string());
    environment.strength = static_cast<float>(number_or(env, "strength", 1.0));
    if (!(environment.strength >= 0.0f))
        throw Error(source + ": environment strength must be non-negative");
    return environment;
}

} // namespace pathcl
