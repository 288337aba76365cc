#include "scene/scene_fingerprint.h"

#include <cstdio>
#include <type_traits>

#include "common/fnv1a.h"

namespace pathcl {
namespace {

// FNV-1a over the bytes of values without padding (floats, doubles, integers and glm
// vectors of them), each fed field by field.
struct Fnv {
    std::uint64_t h = kFnv1aBasis;

    void bytes(const void* p, std::size_t n) { h = fnv1a64(p, n, h); }
    template <class T>
    void add(const T& v)
    {
        static_assert(std::is_trivially_copyable_v<T>); // and no padding: scalars and glm vectors
        bytes(&v, sizeof v);
    }
    template <class T>
    void add_all(const std::vector<T>& v)
    {
        add(v.size());
        if (!v.empty())
            bytes(v.data(), v.size() * sizeof(T));
    }
    void add(const std::string& s)
    {
        add(s.size());
        bytes(s.data(), s.size());
    }
};

} // namespace

std::uint64_t scene_fingerprint(const Scene& scene)
{
    Fnv f;
    f.add(scene.triangles.size());
    for (const SceneTriangle& t : scene.triangles) {
        for (const glm::vec3& v : t.v)
            f.add(v);
        for (const glm::vec3& n : t.n)
            f.add(n);
        f.add(t.material);
    }
    if (!scene.instances.empty()) { // (absent from a scene without: its fingerprint is unchanged)
        f.add(scene.meshes.size());
        for (const SceneMesh& m : scene.meshes) {
            f.add(m.first);
            f.add(m.count);
        }
        f.add(scene.instances.size());
        for (const SceneInstance& i : scene.instances) {
            f.add(i.mesh);
            f.bytes(&i.to_render, sizeof i.to_render);
        }
    }
    f.add(scene.materials.size());
    for (const SceneMaterial& m : scene.materials) {
        f.add(m.base_color);
        f.add(m.metallic);
        f.add(m.roughness);
        f.add(m.emission);
        f.add(static_cast<int>(m.double_sided));
        f.add(m.specular);
        f.add(m.specular_color);
        f.add(m.transmission);
        f.add(m.ior);
        f.add(static_cast<int>(m.thin_walled));
        f.add(m.normal_scale);
        if (m.absorbs()) // (added only where it changes the image, so older fingerprints stand)
            f.add(m.absorption);
        if (m.alpha_mode != AlphaMode::Opaque) { // an opaque material's alpha changes nothing
            f.add(static_cast<int>(m.alpha_mode));
            f.add(m.alpha);
            f.add(m.alpha_cutoff);
        }
        if (m.unlit)
            f.add(2);
        if (m.glossiness_texture) {
            f.add(1);
            f.add(m.glossiness);
        }
        if (m.clearcoat > 0.0f) {
            f.add(3);
            f.add(m.clearcoat);
            f.add(m.clearcoat_roughness);
            if (m.textures[TEXTURE_SLOT_CLEARCOAT_NORMAL].present())
                f.add(m.clearcoat_normal_scale);
        }
        if (m.has_sheen()) {
            f.add(4);
            f.add(m.sheen_color);
            f.add(m.sheen_roughness);
        }
        if (m.has_anisotropy()) {
            f.add(5);
            f.add(m.anisotropy);
            f.add(m.anisotropy_rotation);
        }
        for (std::size_t slot = 0; slot < m.textures.size(); ++slot) {
            const SceneTexture& t = m.textures[slot];
            if (slot >= TEXTURE_SLOT_CLEARCOAT && !t.present())
                continue; // slots added later count only when used, so older fingerprints stand
            f.add(t.image);
            f.add(t.texcoord);
            f.add(static_cast<int>(t.wrap_s));
            f.add(static_cast<int>(t.wrap_t));
            f.add(static_cast<int>(t.nearest));
            f.add(t.transform_u);
            f.add(t.transform_v);
        }
    }
    f.add(scene.images.size());
    for (const SceneImage& img : scene.images) {
        f.add(img.width);
        f.add(img.height);
        f.add(img.bits);
        f.add_all(img.rgba8);
        f.add_all(img.rgba16);
    }
    f.add(scene.texcoords.size());
    for (const auto& set : scene.texcoords)
        for (const TriangleUv& uv : set)
            for (const glm::vec2& v : uv)
                f.add(v);
    for (const TriangleTangent& t : scene.tangents)
        for (const glm::vec4& v : t)
            f.add(v);
    for (const TriangleColor& c : scene.colors)
        for (const glm::vec4& v : c)
            f.add(v);
    f.add(scene.lights.size());
    for (const SceneLight& l : scene.lights) {
        f.add(static_cast<int>(l.type));
        f.add(l.position);
        f.add(l.direction);
        f.add(l.right);
        f.add(l.intensity);
        f.add(l.cos_inner);
        f.add(l.cos_outer);
        f.add(l.tan_half_h);
        f.add(l.tan_half_v);
        f.add(l.radius);
    }
    const SceneEnvironment& e = scene.environment;
    f.add(static_cast<int>(e.present));
    f.add(e.width);
    f.add(e.height);
    f.add_all(e.rgb);
    f.add(e.constant);
    f.add(e.strength);
    f.add(e.rotation_degrees);
    const SceneCamera& c = scene.camera;
    f.add(c.position);
    f.add(c.forward);
    f.add(c.up);
    f.add(c.right);
    f.add(c.yfov);
    f.add(static_cast<int>(c.orthographic));
    f.add(c.ymag);
    f.add(c.aperture);
    f.add(c.focus_distance);
    f.add(scene.render_origin);
    return f.h;
}

std::string scene_fingerprint_hex(const Scene& scene)
{
    char buf[17];
    std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(scene_fingerprint(scene)));
    return buf;
}

} // namespace pathcl
