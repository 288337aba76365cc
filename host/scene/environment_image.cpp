#include "scene/environment_image.h"

#include "image/image_io.h"

namespace pathcl {

void read_environment_image(SceneEnvironment& env, const std::string& path)
{
    Image img = read_image(path);
    env.present = true;
    env.path = path;
    env.width = img.width;
    env.height = img.height;
    env.rgb = std::move(img.rgb);
}

} // namespace pathcl
