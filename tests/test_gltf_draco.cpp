// KHR_draco_mesh_compression (host only). A file compressed by Google's own glTF
// transcoder (draco_transcoder, an independent writer) loads into the triangles of its
// uncompressed original, within the quantization the transcoder applied; broken Draco
// primitives are one-line errors naming the file, the mesh and the primitive.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include <sys/wait.h>

#include <draco/compression/encode.h>
#include <draco/mesh/triangle_soup_mesh_builder.h>
#include <gtest/gtest.h>

#include "common/error.h"
#include "scene/gltf_loader.h"
#include "scene/scene.h"
#include "support/expect_error.h"
#include "support/gltf_builder.h"
#include "support/gltf_fixtures.h"
#include "support/tool_run.h"

namespace pathcl::test_gltf_draco {
namespace {

using test::contains;
using test::error_of;

const std::string kTextured = std::string(PATHCL_SOURCE_DIR) + "/scenes/textured.gltf";

// A fresh directory per test (ToolRun's), removed afterwards.
class DracoFiles : public test::ToolRun {
protected:
    // Compresses `input` into dir_/name with draco_transcoder and `options`; returns the path.
    std::string transcode(const std::string& input, const std::string& name, const std::string& options) const
    {
        std::string out = (dir_ / name).string();
        std::string cmd = "'" + std::string(PATHCL_DRACO_TRANSCODER) + "' " + options + " -i '" + input + "' -o '" +
                          out + "' >'" + out + ".log' 2>&1";
        int rc = std::system(cmd.c_str());
        EXPECT_TRUE(rc != -1 && WIFEXITED(rc) && WEXITSTATUS(rc) == 0) << cmd;
        return out;
    }
};

// The largest differences between the vertices of two scenes' triangles, each triangle of
// `a` paired with the triangle of `b` of the same material name whose corners (in the same
// order, up to rotation) lie nearest.
struct VertexDifferences {
    std::size_t unmatched = 0; // triangles of `b` paired twice or never, plus count mismatch
    double position = 0.0;     // world units
    double normal = 0.0;       // |n_a - n_b| of unit normals
    double uv = 0.0;           // per set
    double color = 0.0;
    double tangent = 0.0; // |t_a - t_b| of unit tangents
    bool handedness_agrees = true;
};

VertexDifferences compare_triangles(const Scene& a, const Scene& b)
{
    VertexDifferences d;
    std::vector<bool> used(b.triangles.size(), false);
    d.unmatched = a.triangles.size() > b.triangles.size() ? a.triangles.size() - b.triangles.size()
                                                          : b.triangles.size() - a.triangles.size();
    for (std::size_t i = 0; i < a.triangles.size(); ++i) {
        const SceneTriangle& ta = a.triangles[i];
        const std::string& name = a.materials[static_cast<std::size_t>(ta.material)].name;
        double best = std::numeric_limits<double>::infinity();
        std::size_t best_j = 0;
        int best_rot = 0;
        for (std::size_t j = 0; j < b.triangles.size(); ++j) {
            const SceneTriangle& tb = b.triangles[j];
            if (b.materials[static_cast<std::size_t>(tb.material)].name != name)
                continue;
            for (int r = 0; r < 3; ++r) {
                double e = 0.0;
                for (int k = 0; k < 3; ++k)
                    e = std::max(e, double(glm::length(ta.v[k] - tb.v[(k + r) % 3])));
                if (e < best) {
                    best = e;
                    best_j = j;
                    best_rot = r;
                }
            }
        }
        if (!std::isfinite(best) || used[best_j]) {
            ++d.unmatched;
            continue;
        }
        used[best_j] = true;
        const SceneTriangle& tb = b.triangles[best_j];
        for (int k = 0; k < 3; ++k) {
            const std::size_t kb = static_cast<std::size_t>((k + best_rot) % 3), ka = static_cast<std::size_t>(k);
            d.position = std::max(d.position, double(glm::length(ta.v[ka] - tb.v[kb])));
            d.normal = std::max(d.normal, double(glm::length(ta.n[ka] - tb.n[kb])));
            for (std::size_t set = 0; set < a.texcoords.size() && set < b.texcoords.size(); ++set)
                d.uv = std::max(d.uv, double(glm::length(a.texcoords[set][i][ka] - b.texcoords[set][best_j][kb])));
            if (!a.colors.empty() && !b.colors.empty())
                d.color = std::max(d.color, double(glm::length(a.colors[i][ka] - b.colors[best_j][kb])));
            if (!a.tangents.empty() && !b.tangents.empty()) {
                glm::vec4 x = a.tangents[i][ka], y = b.tangents[best_j][kb];
                d.tangent = std::max(d.tangent, double(glm::length(glm::vec3(x) - glm::vec3(y))));
                d.handedness_agrees = d.handedness_agrees && x.w == y.w;
            }
        }
    }
    return d;
}

TEST_F(DracoFiles, LosslessTranscodingGivesTheOriginalsTriangles)
{
    // With quantization off, Draco stores the float values themselves: every vertex value
    // comes back. Tolerance: the render-space origins differ (the transcoder drops the
    // camera), so positions went through a different float rounding: 1e-6 m on a 4 m scene.
    const Scene original = test::in_world_space(load_gltf(kTextured));
    for (const char* name : {"lossless.gltf", "lossless.glb"}) {
        const Scene draco =
            test::in_world_space(load_gltf(transcode(kTextured, name, "-qp 0 -qt 0 -qn 0 -qc 0 -qtg 0 -qg 0")));
        // (-qg too: the transcoder quantizes the tangents with the generic attributes' bits.)
        ASSERT_EQ(draco.triangles.size(), original.triangles.size()) << name;
        ASSERT_EQ(draco.texcoords.size(), original.texcoords.size()) << name;
        ASSERT_EQ(draco.colors.empty(), original.colors.empty()) << name;
        ASSERT_EQ(draco.tangents.empty(), original.tangents.empty()) << name;
        VertexDifferences d = compare_triangles(original, draco);
        EXPECT_EQ(d.unmatched, 0u) << name;
        EXPECT_LE(d.position, 1e-6) << name;
        EXPECT_LE(d.normal, 1e-6) << name;
        EXPECT_LE(d.uv, 1e-6) << name;
        EXPECT_LE(d.color, 1e-6) << name;
        EXPECT_LE(d.tangent, 1e-6) << name;
        EXPECT_TRUE(d.handedness_agrees) << name;
    }
}

TEST_F(DracoFiles, DefaultTranscodingGivesTheOriginalsTrianglesWithinItsQuantization)
{
    // The transcoder's defaults: positions on 11 bits, texture coordinates 10, normals and
    // colours 8 per component. Bounds: half a quantization step of the attribute's range
    // per component (positions: the 4 m scene's largest mesh extent, 4 m / 2047 / 2 ≈ 1e-3 m
    // per axis, so 1.7e-3 m as a length; texture coordinates range over [0, 4]: 2e-3 per
    // axis; colours 1/255/2 per component); normals and tangents (octahedral, 8 bits): 0.02.
    const Scene original = test::in_world_space(load_gltf(kTextured));
    const Scene draco = test::in_world_space(load_gltf(transcode(kTextured, "default.glb", "")));
    ASSERT_EQ(draco.triangles.size(), original.triangles.size());
    VertexDifferences d = compare_triangles(original, draco);
    EXPECT_EQ(d.unmatched, 0u);
    EXPECT_LE(d.position, 1.7e-3);
    EXPECT_LE(d.normal, 0.02);
    EXPECT_LE(d.uv, 3e-3);
    EXPECT_LE(d.color, 4e-3);
    EXPECT_LE(d.tangent, 0.02);
    EXPECT_TRUE(d.handedness_agrees);
    std::printf("default Draco quantization, largest differences: position %.2e, normal %.2e, uv %.2e, colour %.2e, "
                "tangent %.2e\n",
                d.position, d.normal, d.uv, d.color, d.tangent);
}

// A glTF model whose only primitive is a Draco-compressed square of two triangles in the
// z = 0 plane with per-corner colours (Google's encoder, lossless: no quantization), under
// accessors without bufferViews, as a Draco file has them.
struct DracoSquare {
    test::GltfBuilder b;
    int mesh = 0;
    tinygltf::Primitive& prim() { return b.model.meshes[static_cast<std::size_t>(mesh)].primitives[0]; }
    tinygltf::Value& ext() { return prim().extensions["KHR_draco_mesh_compression"]; }
};

DracoSquare draco_square()
{
    const glm::vec3 corner[4] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    const std::uint8_t color[4][3] = {{255, 0, 0}, {0, 255, 0}, {0, 0, 255}, {255, 255, 255}};
    const int faces[2][3] = {{0, 1, 2}, {0, 2, 3}};
    draco::TriangleSoupMeshBuilder builder;
    builder.Start(2);
    const int pos = builder.AddAttribute(draco::GeometryAttribute::POSITION, 3, draco::DT_FLOAT32);
    const int col = builder.AddAttribute(draco::GeometryAttribute::COLOR, 3, draco::DT_UINT8);
    for (int f = 0; f < 2; ++f) {
        const int* c = faces[f];
        builder.SetAttributeValuesForFace(pos, draco::FaceIndex(f), &corner[c[0]], &corner[c[1]], &corner[c[2]]);
        builder.SetAttributeValuesForFace(col, draco::FaceIndex(f), color[c[0]], color[c[1]], color[c[2]]);
    }
    std::unique_ptr<draco::Mesh> mesh = builder.Finalize();
    draco::Encoder encoder;
    draco::EncoderBuffer encoded;
    EXPECT_TRUE(encoder.EncodeMeshToBuffer(*mesh, &encoded).ok());

    DracoSquare sq;
    test::GltfBuilder& b = sq.b;
    const std::size_t points = mesh->num_points();
    int view = b.add_view(encoded.data(), encoded.size());
    int positions = b.add_accessor(-1, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, points);
    int colors = b.add_accessor(-1, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_TYPE_VEC3, points);
    b.model.accessors.back().normalized = true;
    int indices = b.add_accessor(-1, test::kU16, TINYGLTF_TYPE_SCALAR, 6);
    int material = b.add_material(glm::vec3(0.5f), glm::vec3(0.0f), true);
    sq.mesh = b.add_mesh(positions, indices, material);
    sq.prim().attributes["COLOR_0"] = colors;
    tinygltf::Value::Object attributes;
    attributes["POSITION"] = tinygltf::Value(static_cast<int>(mesh->attribute(pos)->unique_id()));
    attributes["COLOR_0"] = tinygltf::Value(static_cast<int>(mesh->attribute(col)->unique_id()));
    tinygltf::Value::Object ext;
    ext["bufferView"] = tinygltf::Value(view);
    ext["attributes"] = tinygltf::Value(attributes);
    sq.ext() = tinygltf::Value(ext);
    b.model.extensionsUsed.push_back("KHR_draco_mesh_compression");
    b.model.extensionsRequired.push_back("KHR_draco_mesh_compression");
    b.add_root(b.add_node(sq.mesh));
    return sq;
}

TEST(GltfDraco, ASquareDecodesToItsTrianglesAndColours)
{
    // Exact: lossless encoding, an identity transform, colours 0 or 255 of 255.
    DracoSquare sq = draco_square();
    Scene s = test::import(sq.b);
    ASSERT_EQ(s.triangles.size(), 2u);
    ASSERT_EQ(s.colors.size(), 2u);
    auto color_at = [](glm::vec3 p) {
        return p == glm::vec3(0, 0, 0)   ? glm::vec3(1, 0, 0)
               : p == glm::vec3(1, 0, 0) ? glm::vec3(0, 1, 0)
               : p == glm::vec3(1, 1, 0) ? glm::vec3(0, 0, 1)
                                         : glm::vec3(1, 1, 1);
    };
    float area = 0.0f;
    for (std::size_t t = 0; t < 2; ++t) {
        const SceneTriangle& tri = s.triangles[t];
        glm::vec3 n = glm::cross(tri.v[1] - tri.v[0], tri.v[2] - tri.v[0]);
        EXPECT_GT(n.z, 0.0f) << "triangle " << t << " lost its counter-clockwise winding";
        area += 0.5f * glm::length(n);
        for (int k = 0; k < 3; ++k) {
            EXPECT_EQ(tri.v[k].z, 0.0f);
            EXPECT_EQ(glm::vec3(s.colors[t][static_cast<std::size_t>(k)]), color_at(tri.v[k]))
                << "triangle " << t << " corner " << k;
        }
    }
    EXPECT_EQ(area, 1.0f); // the two halves of the unit square, neither twice
}

TEST(GltfDraco, TheCallersModelIsLeftCompressed)
{
    DracoSquare sq = draco_square();
    const std::size_t accessors = sq.b.model.accessors.size();
    test::import(sq.b);
    EXPECT_EQ(sq.b.model.accessors.size(), accessors);
    EXPECT_TRUE(sq.prim().extensions.count("KHR_draco_mesh_compression"));
}

TEST(GltfDraco, BrokenPrimitivesAreOneLineErrorsNamingThePrimitive)
{
    auto error = [](const std::function<void(DracoSquare&)>& breaker) {
        DracoSquare sq = draco_square();
        breaker(sq);
        std::string e = error_of([&] { test::import(sq.b, "sq.gltf"); });
        EXPECT_TRUE(contains(e, "sq.gltf: mesh 0 primitive 0: KHR_draco_mesh_compression: ")) << e;
        EXPECT_EQ(e.find('\n'), std::string::npos) << e;
        return e;
    };
    // The Draco bytes cut short, or overwritten.
    EXPECT_TRUE(contains(error([](DracoSquare& sq) { sq.b.model.bufferViews[0].byteLength /= 2; }), "cannot decode"));
    EXPECT_TRUE(contains(error([](DracoSquare& sq) {
                             auto& d = sq.b.model.buffers[0].data;
                             std::fill(d.begin(), d.begin() + 8, 0x5a);
                         }),
                         "cannot decode"));
    EXPECT_TRUE(contains(
        error([](DracoSquare& sq) { sq.ext().Get<tinygltf::Value::Object>()["bufferView"] = tinygltf::Value(7); }),
        "bufferView 7 does not exist"));
    EXPECT_TRUE(contains(error([](DracoSquare& sq) { sq.b.model.bufferViews[0].byteOffset = 1u << 20; }),
                         "lies outside its buffer"));
    EXPECT_TRUE(contains(
        error([](DracoSquare& sq) { sq.ext().Get<tinygltf::Value::Object>()["attributes"] = tinygltf::Value(3); }),
        "has no \"attributes\" object"));
    // An attribute id the Draco data does not have; an attribute the primitive does not list.
    EXPECT_TRUE(contains(error([](DracoSquare& sq) {
                             auto& attributes = sq.ext().Get<tinygltf::Value::Object>()["attributes"];
                             attributes.Get<tinygltf::Value::Object>()["COLOR_0"] = tinygltf::Value(9);
                         }),
                         "attribute COLOR_0: the Draco data has no attribute 9"));
    EXPECT_TRUE(contains(error([](DracoSquare& sq) { sq.prim().attributes.erase("COLOR_0"); }),
                         "compresses attribute COLOR_0, which the primitive does not list"));
    // Accessors that disagree with the decoded mesh.
    EXPECT_TRUE(
        contains(error([](DracoSquare& sq) { sq.b.model.accessors[0].count += 1; }), "POSITION: the accessor counts"));
    EXPECT_TRUE(contains(error([](DracoSquare& sq) { sq.b.model.accessors[2].count = 3; }),
                         "indices: the accessor counts 3 indices, the Draco mesh has 6"));
    EXPECT_TRUE(contains(error([](DracoSquare& sq) { sq.b.model.accessors[0].type = TINYGLTF_TYPE_VEC4; }),
                         "POSITION: the accessor has 4 components, the Draco attribute 3"));
    EXPECT_TRUE(contains(error([](DracoSquare& sq) { sq.prim().mode = 5; }), "mode 5"));
}

} // namespace
} // namespace pathcl::test_gltf_draco
