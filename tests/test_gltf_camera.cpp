// The glTF camera (host only, no device): position and orientation from a camera node
// under a scaled parent, yfov unchanged by node scale, which camera node --camera N picks,
// and the framing camera made when the file has none. Each test checks one property; the
// tolerance it allows is stated next to it.
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "common/error.h"
#include "scene/gltf_loader.h"
#include "scene/scene.h"
#include "support/gltf_builder.h"
#include "support/gltf_fixtures.h"

namespace pathcl::test_gltf_camera {
namespace {

using test::GltfBuilder;
using test::import;
using test::in_world_space;
using test::kTilted;
using test::near_rel;
using test::quaternion;
using test::rodrigues;
using test::str;

// Root node: translation (10, -4, 2) and uniform scale 2. Its child: translation
// (1, 2, 3), a general rotation, scale 3 and the perspective camera (yfov 0.7).
struct CameraRig {
    glm::dvec3 parent_t{10.0, -4.0, 2.0};
    double parent_s = 2.0;
    glm::dvec3 child_t{1.0, 2.0, 3.0};
    glm::dvec3 axis{1.0, 2.0, 3.0};
    double angle = 1.1;
    double yfov = 0.7;

    Scene load() const
    {
        GltfBuilder b;
        b.add_root(b.add_node(b.add_mesh(b.add_positions(kTilted), -1, b.add_material(glm::vec3(0.5f)))));
        int cam = b.add_node(-1, {}, {child_t.x, child_t.y, child_t.z}, quaternion(axis, angle), {3.0, 3.0, 3.0});
        b.model.nodes[static_cast<std::size_t>(cam)].camera = b.add_perspective_camera(yfov);
        int parent = b.add_node(-1, {}, {parent_t.x, parent_t.y, parent_t.z}, {}, {parent_s, parent_s, parent_s});
        b.model.nodes[static_cast<std::size_t>(parent)].children = {cam};
        b.add_root(parent);
        return import(b);
    }
    glm::dmat3 rotation() const { return rodrigues(axis, angle); }
};

TEST(GltfCamera, PositionIsTheNodeWorldPosition)
{
    // Tolerance: 1e-9 relative. parent_t + parent_s * child_t.
    CameraRig rig;
    Scene s = rig.load();
    glm::dvec3 expected = rig.parent_t + rig.parent_s * rig.child_t;
    EXPECT_TRUE(near_rel(s.camera.position, expected, 1e-9)) << str(s.camera.position);
}

TEST(GltfCamera, ForwardIsLocalMinusZ)
{
    // Tolerance: 1e-9.
    CameraRig rig;
    Scene s = rig.load();
    glm::dvec3 expected = rig.rotation() * glm::dvec3(0, 0, -1);
    EXPECT_TRUE(near_rel(s.camera.forward, expected, 1e-9)) << str(s.camera.forward) << " vs " << str(expected);
}

TEST(GltfCamera, UpIsLocalPlusY)
{
    // Tolerance: 1e-9.
    CameraRig rig;
    Scene s = rig.load();
    glm::dvec3 expected = rig.rotation() * glm::dvec3(0, 1, 0);
    EXPECT_TRUE(near_rel(s.camera.up, expected, 1e-9)) << str(s.camera.up) << " vs " << str(expected);
}

TEST(GltfCamera, RightIsLocalPlusX)
{
    // Tolerance: 1e-9.
    CameraRig rig;
    Scene s = rig.load();
    glm::dvec3 expected = rig.rotation() * glm::dvec3(1, 0, 0);
    EXPECT_TRUE(near_rel(s.camera.right, expected, 1e-9)) << str(s.camera.right) << " vs " << str(expected);
}

TEST(GltfCamera, NodeScaleDoesNotChangeYfov)
{
    // Tolerance: exact (the file's value; scale 2 x 3 on the camera's nodes).
    CameraRig rig;
    Scene s = rig.load();
    EXPECT_EQ(s.camera.yfov, rig.yfov);
    EXPECT_TRUE(s.camera.from_file);
}

TEST(GltfCamera, FirstCameraNodeIsUsedAndCameraNPicksTheNth)
{
    // Tolerance: exact. Root order: an orthographic camera, perspective A (yfov 0.5),
    // perspective B (yfov 0.9). By default the first camera node (the orthographic one);
    // --camera N counts camera nodes of either type from 0.
    GltfBuilder b;
    b.add_root(b.add_node(b.add_mesh(b.add_positions(kTilted), -1, b.add_material(glm::vec3(0.5f)))));
    tinygltf::Camera ortho;
    ortho.type = "orthographic";
    ortho.orthographic.xmag = ortho.orthographic.ymag = 1.0;
    ortho.orthographic.znear = 0.01;
    ortho.orthographic.zfar = 100.0;
    b.model.cameras.push_back(ortho);
    int o = b.add_node(-1, {}, {0.0, 0.0, 9.0});
    b.model.nodes[static_cast<std::size_t>(o)].camera = 0;
    int a = b.add_node(-1, {}, {0.0, 0.0, 5.0});
    b.model.nodes[static_cast<std::size_t>(a)].camera = b.add_perspective_camera(0.5);
    int c = b.add_node(-1, {}, {0.0, 0.0, 7.0});
    b.model.nodes[static_cast<std::size_t>(c)].camera = b.add_perspective_camera(0.9);
    b.add_root(o);
    b.add_root(a);
    b.add_root(c);
    Scene s = import(b);
    EXPECT_TRUE(s.camera.orthographic);
    EXPECT_EQ(s.camera.ymag, 1.0);
    EXPECT_EQ(s.camera.position, glm::dvec3(0.0, 0.0, 9.0));
    Scene s1 = in_world_space(import_gltf(b.model, "test.gltf", "", {1, ""}));
    EXPECT_FALSE(s1.camera.orthographic);
    EXPECT_EQ(s1.camera.yfov, 0.5);
    EXPECT_EQ(s1.camera.position, glm::dvec3(0.0, 0.0, 5.0));
    Scene s2 = in_world_space(import_gltf(b.model, "test.gltf", "", {2, ""}));
    EXPECT_EQ(s2.camera.yfov, 0.9);
    EXPECT_EQ(s2.camera.position, glm::dvec3(0.0, 0.0, 7.0));
    EXPECT_THROW(import_gltf(b.model, "test.gltf", "", {3, ""}), Error);
}

// Bounds (0..2, -1..1, 3..4) from two triangles; no camera in the file.
Scene framed_scene()
{
    GltfBuilder b;
    int mat = b.add_material(glm::vec3(0.5f));
    b.add_root(b.add_node(b.add_mesh(b.add_positions({{0, -1, 3}, {2, -1, 3}, {2, 1, 3}}), -1, mat)));
    b.add_root(b.add_node(b.add_mesh(b.add_positions({{0, -1, 4}, {2, 1, 4}, {0, 1, 4}}), -1, mat)));
    return import(b);
}

TEST(GltfCamera, WithoutCameraTheFramingCameraIsOutsideTheBounds)
{
    // Exact comparison with the bounds (0..2, -1..1, 3..4): outside the bounding sphere.
    Scene s = framed_scene();
    EXPECT_FALSE(s.camera.from_file);
    glm::dvec3 centre(1.0, 0.0, 3.5);
    double radius = 0.5 * glm::length(glm::dvec3(2.0, 2.0, 1.0));
    EXPECT_GT(glm::length(s.camera.position - centre), radius) << str(s.camera.position);
}

TEST(GltfCamera, WithoutCameraTheFramingCameraLooksAtTheCentre)
{
    // Tolerance: direction to the centre within 1e-9 of forward.
    Scene s = framed_scene();
    glm::dvec3 to_centre = glm::normalize(glm::dvec3(1.0, 0.0, 3.5) - s.camera.position);
    EXPECT_TRUE(near_rel(s.camera.forward, to_centre, 1e-9)) << str(s.camera.forward) << " vs " << str(to_centre);
}

TEST(GltfCamera, WithoutCameraEveryBoundsCornerIsInsideTheVerticalFieldOfView)
{
    // Tolerance: 1e-9 rad. The angle from forward to each corner of the bounds is at most
    // half the vertical field of view (the narrower one for any aspect ratio >= 1).
    Scene s = framed_scene();
    ASSERT_GT(s.camera.yfov, 0.0);
    for (int i = 0; i < 8; ++i) {
        glm::dvec3 corner((i & 1) ? 2.0 : 0.0, (i & 2) ? 1.0 : -1.0, (i & 4) ? 4.0 : 3.0);
        double cosang = glm::dot(glm::normalize(corner - s.camera.position), glm::normalize(s.camera.forward));
        EXPECT_LE(std::acos(std::min(1.0, cosang)), 0.5 * s.camera.yfov + 1e-9) << "corner " << str(corner);
    }
}

} // namespace
} // namespace pathcl::test_gltf_camera
