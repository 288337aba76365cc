// import_light: the node's frame (direction along -Z, right along +X, orthonormalized
// even under shear), then the checks and the parameters of each light type.
#include "scene/gltf_lights.h"

#include <cmath>
#include <numbers>

#include <tiny_gltf.h>

#include "common/error.h"
#include "scene/gltf_values.h"

namespace pathcl {

SceneLight import_light(const tinygltf::Model& model, const tinygltf::Value& index_value, const glm::dmat4& world,
                        const std::string& what, const std::string& source)
{
    // Compared as a double: converting an index beyond int first is undefined behaviour.
    double number = index_value.IsNumber() ? index_value.GetNumberAsDouble() : -1.0;
    if (!(number >= 0.0 && number < static_cast<double>(model.lights.size()) && number == std::floor(number)))
        throw Error(source + ": " + what + ": the KHR_lights_punctual light index names none of the " +
                    std::to_string(model.lights.size()) + " lights");
    int index = static_cast<int>(number);
    const tinygltf::Light& l = model.lights[static_cast<std::size_t>(index)];
    std::string name = what + ": light " + std::to_string(index);
    SceneLight out;
    out.name = l.name;
    glm::dvec3 color(1.0);
    if (l.color.size() == 3)
        color = glm::dvec3(l.color[0], l.color[1], l.color[2]);
    if (!(l.intensity >= 0.0) || !std::isfinite(l.intensity) || color.x < 0.0 || color.y < 0.0 || color.z < 0.0)
        throw Error(source + ": " + name + ": color and intensity must be finite and non-negative");
    out.intensity = glm::vec3(color * l.intensity);
    if (!std::isfinite(out.intensity.x) || !std::isfinite(out.intensity.y) || !std::isfinite(out.intensity.z))
        throw Error(source + ": " + name + ": color times intensity overflows single precision");
    glm::dmat3 m3(world);
    glm::dvec3 dir = m3 * glm::dvec3(0.0, 0.0, -1.0);
    glm::dvec3 right = m3 * glm::dvec3(1.0, 0.0, 0.0);
    if (!(glm::length(dir) > 0.0))
        throw Error(source + ": " + name + ": the node transform is degenerate");
    out.direction = glm::normalize(dir);
    right -= glm::dot(right, out.direction) * out.direction; // orthonormal frame even under shear
    out.right = glm::length(right) > 0.0 ? glm::normalize(right) : glm::dvec3(1.0, 0.0, 0.0);
    out.position = glm::dvec3(world[3]);
    if (l.type == "point") {
        out.type = SceneLight::Type::Point;
        double radius = number_or(l.extras, "radius", 0.0);
        if (l.extras.IsObject() && l.extras.Has("radius")) {
            // The radius is in the node's units: scaled like the geometry around it.
            double scale = std::cbrt(std::fabs(glm::determinant(m3)));
            if (!(radius > 0.0) || !std::isfinite(radius * scale))
                throw Error(source + ": " + name + ": extras.radius must be a positive number");
            // The emitted radiance is intensity / (pi r^2), in single precision on the device.
            glm::dvec3 radiance = glm::dvec3(out.intensity) / (std::numbers::pi * radius * scale * radius * scale);
            if (!std::isfinite(static_cast<float>(radius * scale)))
                throw Error(source + ": " + name + ": extras.radius overflows single precision");
            if (!(static_cast<float>(radius * scale) > 0.0f) || !std::isfinite(static_cast<float>(radiance.x)) ||
                !std::isfinite(static_cast<float>(radiance.y)) || !std::isfinite(static_cast<float>(radiance.z)))
                throw Error(source + ": " + name + ": extras.radius is so small that the sphere's radiance overflows");
            out.type = SceneLight::Type::Sphere;
            out.radius = radius * scale;
        }
    } else if (l.type == "spot") {
        bool rectangular = l.extras.IsObject() && (l.extras.Has("hfov") || l.extras.Has("vfov"));
        double h = number_or(l.extras, "hfov", -1.0), v = number_or(l.extras, "vfov", -1.0);
        if (rectangular) {
            if (!(h > 0.0 && h < 180.0 && v > 0.0 && v < 180.0))
                throw Error(source + ": " + name + ": extras hfov and vfov must both be in (0, 180) degrees");
            out.type = SceneLight::Type::RectSpot;
            out.tan_half_h = std::tan(0.5 * h * std::numbers::pi / 180.0);
            out.tan_half_v = std::tan(0.5 * v * std::numbers::pi / 180.0);
        } else {
            double inner = l.spot.innerConeAngle, outer = l.spot.outerConeAngle;
            if (!(inner >= 0.0 && outer > 0.0 && outer <= 0.5 * std::numbers::pi && inner < outer))
                throw Error(source + ": " + name +
                            ": spot cone angles need 0 <= innerConeAngle < outerConeAngle <= pi/2");
            out.type = SceneLight::Type::Spot;
            out.cos_inner = std::cos(inner);
            out.cos_outer = std::cos(outer);
        }
    } else if (l.type == "directional") {
        out.type = SceneLight::Type::Directional;
    } else {
        throw Error(source + ": " + name + ": unknown light type " + quote(l.type));
    }
    return out;
}

} // namespace pathcl
