// import_environment: the uri must name a regular file inside the scene's directory
// (confined_path: neither ".." nor a link leads out).
#include "scene/gltf_environment.h"

#include <cmath>

#include <tiny_gltf.h>

#include "common/error.h"
#include "scene/confined_files.h"
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
    std::string uri = env.Get("uri").Get<std::string>();
    read_environment_image(environment, confined_path(base_dir, uri, source + ": environment uri " + quote(uri)));
    environment.strength = static_cast<float>(number_or(env, "strength", 1.0));
    if (!(environment.strength >= 0.0f) || !std::isfinite(environment.strength))
        throw Error(source + ": environment strength must be finite and non-negative");
    return environment;
}

} // namespace pathcl
