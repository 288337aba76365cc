#include "scene/alpha_cutouts.h"

#include <algorithm>
#include <limits>

namespace pathcl {
namespace {

// The least alpha of an image's texels, in [0, 1] (bilinear filtering never goes lower).
float least_alpha(const SceneImage& image)
{
    if (image.bits == 16) {
        std::uint16_t least = std::numeric_limits<std::uint16_t>::max();
        for (std::size_t i = 3; i < image.rgba16.size(); i += 4)
            least = std::min(least, image.rgba16[i]);
        return static_cast<float>(least) / 65535.0f;
    }
    std::uint8_t least = std::numeric_limits<std::uint8_t>::max();
    for (std::size_t i = 3; i < image.rgba8.size(); i += 4)
        least = std::min(least, image.rgba8[i]);
    return static_cast<float>(least) / 255.0f;
}

// Whether alpha as low as `alpha` makes the material anything but opaque.
bool cuts(const SceneMaterial& m, float alpha)
{
    switch (m.alpha_mode) {
    case AlphaMode::Mask:
        return alpha < m.alpha_cutoff;
    case AlphaMode::Blend:
        return alpha < 1.0f;
    default:
        return false;
    }
}

} // namespace

std::vector<bool> alpha_tested_triangles(const Scene& scene)
{
    std::vector<bool> tested(scene.triangles.size(), false);
    // The least alpha each material can reach before vertex colours; read only when some
    // material could cut (most scenes have none, and images can be large).
    std::vector<float> material_least(scene.materials.size(), 1.0f);
    bool any = false;
    for (std::size_t i = 0; i < scene.materials.size(); ++i) {
        const SceneMaterial& m = scene.materials[i];
        if (m.alpha_mode == AlphaMode::Opaque)
            continue;
        float least = m.alpha;
        const SceneTexture& base = m.textures[TEXTURE_SLOT_BASE_COLOR];
        if (base.present())
            least *= least_alpha(scene.images[static_cast<std::size_t>(base.image)]);
        material_least[i] = least;
        any = any || cuts(m, least) || !scene.colors.empty();
    }
    if (!any)
        return tested;
    for (std::size_t t = 0; t < scene.triangles.size(); ++t) {
        std::size_t mi = static_cast<std::size_t>(scene.triangles[t].material);
        float least = material_least[mi];
        if (!scene.colors.empty()) {
            const TriangleColor& c = scene.colors[t];
            least *= std::min(c[0].w, std::min(c[1].w, c[2].w));
        }
        tested[t] = cuts(scene.materials[mi], least);
    }
    return tested;
}

} // namespace pathcl
