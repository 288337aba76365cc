// glTF node hierarchy (host only, no device): a parent's TRS times a child's general
// matrix against a world matrix written out independently, composed in double precision,
// a mesh instanced by two nodes, and only the default scene imported. Each test checks
// one property; the tolerance it allows is stated next to it.
#include <algorithm>
#include <cstddef>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "scene/scene.h"
#include "support/gltf_builder.h"
#include "support/gltf_fixtures.h"

namespace pathcl::test_gltf_hierarchy {
namespace {

using test::d3;
using test::GltfBuilder;
using test::import;
using test::near_rel;
using test::quaternion;
using test::rodrigues;
using test::str;

glm::dvec3 transform_point(const glm::dmat4& m, const glm::dvec3& p)
{
    return glm::dvec3(m * glm::dvec4(p, 1.0));
}

// True when `t` has the vertices a, b, c in this counter-clockwise order, up to which
// vertex comes first (a cyclic rotation keeps the winding).
bool same_triangle(const SceneTriangle& t, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, double rel)
{
    const glm::dvec3 e[3] = {a, b, c};
    for (int s = 0; s < 3; ++s) {
        bool all = true;
        for (int k = 0; k < 3; ++k)
            all = all && near_rel(d3(t.v[k]), e[(k + s) % 3], rel);
        if (all)
            return true;
    }
    return false;
}

glm::dmat4 affine(const glm::dmat3& m, const glm::dvec3& t = glm::dvec3(0.0))
{
    glm::dmat4 r(m);
    r[3] = glm::dvec4(t, 1.0);
    return r;
}

// Parent: T * R * S (glTF TRS); child: a general `matrix` with shear. Expected world
// matrix written out here, independently of the loader's composition.
struct Hierarchy {
    glm::dvec3 t{1.5, -2.0, 3.25};
    glm::dvec3 axis{1.0, -2.0, 0.5};
    double angle = 0.7;
    glm::dvec3 s{2.0, 3.0, 0.5};
    // Column-major, as glTF stores it: columns c0, c1, c2, c3.
    std::vector<double> child_matrix = {1.0,  0.2, 0.0, 0.0, //
                                        0.0,  1.0, 0.3, 0.0, //
                                        0.1,  0.0, 1.5, 0.0, //
                                        -0.5, 4.0, 2.0, 1.0};

    glm::dmat4 expected_world() const
    {
        glm::dmat4 T(1.0);
        T[3] = glm::dvec4(t, 1.0);
        glm::dmat4 R = affine(rodrigues(axis, angle));
        glm::dmat4 S(1.0);
        S[0][0] = s.x;
        S[1][1] = s.y;
        S[2][2] = s.z;
        glm::dmat4 M(glm::dvec4(1.0, 0.2, 0.0, 0.0), glm::dvec4(0.0, 1.0, 0.3, 0.0), glm::dvec4(0.1, 0.0, 1.5, 0.0),
                     glm::dvec4(-0.5, 4.0, 2.0, 1.0));
        return T * R * S * M;
    }
};

TEST(GltfHierarchy, ParentTrsTimesChildMatrixGivesWorldPositions)
{
    // Tolerance: 1e-5 relative (positions are stored as float).
    Hierarchy h;
    const std::vector<glm::vec3> p = {{0.0f, 0.0f, 0.0f}, {1.0f, 0.5f, -0.25f}, {-0.75f, 2.0f, 1.0f}};
    GltfBuilder b;
    int mesh = b.add_mesh(b.add_positions(p), -1, b.add_material(glm::vec3(0.5f)));
    int child = b.add_node(mesh, h.child_matrix);
    int parent = b.add_node(-1, {}, {h.t.x, h.t.y, h.t.z}, quaternion(h.axis, h.angle), {h.s.x, h.s.y, h.s.z});
    b.model.nodes[static_cast<std::size_t>(parent)].children = {child};
    b.add_root(parent);

    Scene scene = import(b);
    ASSERT_EQ(scene.triangles.size(), 1u);
    glm::dmat4 w = h.expected_world();
    ASSERT_GT(glm::determinant(glm::dmat3(w)), 0.0); // no mirroring: the vertex order is kept
    glm::dvec3 e[3];
    for (int k = 0; k < 3; ++k)
        e[k] = transform_point(w, d3(p[static_cast<std::size_t>(k)]));
    const SceneTriangle& t = scene.triangles[0];
    EXPECT_TRUE(same_triangle(t, e[0], e[1], e[2], 1e-5))
        << "got " << str(d3(t.v[0])) << " " << str(d3(t.v[1])) << " " << str(d3(t.v[2])) << ", expected " << str(e[0])
        << " " << str(e[1]) << " " << str(e[2]);
}

TEST(GltfHierarchy, MeshDrawnByTwoNodesIsStoredOnceAndDrawnTwice)
{
    // Tolerance: 1e-6 relative. Node A: translation (5,0,0); node B: translation (0,0,-3)
    // and 90 degrees about +Z, (x, y) -> (-y, x). Stored once with two instances; with
    // copy_instances, two copies; both draw the same two triangles.
    GltfBuilder b;
    int mesh = b.add_mesh(b.add_positions({{0.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}}), -1,
                          b.add_material(glm::vec3(0.5f)));
    b.add_root(b.add_node(mesh, {}, {5.0, 0.0, 0.0}));
    b.add_root(b.add_node(mesh, {}, {0.0, 0.0, -3.0}, quaternion({0.0, 0.0, 1.0}, std::numbers::pi / 2)));
    Scene instanced = import(b), copied = import_copies(b);
    ASSERT_EQ(instanced.triangles.size(), 1u);
    ASSERT_EQ(instanced.meshes.size(), 1u);
    ASSERT_EQ(instanced.instances.size(), 2u);
    ASSERT_EQ(copied.triangles.size(), 2u);
    EXPECT_TRUE(copied.instances.empty());
    for (const Scene* scene : {&instanced, &copied}) {
        std::vector<SceneTriangle> drawn = drawn_triangle_list(*scene);
        ASSERT_EQ(drawn.size(), 2u);
        auto count = [&](glm::dvec3 a, glm::dvec3 bb, glm::dvec3 c) {
            int n = 0;
            for (const SceneTriangle& t : drawn)
                n += same_triangle(t, a, bb, c, 1e-6) ? 1 : 0;
            return n;
        };
        EXPECT_EQ(count({5, 0, 0}, {6, 0, 0}, {5, 1, 0}), 1) << "drawing at node A";
        EXPECT_EQ(count({0, 0, -3}, {0, 1, -3}, {-1, 0, -3}), 1) << "drawing at node B";
    }
}

TEST(GltfHierarchy, TransformsAreComposedInDoublePrecision)
{
    // Tolerance: 1e-9 absolute. Parent at x = 1e5, child at x = -99999.999: the sum 0.001
    // survives in double precision; composed in float (spacing 0.0078 at 1e5) it is 0.
    GltfBuilder b;
    int mesh = b.add_mesh(b.add_positions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}), -1, b.add_material(glm::vec3(0.5f)));
    int child = b.add_node(mesh, {}, {-99999.999, 0.0, 0.0});
    int parent = b.add_node(-1, {}, {100000.0, 0.0, 0.0});
    b.model.nodes[static_cast<std::size_t>(parent)].children = {child};
    b.add_root(parent);
    Scene scene = import(b);
    ASSERT_EQ(scene.triangles.size(), 1u);
    double x_min = std::min({scene.triangles[0].v[0].x, scene.triangles[0].v[1].x, scene.triangles[0].v[2].x});
    EXPECT_NEAR(x_min, static_cast<double>(0.001f), 1e-9);
}

TEST(GltfHierarchy, OnlyTheDefaultSceneIsImported)
{
    // Exact count: scene 1 is the default and holds one triangle; scene 0 holds another.
    GltfBuilder b;
    int mat = b.add_material(glm::vec3(0.5f));
    int m0 = b.add_mesh(b.add_positions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}), -1, mat);
    int m1 = b.add_mesh(b.add_positions({{0, 0, 5}, {1, 0, 5}, {0, 1, 5}}), -1, mat);
    b.add_root(b.add_node(m0));
    b.model.scenes.emplace_back();
    b.model.scenes[1].nodes = {b.add_node(m1)};
    b.model.defaultScene = 1;
    Scene scene = import(b);
    ASSERT_EQ(scene.triangles.size(), 1u);
    EXPECT_EQ(scene.triangles[0].v[0].z, 5.0f);
}

} // namespace
} // namespace pathcl::test_gltf_hierarchy
