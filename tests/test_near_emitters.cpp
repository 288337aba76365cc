// --triangle-sampling auto (compile/near_emitters.h): solid-angle sampling is compiled in
// where half the emitters' light meets surfaces near enough for the kernels to use it, or
// where one surface comes very close to an emitter, and only there: not for a light whose
// surroundings are behind it or far off (the Cornell box's ceiling light), nor where a
// little of its light grazes a wall and meets other surfaces farther off (the textured
// scene's panel), nor for a glowing sphere whose float vertices put neighbours a
// rounding error in front of each other.
#include <string>

#include <gtest/gtest.h>

#include "compile/near_emitters.h"
#include "scene/gltf_loader.h"
#include "support/gltf_builder.h"

namespace pathcl::test_near_emitters {
namespace {

// A 1 x 0.5 m emissive panel in the plane z = 0 (two triangles of 0.25 m^2: the kernels
// sample them by solid angle within 0.91 m of their centroids), facing +z (`facing` 1) or
// -z (-1), and a grey wall of 4 x 4 m parallel to it at z = wall_z; with `lamp`, a second
// emitter of 0.1 x 0.1 m (2 % of the power) 1 cm in front of the wall, facing it.
Scene panel_and_wall(float facing, float wall_z, bool lamp = false)
{
    test::GltfBuilder b;
    const int grey = b.add_material(glm::vec3(0.5f));
    b.add_root(b.add_node(b.add_quad_mesh({{-2, -2, wall_z}, {-2, 2, wall_z}, {2, 2, wall_z}, {2, -2, wall_z}}, grey)));
    const int light = b.add_material(glm::vec3(0.0f), glm::vec3(5.0f));
    if (facing > 0.0f)
        b.add_root(
            b.add_node(b.add_quad_mesh({{-0.5f, 0, 0}, {0.5f, 0, 0}, {0.5f, 0.5f, 0}, {-0.5f, 0.5f, 0}}, light)));
    else
        b.add_root(
            b.add_node(b.add_quad_mesh({{-0.5f, 0, 0}, {-0.5f, 0.5f, 0}, {0.5f, 0.5f, 0}, {0.5f, 0, 0}}, light)));
    if (lamp) {
        const float z = wall_z - 0.01f;
        b.add_root(
            b.add_node(b.add_quad_mesh({{1.0f, 1.0f, z}, {1.1f, 1.0f, z}, {1.1f, 1.1f, z}, {1.0f, 1.1f, z}}, light)));
    }
    b.add_camera_node(b.add_perspective_camera(1.0), {0.0, 0.0, -3.0});
    return import_gltf(b.model, "panel-and-wall");
}

// A glowing UV sphere (outward, 80 x 160) above a floor.
Scene glowing_sphere()
{
    test::GltfBuilder b;
    const int grey = b.add_material(glm::vec3(0.5f));
    b.add_root(b.add_node(b.add_quad_mesh({{-5, 0, -5}, {-5, 0, 5}, {5, 0, 5}, {5, 0, -5}}, grey)));
    const int glow = b.add_material(glm::vec3(0.0f), glm::vec3(5.0f));
    b.add_root(b.add_node(b.add_sphere_mesh(0.4, 80, 160, glow, false), {}, {1.3, 0.9, -0.7}));
    b.add_camera_node(b.add_perspective_camera(1.0), {0.0, 1.0, 6.0});
    return import_gltf(b.model, "glowing-sphere");
}

TriangleSampling resolved(const Scene& scene, Integrator integrator = Integrator::Megakernel)
{
    RenderOptions o; // triangle_sampling Auto by default
    o.integrator = integrator;
    return resolve_triangle_sampling(scene, o);
}

TEST(NearEmitters, AutoSamplesBySolidAngleWhereASurfaceIsNearTheLitSide)
{
    EXPECT_EQ(RenderOptions().triangle_sampling, TriangleSampling::Auto);
    EXPECT_EQ(resolved(panel_and_wall(1.0f, 0.03f)), TriangleSampling::SolidAngle) << "a wall 3 cm in front";
    EXPECT_EQ(resolved(panel_and_wall(1.0f, 0.4f)), TriangleSampling::SolidAngle)
        << "a wall 0.4 m in front: 81 % of the light meets it within 0.91 m";
    EXPECT_EQ(resolved(panel_and_wall(1.0f, 0.8f)), TriangleSampling::Area)
        << "a wall 0.8 m in front: 23 % of the light meets it within 0.91 m, none much closer";
    EXPECT_EQ(resolved(panel_and_wall(-1.0f, 0.03f)), TriangleSampling::Area) << "the wall behind it";
    EXPECT_EQ(resolved(panel_and_wall(-1.0f, 0.03f, true)), TriangleSampling::SolidAngle)
        << "the wall behind the panel, a small lamp 1 cm in front of it";
    EXPECT_EQ(resolved(panel_and_wall(1.0f, 1.2f)), TriangleSampling::Area) << "a wall 1.2 m in front";
    EXPECT_EQ(resolved(panel_and_wall(1.0f, 0.03f), Integrator::Wavefront), TriangleSampling::Area)
        << "the wavefront has area sampling only";
    EXPECT_EQ(resolved(load_gltf(std::string(PATHCL_SOURCE_DIR) + "/scenes/cornell-box.gltf")), TriangleSampling::Area)
        << "the ceiling light: the ceiling behind it, the walls and blocks far off";
    EXPECT_EQ(resolved(load_gltf(std::string(PATHCL_SOURCE_DIR) + "/scenes/textured.gltf")), TriangleSampling::Area)
        << "the panel: a seventh of its light meets the sphere, the box and the back wall within 1.79 m";
    EXPECT_EQ(resolved(glowing_sphere()), TriangleSampling::Area) << "a convex emitter of float vertices";
    for (TriangleSampling asked : {TriangleSampling::Area, TriangleSampling::SolidAngle}) {
        RenderOptions explicit_choice;
        explicit_choice.triangle_sampling = asked;
        EXPECT_EQ(resolve_triangle_sampling(panel_and_wall(-1.0f, 0.03f), explicit_choice), asked);
        EXPECT_EQ(resolve_triangle_sampling(panel_and_wall(1.0f, 0.03f), explicit_choice), asked);
    }
}

} // namespace
} // namespace pathcl::test_near_emitters
