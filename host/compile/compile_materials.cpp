// Materials for the device: one Material record per scene material (factors; the texture
// slots are filled by compile_textures), and the layer albedo tables when a material has
// a specular layer, transmission, a clear coat, a sheen or anisotropy.
#include "compile/compile_scene.h"
#include "tables/layer_albedo.h"

#include "closure/layer_table.h"

#include <cmath>

namespace pathcl {

void compile_materials(const Scene& scene, const KernelFeatures& features, SceneArrays& arrays)
{
    for (const SceneMaterial& m : scene.materials) {
        Material dm{};
        dm.base_color = to_float4(m.base_color, m.alpha);
        dm.emission = to_float4(m.emission);
        dm.specular_color = to_float4(m.specular_color, m.specular);
        dm.absorption = to_float4(m.absorbs() ? m.absorption : glm::vec3(0.0f));
        dm.metallic = m.metallic;
        dm.roughness = m.glossiness_texture ? m.glossiness : m.roughness;
        dm.transmission = m.transmission;
        dm.ior = m.ior;
        dm.flags = (m.double_sided ? MATERIAL_DOUBLE_SIDED : 0u) | (m.thin_walled ? MATERIAL_THIN_WALLED : 0u) |
                   (m.alpha_mode == AlphaMode::Mask ? MATERIAL_ALPHA_MASK : 0u) |
                   (m.alpha_mode == AlphaMode::Blend ? MATERIAL_ALPHA_BLEND : 0u) |
                   (m.glossiness_texture ? MATERIAL_GLOSSINESS : 0u) | (m.unlit ? MATERIAL_UNLIT : 0u);
        dm.alpha_cutoff = m.alpha_cutoff;
        dm.clearcoat = m.clearcoat;
        dm.clearcoat_roughness = m.clearcoat_roughness;
        dm.clearcoat_normal_scale = m.clearcoat_normal_scale;
        dm.sheen = to_float4(m.has_sheen() ? m.sheen_color : glm::vec3(0.0f), m.sheen_roughness);
        if (m.has_anisotropy()) {
            double r = m.anisotropy_rotation;
            dm.anisotropy = {m.anisotropy, static_cast<float>(std::cos(r)), static_cast<float>(std::sin(r)), 0.0f};
        } else {
            dm.anisotropy = {0.0f, 1.0f, 0.0f, 0.0f};
        }
        for (pcl_int& t : dm.textures)
            t = TEXTURE_NONE;
        dm.smooth_layer_average = static_cast<float>(smooth_layer_average(m.ior));
        dm.normal_scale = m.normal_scale;
        arrays.materials.push_back(dm);
    }
    if (features.has(FEATURE_GLOSSY) || features.has(FEATURE_TRANSMISSION) || features.has(FEATURE_CLEARCOAT) ||
        features.has(FEATURE_SHEEN) || features.has(FEATURE_ANISOTROPY)) {
        // The anisotropic albedo (two thirds of the table) only where the kernels can read
        // it: a program with FEATURE_ANISOTROPY.
        const std::vector<float>& table = layer_albedo_table();
        arrays.layer_albedo.assign(
            table.begin(), table.begin() + (features.has(FEATURE_ANISOTROPY) ? LAYER_TABLE_SIZE : LAYER_TABLE_ANISO));
    }
}

} // namespace pathcl
