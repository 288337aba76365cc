#include "compile/texture_lookup.h"

#include <cmath>

#include "texture/srgb.h"
#include "texture/wrap.h"

namespace pathcl {

pcl_uint texture_wrap_mode(TextureWrap w)
{
    switch (w) {
    case TextureWrap::ClampToEdge:
        return TEXTURE_WRAP_CLAMP_TO_EDGE;
    case TextureWrap::MirroredRepeat:
        return TEXTURE_WRAP_MIRRORED_REPEAT;
    default:
        return TEXTURE_WRAP_REPEAT;
    }
}

float srgb8_to_linear(std::uint8_t value)
{
    return static_cast<float>(srgb_to_linear(value / 255.0));
}

glm::vec4 texture_value_nearest(const SceneImage& image, const SceneTexture& texture, bool srgb, glm::vec2 uv)
{
    glm::dvec3 p(uv.x, uv.y, 1.0);
    // The kernels' nearest lookup: transform, move into one period of the wrap mode, then
    // wrap the texel index.
    auto texel = [](double c, std::uint32_t n, TextureWrap w) {
        pcl_uint mode = texture_wrap_mode(w);
        double wrapped = wrap_coordinate(c, mode);
        return static_cast<std::size_t>(
            wrap_texel(static_cast<pcl_int>(std::floor(wrapped * n)), static_cast<pcl_int>(n), mode));
    };
    std::size_t x = texel(glm::dot(glm::dvec3(texture.transform_u), p), image.width, texture.wrap_s);
    std::size_t y = texel(glm::dot(glm::dvec3(texture.transform_v), p), image.height, texture.wrap_t);
    std::size_t base = (y * image.width + x) * 4;
    glm::vec4 out;
    for (int c = 0; c < 4; ++c) {
        bool decode = srgb && c < 3;
        if (image.bits == 16) {
            double value = image.rgba16[base + static_cast<std::size_t>(c)] / 65535.0;
            out[c] = static_cast<float>(decode ? srgb_to_linear(value) : value);
        } else {
            std::uint8_t value = image.rgba8[base + static_cast<std::size_t>(c)];
            out[c] = decode ? srgb8_to_linear(value) : static_cast<float>(value / 255.0);
        }
    }
    return out;
}

glm::dvec3 texture_mean_over_triangle(const SceneImage& image, const SceneTexture& texture, bool srgb,
                                      const TriangleUv& uv)
{
    const int n = 8;
    glm::dvec3 sum(0.0);
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            // Cell centres of an n x n grid, warped to the triangle uniformly by area.
            double su = std::sqrt((i + 0.5) / n), b1 = 1.0 - su, b2 = (j + 0.5) / n * su, b0 = 1.0 - b1 - b2;
            glm::dvec2 p = b0 * glm::dvec2(uv[0]) + b1 * glm::dvec2(uv[1]) + b2 * glm::dvec2(uv[2]);
            sum += glm::dvec3(glm::vec3(texture_value_nearest(image, texture, srgb, glm::vec2(p))));
        }
    return sum / double(n * n);
}

} // namespace pathcl
