// The light tree's host side (compile/light_tree.h): the union of two emission cones holds
// both; the built tree holds every light in exactly one leaf lane, which its trail leads
// to, with every lane's bounds (sphere, power, cone) holding those of the lanes below it,
// its cone no wider than its lights need about its axis; infinite lights stay beside it
// with their share of the power.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <numbers>
#include <random>
#include <string>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "common/error.h"
#include "compile/light_tree.h"
#include "scene/gltf_loader.h"
#include "support/glowing_sphere.h"
#include "support/gltf_builder.h"

namespace pathcl::test_light_tree {
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

// Coplanar triangles' normals agree to rounding: their cones' union must stay as narrow
// (a whole-sphere cone there sends picks to emitters facing away).
TEST(LightTree, UnionOfNearlyParallelConesIsNarrow)
{
    std::mt19937 rng(5);
    for (int t = 0; t < 200; ++t) {
        const glm::dvec3 a = random_direction(rng);
        const double tilt = std::ldexp(1.0, -40 - t % 12); // 2^-40 .. 2^-51 radians
        const glm::dvec3 b = glm::normalize(a + tilt * glm::normalize(glm::cross(a, random_direction(rng))));
        const double cos_o = t % 2 == 0 ? 1.0 : std::cos(0.01);
        const LightCone u = cone_union({a, cos_o, 0.0}, {b, cos_o, 0.0});
        EXPECT_GE(u.cos_o, std::cos(0.01 + 1e-9)) << "case " << t << ": tilt " << tilt;
        // acos near 1 resolves angles to about 1.5e-8 radians.
        EXPECT_TRUE(in_cone(u, a, 1e-7) && in_cone(u, b, 1e-7)) << "case " << t;
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

// One lane's bounds, read back.
struct Lane {
    glm::dvec3 centre;
    double radius2, phi;
    LightCone cone;
    pcl_int child;
};

// Lane k of node n (its axis renormalized: stored as float, its length is 1 only to a
// few ulps, which the cone's outward rounding covers).
Lane lane_of(const LightTreeNode& n, int k)
{
    const glm::dvec3 axis(n.axis_x.s[k], n.axis_y.s[k], n.axis_z.s[k]);
    return {{n.centre_x.s[k], n.centre_y.s[k], n.centre_z.s[k]},
            n.radius2.s[k],
            n.phi.s[k],
            {glm::length(axis) > 0.0 ? glm::normalize(axis) : axis, n.cos_o.s[k], n.cos_e.s[k]},
            n.child.s[k]};
}

// Whether lane a's sphere holds point p.
bool sphere_holds(const Lane& a, const glm::dvec3& p)
{
    return glm::length(p - a.centre) <= std::sqrt(a.radius2) * (1.0 + 1e-6) + 1e-9;
}

// The lights of a leaf lane's child (-1 - leaf): one light, or a cluster's.
std::vector<std::size_t> leaf_lights(const LightTree& tree, pcl_int child)
{
    const pcl_int leaf = -1 - child;
    if (!(leaf & LIGHT_TREE_CLUSTER))
        return {static_cast<std::size_t>(leaf)};
    const auto header = static_cast<std::size_t>(LIGHT_TREE_LEAF_INDEX(leaf));
    std::vector<std::size_t> lights;
    for (pcl_int i = 1; i <= tree.cluster.at(header).light; ++i)
        lights.push_back(static_cast<std::size_t>(tree.cluster.at(header + static_cast<std::size_t>(i)).light));
    return lights;
}

// Walks the subtree of node `index`, whose parent lane is `parent`: every node uses at
// least two lanes (one at a root of one light), whose powers sum to the parent's; counts
// each light's leaf lanes.
void check_subtree(const LightTree& tree, std::size_t index, const Lane* parent, std::vector<int>& leaves_of,
                   std::uint32_t depth)
{
    ASSERT_LT(index, tree.nodes.size());
    ASSERT_LE(depth, tree.depth);
    double phi = 0.0;
    int used = 0;
    for (int k = 0; k < LIGHT_TREE_WIDTH; ++k) {
        Lane lane = lane_of(tree.nodes[index], k);
        if (lane.phi == 0.0)
            continue;
        ++used;
        phi += lane.phi;
        if (lane.child < 0)
            for (std::size_t l : leaf_lights(tree, lane.child))
                ++leaves_of.at(l);
        else
            check_subtree(tree, static_cast<std::size_t>(lane.child), &lane, leaves_of, depth + 1);
    }
    EXPECT_GE(used, parent ? 2 : 1) << "node " << index;
    if (parent) {
        EXPECT_NEAR(parent->phi, phi, 1e-5 * phi) << "node " << index << ": power is not its lanes'";
    }
}

// Checks that every light of `lights` (finite, all of them) has one leaf lane in `tree`,
// which its trail leads to, and that every lane on the way holds it.
void check_every_light_within_its_lanes(const std::vector<LightBounds>& lights, const LightTree& tree,
                                        std::mt19937& rng)
{
    const std::size_t n = lights.size();
    std::vector<int> leaves_of(n, 0);
    check_subtree(tree, 0, nullptr, leaves_of, 1);
    for (std::size_t l = 0; l < n; ++l) {
        EXPECT_EQ(leaves_of[l], 1) << "light " << l;
        // Down its trail, every lane holds the light: its box's corners in the lane's
        // sphere, its directions in the lane's cone, its spread in the lane's.
        const LightBounds& b = lights[l];
        std::size_t node = 0;
        pcl_ulong trail = tree.trails[l];
        bool reached = false;
        for (std::uint32_t level = 0; level < tree.depth && !reached; ++level) {
            int k = 0;
            for (; k < LIGHT_TREE_WIDTH; ++k) {
                const pcl_int code = tree.nodes[node].code.s[k];
                const pcl_ulong mask = (pcl_ulong(1) << LIGHT_TREE_CODE_LENGTH(code)) - 1;
                if ((trail & mask) == pcl_ulong(LIGHT_TREE_CODE_BITS(code)))
                    break;
            }
            ASSERT_LT(k, LIGHT_TREE_WIDTH) << "light " << l << ": no lane's code starts its trail";
            trail >>= LIGHT_TREE_CODE_LENGTH(tree.nodes[node].code.s[k]);
            const Lane lane = lane_of(tree.nodes[node], k);
            for (int corner = 0; corner < 8; ++corner) {
                glm::dvec3 p((corner & 1) ? b.hi.x : b.lo.x, (corner & 2) ? b.hi.y : b.lo.y,
                             (corner & 4) ? b.hi.z : b.lo.z);
                EXPECT_TRUE(sphere_holds(lane, p)) << "light " << l << " at level " << level;
            }
            for (int t = 0; t < 10; ++t)
                EXPECT_TRUE(in_cone(lane.cone, direction_in(b.cone, rng), 1e-5)) << "light " << l;
            EXPECT_LE(lane.cone.cos_e, b.cone.cos_e) << "light " << l;
            if (lane.child < 0) {
                const std::vector<std::size_t> leaf = leaf_lights(tree, lane.child);
                EXPECT_NE(std::find(leaf.begin(), leaf.end(), l), leaf.end()) << "light " << l << "'s trail";
                reached = true;
            } else {
                node = static_cast<std::size_t>(lane.child);
            }
        }
        EXPECT_TRUE(reached) << "light " << l << "'s trail ends nowhere";
    }
}

TEST(LightTree, EveryLightHasOneLeafItsTrailLeadsToWithinEveryLaneOnTheWay)
{
    std::mt19937 rng(7);
    for (std::size_t n : {1u, 2u, 3u, 9u, 17u, 1000u}) {
        std::vector<LightBounds> lights = random_lights(n, rng);
        LightTree tree = build_light_tree(lights);
        EXPECT_TRUE(tree.infinite.empty());
        EXPECT_EQ(tree.infinite_pick, 0.0);
        EXPECT_LE(tree.depth, 62u);
        check_every_light_within_its_lanes(lights, tree, rng);
        // Not vacuous: a thousand lights take several levels of eight.
        if (n == 1000) {
            EXPECT_GE(tree.depth, 3u);
            EXPECT_LT(tree.nodes.size(), 500u) << "fewer than two lanes a node";
        }
    }
    // No point light widens the cones to the whole sphere here: they are tightened around
    // the lights at every node. Spots among the triangles bring cones of their own width.
    std::vector<LightBounds> sphere = test::glowing_sphere(24, 24, {1.0, 2.0, 3.0}, 1.0, 0.6, 0.45).lights;
    for (std::size_t i = 0; i < sphere.size(); i += 7)
        sphere[i].cone = {sphere[i].cone.axis, std::cos(0.3), std::cos(0.4)};
    check_every_light_within_its_lanes(sphere, build_light_tree(sphere), rng);
}

// The lights below `child` (a lane's child: a node, or -1 - a light).
void lights_below(const LightTree& tree, pcl_int child, std::vector<std::size_t>& lights)
{
    if (child < 0) {
        for (std::size_t l : leaf_lights(tree, child))
            lights.push_back(l);
        return;
    }
    const LightTreeNode& n = tree.nodes[static_cast<std::size_t>(child)];
    for (int k = 0; k < LIGHT_TREE_WIDTH; ++k)
        if (n.phi.s[k] > 0.0f)
            lights_below(tree, n.child.s[k], lights);
}

// A lane's cone is as narrow about its axis as its lights allow. The cone that holds two
// cones holds each whole, so a node's cone made only as the union of its children's grows
// wider up the tree than its lights need: made so, 311 of this sphere's lanes came out
// wider, a root lane over 602 triangles 109 degrees wide where 87 hold them.
TEST(LightTree, EachLanesConeIsAsNarrowAsItsLightsAllowAboutItsAxis)
{
    // Turned so that its poles, where the triangles crowd, lie off the axes.
    const test::GlowingSphere sphere = test::glowing_sphere(40, 40, {1.0, 2.0, 3.0}, 1.0, 0.6, 0.45);
    const std::vector<LightBounds>& lights = sphere.lights;
    const LightTree tree = build_light_tree(lights);
    int lanes = 0, broad = 0;
    for (std::size_t i = 0; i < tree.nodes.size(); ++i)
        for (int k = 0; k < LIGHT_TREE_WIDTH; ++k) {
            const Lane lane = lane_of(tree.nodes[i], k);
            if (lane.phi == 0.0)
                continue;
            std::vector<std::size_t> below;
            lights_below(tree, lane.child, below);
            double cos_needed = 1.0;
            for (std::size_t l : below)
                cos_needed = std::min(cos_needed, glm::dot(lane.cone.axis, sphere.normal[l]));
            // float rounding of the axis and the cosine, outward
            EXPECT_GE(lane.cone.cos_o, cos_needed - 1e-6)
                << "node " << i << " lane " << k << ": " << below.size() << " lights";
            ++lanes;
            broad += below.size() >= 64;
        }
    EXPECT_GT(lanes, 800);
    EXPECT_GE(broad, 8) << "lanes over many lights, where unions of unions would widen the cone";
}

// The number of lights below each of node n's lanes (0: an empty lane).
std::array<std::size_t, LIGHT_TREE_WIDTH> lights_per_lane(const LightTree& tree, const LightTreeNode& n)
{
    std::array<std::size_t, LIGHT_TREE_WIDTH> count{};
    for (int k = 0; k < LIGHT_TREE_WIDTH; ++k)
        if (n.phi.s[k] > 0.0f) {
            std::vector<std::size_t> below;
            lights_below(tree, n.child.s[k], below);
            count[static_cast<std::size_t>(k)] = below.size();
        }
    return count;
}

// Whether lanes a and b of node n are the two halves of one binary node: codes of one
// length that differ only in their last step.
bool binary_halves(const LightTreeNode& n, int a, int b)
{
    const int length = LIGHT_TREE_CODE_LENGTH(n.code.s[a]);
    const int parent = (1 << (length - 1)) - 1; // the steps down to their parent
    return length > 0 && LIGHT_TREE_CODE_LENGTH(n.code.s[b]) == length &&
           (LIGHT_TREE_CODE_BITS(n.code.s[a]) & parent) == (LIGHT_TREE_CODE_BITS(n.code.s[b]) & parent);
}

// In a node over more than eight lights, a lane over at most eight whose halves are
// several lights each is split only where the halves lie apart: its halves would each
// still need a node below, emptier ones, and neighbouring triangles of one surface gain
// nothing from the finer lanes. Split down to the last free lane, the glowing sphere of
// docs/accuracy.md took 32,994 nodes, 21,157 so (before clusters ended the descent a
// level above most of its triangles).
TEST(LightTree, ANodeOverManyLightsSplitsALaneOverAFewOnlyWhereItsHalvesLieApart)
{
    const test::GlowingSphere sphere = test::glowing_sphere(40, 40, {1.0, 2.0, 3.0}, 1.0, 0.6, 0.45);
    const LightTree tree = build_light_tree(sphere.lights);
    int pairs = 0;
    for (std::size_t i = 0; i < tree.nodes.size(); ++i) {
        const LightTreeNode& node = tree.nodes[i];
        const auto count = lights_per_lane(tree, node);
        std::size_t total = 0;
        for (std::size_t c : count)
            total += c;
        if (total <= LIGHT_TREE_WIDTH)
            continue;
        for (int a = 0; a < LIGHT_TREE_WIDTH; ++a)
            for (int b = a + 1; b < LIGHT_TREE_WIDTH; ++b) {
                const auto ca = count[static_cast<std::size_t>(a)], cb = count[static_cast<std::size_t>(b)];
                if (ca == 0 || cb == 0 || !binary_halves(node, a, b))
                    continue;
                ++pairs;
                // Touching triangles: a split lane was over more than eight, or a half is one light.
                EXPECT_TRUE(ca + cb > LIGHT_TREE_WIDTH || ca == 1 || cb == 1)
                    << "node " << i << " (" << total << " lights), lanes " << a << " and " << b << ": " << ca << " and "
                    << cb << " lights";
            }
    }
    EXPECT_GT(pairs, 100);

    // Points apart from each other, sixteen on a 4 x 4 grid: they take all eight lanes of
    // the root, where lanes split only while over more than eight would leave it two.
    std::vector<LightBounds> grid(16);
    for (std::size_t i = 0; i < grid.size(); ++i) {
        grid[i].lo = grid[i].hi = glm::dvec3(static_cast<double>(i % 4), 0.0, static_cast<double>(i / 4));
        grid[i].phi = 1.0;
        grid[i].cone = {{0.0, 0.0, 1.0}, -1.0, 0.0};
    }
    const LightTree spread = build_light_tree(grid);
    for (std::size_t c : lights_per_lane(spread, spread.nodes[0]))
        EXPECT_GT(c, 0u);
}

// The cluster leaves of a tree: each lane's node and lane, and the lights it stands for.
struct ClusterLane {
    std::size_t node;
    int lane;
    pcl_int header; // in tree.cluster
    std::vector<std::size_t> lights;
};

std::vector<ClusterLane> cluster_lanes(const LightTree& tree)
{
    std::vector<ClusterLane> out;
    for (std::size_t i = 0; i < tree.nodes.size(); ++i)
        for (int k = 0; k < LIGHT_TREE_WIDTH; ++k) {
            const pcl_int child = tree.nodes[i].child.s[k];
            if (tree.nodes[i].phi.s[k] > 0.0f && child < 0 && ((-1 - child) & LIGHT_TREE_CLUSTER))
                out.push_back({i, k, LIGHT_TREE_LEAF_INDEX(-1 - child), leaf_lights(tree, child)});
        }
    return out;
}

// In a node over many lights, a lane over neighbouring triangles of one surface that face
// nearly one way ends the descent: a cluster of up to LIGHT_TREE_CLUSTER_MAX, whose lights
// the kernel picks among by power (stored in the order of the lights' indices, each with
// its probability and its slot of an alias table that realizes it). Lamps apart, or
// triangles that face different ways, stay lanes of their own.
TEST(LightTree, NeighbouringTrianglesFacingOneWayEndTheDescentAsAClusterPickedByPower)
{
    // 40 x 40: neighbouring quads 4.5 and 9 degrees apart; 120 x 120, 1.5 and 3 degrees.
    for (const int stacks : {40, 120}) {
        const test::GlowingSphere sphere = test::glowing_sphere(stacks, stacks, {1.0, 2.0, 3.0}, 1.0, 0.6, 0.45);
        const LightTree tree = build_light_tree(sphere.lights);
        const std::vector<ClusterLane> clusters = cluster_lanes(tree);
        std::size_t clustered = 0, largest = 0;
        for (const ClusterLane& c : clusters) {
            const Lane lane = lane_of(tree.nodes[c.node], c.lane);
            EXPECT_GE(c.lights.size(), 4u) << "node " << c.node << " lane " << c.lane; // two halves of two or more
            EXPECT_LE(c.lights.size(), std::size_t(LIGHT_TREE_CLUSTER_MAX));
            EXPECT_GE(lane.cone.cos_o, std::cos(0.25) - 1e-6) << "node " << c.node << " lane " << c.lane;
            const std::size_t count = c.lights.size();
            double phi = 0.0;
            for (std::size_t l : c.lights)
                phi += sphere.lights[l].phi;
            // Each light's share of the alias slots: its own slot's keep and what other
            // slots give it, each slot 1 / count.
            std::vector<double> realized(count, 0.0);
            for (std::size_t i = 0; i < count; ++i) {
                const LightTreeClusterLight& e = tree.cluster.at(static_cast<std::size_t>(c.header) + 1 + i);
                ASSERT_GE(e.alias, 0);
                ASSERT_LT(static_cast<std::size_t>(e.alias), count) << "cluster " << c.header;
                EXPECT_GE(e.keep, 0.0f);
                EXPECT_LE(e.keep, 1.0f);
                realized[i] += e.keep / static_cast<double>(count);
                realized[static_cast<std::size_t>(e.alias)] += (1.0 - e.keep) / static_cast<double>(count);
            }
            for (std::size_t i = 0; i < count; ++i) {
                const std::size_t l = c.lights[i];
                const LightTreeClusterLight& e = tree.cluster.at(static_cast<std::size_t>(c.header) + 1 + i);
                EXPECT_TRUE(i == 0 || c.lights[i - 1] < l) << "cluster " << c.header << ": lights out of order";
                const double share = sphere.lights[l].phi / phi;
                EXPECT_NEAR(e.pmf, share, 1e-6 * share)
                    << "cluster " << c.header << ", light " << l << ": not by power";
                EXPECT_NEAR(realized[i], e.pmf, 2e-7 * share)
                    << "cluster " << c.header << ", light " << l << ": the alias slots give another probability";
                EXPECT_GE(glm::dot(lane.cone.axis, sphere.normal[l]), lane.cone.cos_o - 1e-6) << "light " << l;
            }
            EXPECT_NEAR(lane.phi, phi, 1e-5 * phi) << "node " << c.node << " lane " << c.lane;
            clustered += c.lights.size();
            largest = std::max(largest, c.lights.size());
        }
        EXPECT_EQ(clustered + clusters.size(), tree.cluster.size()) << "a header and the lights of each cluster";
        EXPECT_GT(clustered, sphere.lights.size() / 2) << "most of a fine sphere's triangles end in clusters";
        if (stacks == 120) {
            EXPECT_GT(largest, std::size_t(LIGHT_TREE_WIDTH)) << "clusters are not capped at a node's width";
        }
    }

    // A coarse sphere (24 triangles): neighbouring quads face 45 degrees apart or more.
    EXPECT_TRUE(cluster_lanes(build_light_tree(test::glowing_sphere(4, 4, {0.0, 0.0, 0.0}, 1.0).lights)).empty());
    // Small flat lamps on a grid, two triangles each, apart from each other.
    std::vector<LightBounds> lamps;
    for (int i = 0; i < 64; ++i)
        for (int t = 0; t < 2; ++t) {
            LightBounds b;
            b.lo = {static_cast<double>(i % 8), 3.0, static_cast<double>(i / 8)};
            b.hi = b.lo + glm::dvec3(0.1, 0.0, 0.1);
            b.phi = 1.0;
            b.cone = {{0.0, -1.0, 0.0}, 1.0, 0.0};
            lamps.push_back(b);
        }
    EXPECT_TRUE(cluster_lanes(build_light_tree(lamps)).empty());
}

// A cluster of more than eight lights is small beside all of them: on a flat panel of
// 64 x 64 quads (its triangles' cones all one direction), clusters of more than eight
// span at most a sixteenth of the panel's diagonal, so that from a point close to the
// panel the descent still leads to the part near it. Without the bound the panel's
// 8,192 triangles took clusters of up to LIGHT_TREE_CLUSTER_MAX.
TEST(LightTree, AClusterOfMoreThanEightLightsIsSmallBesideThemAll)
{
    std::vector<LightBounds> panel;
    const int quads = 64;
    for (int i = 0; i < quads * quads; ++i)
        for (int t = 0; t < 2; ++t) {
            LightBounds b;
            b.lo = {static_cast<double>(i % quads) / quads, 2.0, static_cast<double>(i / quads) / quads};
            b.hi = b.lo + glm::dvec3(1.0 / quads, 0.0, 1.0 / quads);
            b.phi = 1.0;
            b.cone = {{0.0, -1.0, 0.0}, 1.0, 0.0};
            panel.push_back(b);
        }
    const LightTree tree = build_light_tree(panel);
    std::size_t large = 0;
    for (const ClusterLane& c : cluster_lanes(tree)) {
        if (c.lights.size() <= std::size_t(LIGHT_TREE_WIDTH))
            continue;
        ++large;
        glm::dvec3 lo(INFINITY), hi(-INFINITY);
        for (std::size_t l : c.lights) {
            lo = glm::min(lo, panel[l].lo);
            hi = glm::max(hi, panel[l].hi);
        }
        EXPECT_LE(glm::length(hi - lo), std::sqrt(2.0) / 16.0 + 1e-12) << "cluster " << c.header;
    }
    EXPECT_GT(large, 0u) << "no cluster of more than eight to test";
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
    EXPECT_GE(tree.nodes.size(), 2u);
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

Light point_light(float x, float y, float z)
{
    Light l{};
    l.type = LIGHT_POINT;
    l.data.point.position = {x, y, z, 0.0f};
    return l;
}

// The tree over light records (what a compiled scene has) is the one over the bounds
// those records have: points, spheres, triangles and a directional light, in one list.
TEST(LightTree, LightRecordsGiveTheTreeTheirBoundsGive)
{
    std::mt19937 rng(17);
    std::uniform_real_distribution<float> position(-10.0f, 10.0f), size(0.01f, 1.0f);
    std::vector<Light> lights;
    std::vector<double> power;
    std::vector<LightBounds> bounds;
    for (int i = 0; i < 300; ++i) {
        const float x = position(rng), y = position(rng), z = position(rng), s = size(rng);
        LightBounds b;
        b.phi = static_cast<double>(s) * 3.0;
        Light l{};
        if (i % 3 == 0) {
            l = point_light(x, y, z);
            b.lo = b.hi = glm::dvec3(x, y, z);
        } else if (i % 3 == 1) {
            l.type = LIGHT_SPHERE;
            l.data.sphere.centre = {x, y, z, 0.0f};
            l.data.sphere.radius = s;
            b.lo = glm::dvec3(x, y, z) - glm::dvec3(s);
            b.hi = glm::dvec3(x, y, z) + glm::dvec3(s);
        } else {
            // In a plane of z, facing +z or -z by its winding: the normal needs no rounding.
            l.type = LIGHT_TRIANGLE;
            const float turn = i % 2 ? s : -s;
            l.data.triangle.v0 = {x, y, z, 0.0f};
            l.data.triangle.v1 = {x + s, y, z, 0.0f};
            l.data.triangle.v2 = {x, y + turn, z, 0.0f};
            b.lo = glm::dvec3(x, std::min(y, y + turn), z);
            b.hi = glm::dvec3(x + s, std::max(y, y + turn), z);
            b.cone = {{0.0, 0.0, turn > 0.0f ? 1.0 : -1.0}, 1.0, 0.0};
        }
        lights.push_back(l);
        power.push_back(b.phi);
        bounds.push_back(b);
    }
    Light sun{};
    sun.type = LIGHT_DIRECTIONAL;
    sun.data.directional.direction = {0.0f, -1.0f, 0.0f, 0.0f};
    lights.insert(lights.begin() + 7, sun);
    power.insert(power.begin() + 7, 40.0);
    LightBounds infinite;
    infinite.infinite = true;
    infinite.phi = 40.0;
    bounds.insert(bounds.begin() + 7, infinite);

    const LightTree from_records = build_light_tree(lights, power), from_bounds = build_light_tree(bounds);
    ASSERT_EQ(from_records.nodes.size(), from_bounds.nodes.size());
    ASSERT_GT(from_records.nodes.size(), 1u);
    EXPECT_EQ(std::memcmp(from_records.nodes.data(), from_bounds.nodes.data(),
                          from_records.nodes.size() * sizeof(LightTreeNode)),
              0);
    EXPECT_EQ(from_records.trails, from_bounds.trails);
    EXPECT_EQ(from_records.infinite, std::vector<pcl_int>{7});
    EXPECT_EQ(from_records.infinite_pick, from_bounds.infinite_pick);
    EXPECT_EQ(from_records.depth, from_bounds.depth);
}

// The light named is the light's own index, not its place among the lights with a
// position (the directional light before it has none).
TEST(LightTree, ALightRecordWhosePositionIsNotFiniteIsRefusedByItsIndex)
{
    std::vector<Light> lights;
    for (int i = 0; i < 6; ++i)
        lights.push_back(point_light(static_cast<float>(i), 0.0f, 1.0f));
    lights[1].type = LIGHT_DIRECTIONAL;
    lights[1].data.directional.direction = {0.0f, -1.0f, 0.0f, 0.0f};
    lights[4].data.point.position.y = NAN;
    const std::vector<double> power(lights.size(), 1.0);
    try {
        build_light_tree(lights, power);
        ADD_FAILURE() << "no error";
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()), "light 4 has bounds or power that are not finite");
    }
}

// A floor of 10 x 10 with `lamps` emissive quads spaced `spacing` apart along x.
Scene lamps_on_a_floor(int lamps, float spacing)
{
    test::GltfBuilder b;
    const int grey = b.add_material(glm::vec3(0.5f));
    b.add_root(b.add_node(b.add_quad_mesh({{-5, 0, -5}, {-5, 0, 5}, {5, 0, 5}, {5, 0, -5}}, grey)));
    const int lamp = b.add_material(glm::vec3(0.0f), glm::vec3(5.0f));
    for (int i = 0; i < lamps; ++i) {
        const float x = -4.0f + spacing * static_cast<float>(i);
        b.add_root(b.add_node(b.add_quad_mesh({{x, 2, 0}, {x + 0.1f, 2, 0}, {x + 0.1f, 2, 0.1f}, {x, 2, 0.1f}}, lamp)));
    }
    b.add_camera_node(b.add_perspective_camera(1.0), {0.0, 1.0, 6.0});
    return import_gltf(b.model, "lamps-on-a-floor");
}

TEST(LightTree, AutoTakesTheTreeWhereLightsAreManyAndSpread)
{
    RenderOptions o; // light_sampler Auto by default
    EXPECT_EQ(o.light_sampler, LightSampler::Auto);
    EXPECT_EQ(resolve_light_sampler(load_gltf(std::string(PATHCL_SOURCE_DIR) + "/scenes/cornell-box.gltf"), o),
              LightSampler::Power)
        << "one area light";
    EXPECT_EQ(resolve_light_sampler(lamps_on_a_floor(3, 3.5f), o), LightSampler::Tree) << "three lamps 7 apart";
    EXPECT_EQ(resolve_light_sampler(lamps_on_a_floor(3, 0.2f), o), LightSampler::Power) << "three lamps together";
    EXPECT_EQ(resolve_light_sampler(lamps_on_a_floor(1, 1.0f), o), LightSampler::Power) << "one lamp (two triangles)";
    RenderOptions wavefront = o;
    wavefront.integrator = Integrator::Wavefront;
    EXPECT_EQ(resolve_light_sampler(lamps_on_a_floor(3, 3.5f), wavefront), LightSampler::Power) << "no tree there";
    for (LightSampler asked : {LightSampler::Power, LightSampler::Tree, LightSampler::Uniform}) {
        RenderOptions explicit_choice = o;
        explicit_choice.light_sampler = asked;
        EXPECT_EQ(resolve_light_sampler(lamps_on_a_floor(3, 0.2f), explicit_choice), asked);
    }
}

} // namespace
} // namespace pathcl::test_light_tree
