// Rays spawned from surface points (kernels/geom/ray_offset.cl offset_ray_origin) never re-hit
// the surface they leave, on either side, including surfaces lying exactly on a
// coordinate plane (where the hit point is exact, its error bound is zero and only the
// intersection test's own conservative t bound prevents a self-hit), and at coordinates
// from 1e-6 to 1e6. Naive variant that fails: no t > delta-t check in ray_triangle_block (the
// Cornell box's x = 0 wall then loses next event estimation on one of its triangles).
#include <random>

#include <gtest/gtest.h>

#include "bvh/bvh_builder.h"
#include "bvh/triangle_blocks.h"
#include "support/device_fixture.h"
#include "support/leaf_triangles.h"
#include "support/random_meshes.h"

namespace pathcl::test_self_intersection {
namespace {

struct Counts {
    std::size_t self_hits = 0, rays = 0;
};

// Traces `rays` spawned rays; counts hits on the source triangle or, when `planar`, on
// any triangle (every triangle then lies in one plane, so any hit is a self-hit).
Counts spawn(const std::vector<glm::vec3>& v, std::size_t rays, bool planar, std::uint32_t seed)
{
    static cl::Program program = test::build_test_program("trace_test_kernels.cl");
    ClDevice& dev = test::test_device();
    Bvh bvh = build_bvh(bvh_input_from_triangles(v));
    std::vector<Triangle> tris = test::leaf_order_triangles(v, bvh);
    std::vector<TriangleBlock> blocks;
    make_triangle_blocks(bvh.nodes, 0, tris, blocks);
    cl::Buffer nodes(dev.context, CL_MEM_COPY_HOST_PTR, bvh.nodes.size() * sizeof(BvhNode), bvh.nodes.data());
    cl::Buffer tb(dev.context, CL_MEM_COPY_HOST_PTR, tris.size() * sizeof(Triangle), tris.data());
    cl::Buffer bb(dev.context, CL_MEM_COPY_HOST_PTR, blocks.size() * sizeof(TriangleBlock), blocks.data());
    cl::Buffer hit(dev.context, CL_MEM_WRITE_ONLY, rays * sizeof(cl_int));
    cl::Buffer src(dev.context, CL_MEM_WRITE_ONLY, rays * sizeof(cl_int));
    cl::Kernel k(program, "test_spawned_ray_hits");
    set_kernel_args(k, nodes, tb, bb, static_cast<cl_uint>(tris.size()), seed, hit, src);
    dev.queue.enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(rays));
    std::vector<cl_int> h(rays), s(rays);
    dev.queue.enqueueReadBuffer(hit, CL_TRUE, 0, rays * sizeof(cl_int), h.data());
    dev.queue.enqueueReadBuffer(src, CL_TRUE, 0, rays * sizeof(cl_int), s.data());
    Counts c;
    c.rays = rays;
    for (std::size_t i = 0; i < rays; ++i)
        c.self_hits += planar ? (h[i] >= 0) : (h[i] == s[i]);
    return c;
}

// A rectangle split into two triangles, lying exactly in a coordinate plane.
std::vector<glm::vec3> axis_plane_quad(int axis, float at, float size)
{
    auto point = [&](float a, float b) {
        glm::vec3 p;
        p[axis] = at;
        p[(axis + 1) % 3] = a;
        p[(axis + 2) % 3] = b;
        return p;
    };
    glm::vec3 p0 = point(0, 0), p1 = point(size, 0), p2 = point(size, size), p3 = point(0, size);
    return {p0, p1, p2, p0, p2, p3};
}

TEST(SelfIntersection, ExactCoordinatePlanesOneMillionRays)
{
    // The Cornell box's walls: the planes x = 0 and y = 0, and an offset plane z = 0.5592.
    for (auto [axis, at] : {std::pair{0, 0.0f}, std::pair{1, 0.0f}, std::pair{2, 0.5592f}}) {
        Counts c = spawn(axis_plane_quad(axis, at, 0.5488f), 1000000, true, 1u + static_cast<std::uint32_t>(axis));
        EXPECT_EQ(c.self_hits, 0u) << "plane axis " << axis << " at " << at << ": " << c.self_hits << " of " << c.rays
                                   << " spawned rays re-hit the plane";
    }
}

TEST(SelfIntersection, TrianglesFrom1e6To1e6OneMillionRays)
{
    for (float scale : {1e-6f, 1e-3f, 1.0f, 1e3f, 1e6f}) {
        std::vector<glm::vec3> v = test::random_triangle_soup(2000, 17);
        for (glm::vec3& p : v)
            p = p * scale + glm::vec3(3.0f * scale, -2.0f * scale, 0.5f * scale);
        Counts c = spawn(v, 1000000, false, 9);
        EXPECT_EQ(c.self_hits, 0u) << "scale " << scale << ": " << c.self_hits << " of " << c.rays;
    }
}

} // namespace
} // namespace pathcl::test_self_intersection
