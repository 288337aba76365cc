// The light tree's host side (render/light_tree.h): the union of two emission cones holds
// both; the built tree holds every light in exactly one leaf, which its trail leads to,
// with every inner node's bounds holding its children's (box, power, cone); infinite
// lights stay beside it with their share of the power; the importance (light/light_tree.h)
// is zero exactly where a one-sided emitter cannot reach.
#include <cmath>
#include <numbers>
#include <random>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "common/error.h"
#include "light/light_tree.h"
#include "render/light_tree.h"

namespace pathcl {
namespace {

constexpr double kPi = std::numbers::pi;

glm::dvec3 random_direction(std::mt19937& rng)
{
    std::uniform_real_distribution<double> u(0.0, 1.0);
    double z = 2.0 * u(rng) - 1.0, phi = 2.0 * kPi * u(rng), r = std::sqrt(std::max(0.0, 1.0 - z * z));
    return {r * std::cos(phi), r * std::sin(phi), z};
}

// Whether direction d lies in cone c, up to `slack` radians.
bool in_cone(const LightCone& c, const glm::dvec3& d, double slack = 1e-9)
{
    if (c.cos_o <= -1.0)
        return true;
    double angle = std::acos(std::clamp(glm::dot(c.axis, d), -1.0, 1.0));
    return angle <= std::acos(std::clamp(c.cos_o, -1.0, 1.0)) + slack;
}

// A direction inside cone c, uniformly over its solid angle (its axis for a cone of one
// direction).
glm::dvec3 direction_in(const LightCone& c, std::mt19937& rng)
{
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const double cos_t = 1.0 - u(rng) * (1.0 - std::max(c.cos_o, -1.0));
    const double sin_t = std::sqrt(std::max(0.0, 1.0 - cos_t * cos_t)), phi = 2.0 * kPi * u(rng);
    const glm::dvec3 n = c.axis;
    const double sign = std::copysign(1.0, n.z), a = -1.0 / (sign + n.z), b = n.x * n.y * a;
    const glm::dvec3 t(1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x), bt(b, sign + n.y * n.y * a, -n.y);
    return glm::normalize(sin_t * std::cos(phi) * t + sin_t * std::sin(phi) * bt + cos_t * n);
}

TEST(LightTree, UnionOfTwoConesHoldsBoth)
{
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> angle(0.0, kPi);
    for (int t = 0; t < 500; ++t) {
        LightCone a{random_direction(rng), std::cos(angle(rng) * (t % 3 == 0 ? 0.05 : 1.0)), 0.0};
        LightCone b{random_direction(rng), std::cos(angle(rng) * (t % 5 == 0 ? 0.05 : 1.0)), 0.5};
        if (t % 7 == 0)
            b.axis = a.axis; // same axis
        if (t % 11 == 0)
            b.axis = -a.axis; // opposite axes
        LightCone u = cone_union(a, b);
        EXPECT_EQ(u.cos_e, 0.0) << "the wider emission spread is kept";
        for (int k = 0; k < 40; ++k) {
            EXPECT_TRUE(in_cone(u, direction_in(a, rng), 1e-9)) << "cone a left out, case " << t;
            EXPECT_TRUE(in_cone(u, direction_in(b, rng), 1e-9)) << "cone b left out, case " << t;
        }
        // Not vacuous: the union is not the whole sphere whenever both fit in a hemisphere
        // around a common axis.
        if (std::acos(a.cos_o) + std::acos(b.cos_o) + std::acos(glm::dot(a.axis, b.axis)) < kPi - 1e-6) {
            EXPECT_GT(u.cos_o, -1.0) << "case " << t;
        }
    }
}

std::vector<LightBounds> random_lights(std::size_t n, std::mt19937& rng)
{
    std::uniform_real_distribution<double> u(-10.0, 10.0), size(0.0, 0.5), decades(-2.0, 2.0);
    std::vector<LightBounds> lights(n);
    for (std::size_t i = 0; i < n; ++i) {
        LightBounds& b = lights[i];
        glm::dvec3 c(u(rng), u(rng), u(rng));
        glm::dvec3 half(size(rng), size(rng), size(rng));
        if (i % 5 == 0)
            half = glm::dvec3(0.0); // a point
        b.lo = c - half;
        b.hi = c + half;
        b.phi = std::pow(10.0, decades(rng));
        b.cone = i % 5 == 0 ? LightCone{{0, 0, 1}, -1.0, 0.0} : LightCone{random_direction(rng), 1.0, 0.0};
    }
    return lights;
}

bool box_holds(const LightTreeNode& outer, const LightTreeNode& inner)
{
    return outer.lo.x <= inner.lo.x && outer.lo.y <= inner.lo.y && outer.lo.z <= inner.lo.z &&
           outer.hi.x >= inner.hi.x && outer.hi.y >= inner.hi.y && outer.hi.z >= inner.hi.z;
}

LightCone node_cone(const LightTreeNode& n)
{
    return {{n.axis.x, n.axis.y, n.axis.z}, n.hi.w, n.axis.w};
}

TEST(LightTree, EveryLightHasOneLeafItsTrailLeadsToAndNodesHoldTheirChildren)
{
    std::mt19937 rng(7);
    for (std::size_t n : {1u, 2u, 3u, 17u, 1000u}) {
        std::vector<LightBounds> lights = random_lights(n, rng);
        LightTree tree = build_light_tree(lights);
        ASSERT_EQ(tree.nodes.size(), 2 * n - 1) << n;
        EXPECT_TRUE(tree.infinite.empty());
        EXPECT_EQ(tree.infinite_pick, 0.0);
        EXPECT_LT(tree.depth, 64u);
        std::vector<int> leaves_of(n, 0);
        for (std::size_t i = 0; i < tree.nodes.size(); ++i) {
            const LightTreeNode& node = tree.nodes[i];
            if (node.child < 0) {
                ++leaves_of[static_cast<std::size_t>(-1 - node.child)];
                continue;
            }
            ASSERT_LT(static_cast<std::size_t>(node.child), tree.nodes.size());
            ASSERT_GT(static_cast<std::size_t>(node.child), i + 1);
            for (const LightTreeNode* c : {&tree.nodes[i + 1], &tree.nodes[static_cast<std::size_t>(node.child)]}) {
                EXPECT_TRUE(box_holds(node, *c)) << "node " << i;
                EXPECT_GE(node.axis.w, -1.0f);
                EXPECT_LE(node.axis.w, c->axis.w) << "node " << i << ": a child emits wider";
                LightCone outer = node_cone(node), inner = node_cone(*c);
                for (int k = 0; k < 10; ++k)
                    EXPECT_TRUE(in_cone(outer, direction_in(inner, rng), 1e-5)) << "node " << i;
            }
            const double sum = double(tree.nodes[i + 1].lo.w) + tree.nodes[static_cast<std::size_t>(node.child)].lo.w;
            EXPECT_NEAR(node.lo.w, sum, 1e-5 * sum) << "node " << i << ": power is not its children's";
        }
        for (std::size_t l = 0; l < n; ++l) {
            EXPECT_EQ(leaves_of[l], 1) << "light " << l;
            std::size_t node = 0;
            pcl_ulong trail = tree.trails[l];
            while (tree.nodes[node].child >= 0) {
                node = (trail & 1u) ? static_cast<std::size_t>(tree.nodes[node].child) : node + 1;
                trail >>= 1;
            }
            EXPECT_EQ(tree.nodes[node].child, -1 - static_cast<pcl_int>(l)) << "light " << l << "'s trail";
        }
    }
}

TEST(LightTree, InfiniteLightsStayBesideTheTreeWithTheirShareOfPower)
{
    std::mt19937 rng(11);
    std::vector<LightBounds> lights = random_lights(10, rng);
    double bounded = 0.0;
    for (const LightBounds& b : lights)
        bounded += b.phi;
    LightBounds sun;
    sun.infinite = true;
    sun.phi = bounded / 3.0;
    lights.insert(lights.begin() + 4, sun);
    LightTree tree = build_light_tree(lights);
    ASSERT_EQ(tree.infinite.size(), 1u);
    EXPECT_EQ(tree.infinite[0], 4);
    EXPECT_EQ(tree.trails[4], ~pcl_ulong(0));
    EXPECT_NEAR(tree.infinite_pick, 0.25, 1e-12);
    EXPECT_EQ(tree.nodes.size(), 19u);
    // Only infinite lights: always picked, and no tree.
    LightTree only = build_light_tree({sun, sun});
    EXPECT_TRUE(only.nodes.empty());
    EXPECT_EQ(only.infinite_pick, 1.0);
}

TEST(LightTree, BoundsThatAreNotFiniteAreRefused)
{
    std::mt19937 rng(5);
    std::vector<LightBounds> lights = random_lights(4, rng);
    lights[2].hi.y = INFINITY;
    EXPECT_THROW(build_light_tree(lights), Error);
}

TEST(LightTree, ImportanceIsZeroOnlyBehindAOneSidedEmitter)
{
    // A unit triangle-like node at the origin facing +z, seen from points in every direction.
    std::mt19937 rng(13);
    for (int t = 0; t < 2000; ++t) {
        glm::dvec3 d = random_direction(rng);
        double dist = 2.0 + 10.0 * (t % 10);
        double radius2 = 0.25 * 0.02; // a small box's half diagonal squared
        double cos_b = std::sqrt(1.0 - radius2 / (dist * dist));
        double imp = light_cone_importance(1.0, 1.0, 0.0, dist * dist, d.z, cos_b, 2.0);
        double theta_b = std::acos(cos_b);
        double theta_w = std::acos(d.z);
        if (theta_w < kPi / 2 + theta_b - 1e-9) {
            EXPECT_GT(imp, 0.0) << "in front: " << d.z;
        } else if (theta_w > kPi / 2 + theta_b + 1e-9) {
            EXPECT_EQ(imp, 0.0) << "behind: " << d.z;
        }
    }
    // Closer is more important; a normal facing away still sees it (transmission).
    EXPECT_GT(light_cone_importance(1.0, 1.0, 0.0, 4.0, 1.0, 0.99, 2.0),
              light_cone_importance(1.0, 1.0, 0.0, 9.0, 1.0, 0.99, 2.0));
    EXPECT_GT(light_cone_importance(1.0, 1.0, 0.0, 4.0, 1.0, 0.99, 0.5), 0.0);
}

} // namespace
} // namespace pathcl
