#include "compile/light_tree.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <exception>
#include <numbers>
#include <thread>

#include <glm/geometric.hpp>

#include "common/error.h"

namespace pathcl {
namespace {

constexpr double kPi = std::numbers::pi;

// The trail an infinite light gets: no tree node's (kernels/light/light_tree.cl).
constexpr pcl_ulong kLightTreeInfiniteTrail = ~pcl_ulong(0);

// A little wider than the exact cone of a spot, so that float rounding on the device can
// never put a point the light reaches outside it (where the importance is 0).
constexpr double kConeSlack = 1e-3;

glm::dvec3 xyz(const pcl_float4& v)
{
    return {v.x, v.y, v.z};
}

double angle_between(const glm::dvec3& a, const glm::dvec3& b)
{
    // Accurate for nearly parallel and nearly opposite unit vectors alike.
    const double d = glm::dot(a, b);
    return d < 0.0 ? kPi - 2.0 * std::asin(std::min(1.0, glm::length(a + b) / 2.0))
                   : 2.0 * std::asin(std::min(1.0, glm::length(a - b) / 2.0));
}

LightCone whole_sphere(double cos_e)
{
    return {{0.0, 0.0, 1.0}, -1.0, cos_e};
}

// A LightCone with its angles and sine, computed once: the build unites and weighs cones
// millions of times.
struct Cone {
    glm::dvec3 axis{0.0, 0.0, 1.0};
    double cos_o = -1.0, sin_o = 0.0, theta_o = std::numbers::pi;
    double cos_e = 0.0, theta_e = std::numbers::pi / 2;
    Cone() = default;
    explicit Cone(const LightCone& c)
        : axis(c.axis), cos_o(std::clamp(c.cos_o, -1.0, 1.0)), sin_o(std::sqrt(1.0 - cos_o * cos_o)),
          theta_o(std::acos(cos_o)), cos_e(std::clamp(c.cos_e, -1.0, 1.0)), theta_e(std::acos(cos_e))
    {}
    Cone(const glm::dvec3& a, double theta, const Cone& spread)
        : axis(a), cos_o(std::cos(theta)), sin_o(std::sin(theta)), theta_o(theta), cos_e(spread.cos_e),
          theta_e(spread.theta_e)
    {}
    LightCone light_cone() const { return {axis, cos_o, cos_e}; }
};

// The smaller emission spread of the two (the wider theta_e).
const Cone& wider_spread(const Cone& a, const Cone& b)
{
    return a.cos_e <= b.cos_e ? a : b;
}

Cone with_spread(Cone c, const Cone& spread)
{
    c.cos_e = spread.cos_e;
    c.theta_e = spread.theta_e;
    return c;
}

// The smallest cone (up to the method's slack) that holds both: cone_union's arithmetic.
Cone unite(const Cone& a, const Cone& b)
{
    const Cone& spread = wider_spread(a, b);
    if (a.cos_o <= -1.0 || b.cos_o <= -1.0)
        return with_spread(Cone(), spread);
    // Most unions while building hold one cone inside the other: told apart by cosines,
    // a margin on the safe side, before any angle is computed.
    const double cos_d = glm::dot(a.axis, b.axis);
    const double cos_difference = a.cos_o * b.cos_o + a.sin_o * b.sin_o; // cos(theta_a - theta_b)
    constexpr double margin = 1e-12;
    if (a.cos_o <= b.cos_o && cos_d >= cos_difference + margin)
        return with_spread(a, spread); // theta_d + theta_b < theta_a
    if (b.cos_o <= a.cos_o && cos_d >= cos_difference + margin)
        return with_spread(b, spread);
    const double theta_d = angle_between(a.axis, b.axis);
    if (std::min(theta_d + b.theta_o, kPi) <= a.theta_o)
        return with_spread(a, spread);
    if (std::min(theta_d + a.theta_o, kPi) <= b.theta_o)
        return with_spread(b, spread);
    // The cone that just holds both: half-angle (theta_a + theta_d + theta_b) / 2, its axis
    // turned from a's towards b's.
    const double theta_o = (a.theta_o + theta_d + b.theta_o) / 2.0;
    if (theta_o >= kPi)
        return with_spread(Cone(), spread);
    const glm::dvec3 w = glm::cross(a.axis, b.axis);
    const double w_len = glm::length(w);
    if (!(w_len > 1e-12))
        return with_spread(Cone(), spread);
    const glm::dvec3 k = w / w_len;
    const double turn = theta_o - a.theta_o;
    // Rodrigues: a.axis (orthogonal to k) turned by `turn` about k.
    const glm::dvec3 axis = a.axis * std::cos(turn) + glm::cross(k, a.axis) * std::sin(turn);
    return Cone(glm::normalize(axis), theta_o, spread);
}

// A box: two corners. The empty box has lo > hi.
struct Box {
    glm::dvec3 lo{INFINITY}, hi{-INFINITY};
    void extend(const glm::dvec3& l, const glm::dvec3& h)
    {
        lo = glm::min(lo, l);
        hi = glm::max(hi, h);
    }
    double area() const
    {
        const glm::dvec3 d = glm::max(hi - lo, glm::dvec3(0.0));
        return 2.0 * (d.x * d.y + d.y * d.z + d.z * d.x);
    }
};

// A node's bounds while building: box, power, cone (and whether any light is two-sided).
struct Bounds {
    Box box;
    double phi = 0.0;
    Cone cone;
    bool any = false;
    bool two_sided = false;
    // A light of bounds b and cone c.
    void extend(const LightBounds& b, const Cone& c)
    {
        box.extend(b.lo, b.hi);
        phi += b.phi;
        cone = any ? unite(cone, c) : c;
        two_sided = two_sided || b.two_sided;
        any = true;
    }
    void extend(const Bounds& b)
    {
        if (!b.any)
            return;
        box.extend(b.box.lo, b.box.hi);
        phi += b.phi;
        cone = any ? unite(cone, b.cone) : b.cone;
        two_sided = two_sided || b.two_sided;
        any = true;
    }
};

// The orientation measure of a cone of normals theta_o wide emitting theta_e past it (the
// paper's M_Omega): the solid angle its directions sweep, weighted by their cosine.
double orientation_measure(const Cone& c)
{
    const double theta_w = std::min(c.theta_o + c.theta_e, kPi);
    return 2.0 * kPi * (1.0 - c.cos_o) +
           kPi / 2.0 *
               (2.0 * theta_w * c.sin_o - std::cos(c.theta_o - 2.0 * theta_w) - 2.0 * c.theta_o * c.sin_o + c.cos_o);
}

double saoh_cost(const Bounds& b)
{
    return b.any ? b.phi * orientation_measure(b.cone) * b.box.area() : 0.0;
}

constexpr int kBuckets = 12;
// Past this depth, splits are in the middle by count, which halves what is left: no tree
// of fewer than 2^32 lights is deeper than 62, so every light's path fits one bit a level
// in 64.
constexpr std::uint32_t kMedianDepth = 30;
// Subtrees of more lights than this are built on a thread of their own (two cores halve
// the build of a large tree).
constexpr std::size_t kParallelLights = 4096;

// A node of the binary tree the eight-wide one is collapsed from; the nodes of a subtree
// built apart are appended with their indices shifted.
struct BinaryNode {
    Bounds bounds;
    std::uint32_t first = 0, second = 0; // the children
    std::int64_t light = -1;             // a leaf's light
    std::uint32_t lights = 1;            // below it
};

class Builder {
public:
    Builder(const std::vector<LightBounds>& lights, std::vector<pcl_ulong>& trails) : lights_(lights), trails_(trails)
    {
        cones_.reserve(lights.size());
        centroids_.reserve(lights.size());
        for (const LightBounds& b : lights) {
            cones_.emplace_back(b.cone);
            centroids_.push_back((b.lo + b.hi) * 0.5);
        }
    }

    // Builds the subtree over order[begin, end), reached from the root by `trail` (bit k:
    // the child taken at depth k) at `depth`, into `nodes`; returns its node.
    std::uint32_t build(std::vector<BinaryNode>& nodes, std::vector<std::uint32_t>& order, std::size_t begin,
                        std::size_t end, std::uint32_t depth, pcl_ulong trail)
    {
        const auto index = static_cast<std::uint32_t>(nodes.size());
        nodes.emplace_back();
        if (end - begin == 1) {
            nodes[index].light = order[begin];
            nodes[index].bounds.extend(lights_[order[begin]], cones_[order[begin]]);
            trails_[order[begin]] = trail;
            return index;
        }
        const std::size_t mid = split(order, begin, end, depth);
        const pcl_ulong second_trail = trail | (pcl_ulong(1) << depth);
        std::uint32_t first = 0, second = 0;
        if (end - begin > kParallelLights && depth < 2) {
            // The second subtree on another thread, into nodes of its own.
            std::vector<BinaryNode> apart;
            std::exception_ptr failure;
            std::thread worker([&] {
                try {
                    build(apart, order, mid, end, depth + 1, second_trail);
                } catch (...) {
                    failure = std::current_exception();
                }
            });
            first = build(nodes, order, begin, mid, depth + 1, trail);
            worker.join();
            if (failure)
                std::rethrow_exception(failure);
            second = static_cast<std::uint32_t>(nodes.size());
            for (BinaryNode n : apart) {
                if (n.light < 0) {
                    n.first += second;
                    n.second += second;
                }
                nodes.push_back(n);
            }
        } else {
            first = build(nodes, order, begin, mid, depth + 1, trail);
            second = build(nodes, order, mid, end, depth + 1, second_trail);
        }
        Bounds b = nodes[first].bounds;
        b.extend(nodes[second].bounds);
        nodes[index].bounds = b;
        nodes[index].first = first;
        nodes[index].second = second;
        nodes[index].lights = nodes[first].lights + nodes[second].lights;
        return index;
    }

private:
    const glm::dvec3& centroid(std::uint32_t light) const { return centroids_[light]; }

    // Partitions order[begin, end) and returns where the second child starts.
    std::size_t split(std::vector<std::uint32_t>& order, std::size_t begin, std::size_t end, std::uint32_t depth)
    {
        Box centroids;
        for (std::size_t i = begin; i < end; ++i) {
            const glm::dvec3 c = centroid(order[i]);
            centroids.extend(c, c);
        }
        const glm::dvec3 extent = centroids.hi - centroids.lo;
        double best_cost = INFINITY;
        int best_axis = -1, best_bucket = 0;
        // Binned along the centroids' longest axis only: a third of the work of trying all
        // three, which the build's speed needs.
        int axis = 0;
        for (int a = 1; a < 3; ++a)
            if (extent[a] > extent[axis])
                axis = a;
        if (depth < kMedianDepth && extent[axis] > 0.0) {
            std::array<Bounds, kBuckets> buckets = bin(order, begin, end, axis, centroids, extent);
            // Costs of splitting after bucket k: a sweep from each side.
            std::array<double, kBuckets - 1> cost{};
            Bounds below;
            for (int k = 0; k < kBuckets - 1; ++k) {
                below.extend(buckets[k]);
                cost[k] = saoh_cost(below);
            }
            Bounds above;
            for (int k = kBuckets - 1; k > 0; --k) {
                above.extend(buckets[k]);
                cost[k - 1] += saoh_cost(above);
            }
            for (int k = 0; k < kBuckets - 1; ++k) {
                if (cost[k] < best_cost) {
                    best_cost = cost[k];
                    best_axis = axis;
                    best_bucket = k;
                }
            }
        }
        std::size_t mid = begin;
        if (best_axis >= 0) {
            auto first = order.begin() + static_cast<std::ptrdiff_t>(begin);
            auto last = order.begin() + static_cast<std::ptrdiff_t>(end);
            mid = static_cast<std::size_t>(std::partition(first, last,
                                                          [&](std::uint32_t l) {
                                                              return bucket_of(l, best_axis, centroids, extent) <=
                                                                     best_bucket;
                                                          }) -
                                           order.begin());
        }
        if (mid == begin || mid == end) { // no split of the centroids: halves by count, along the widest axis
            mid = begin + (end - begin) / 2;
            std::nth_element(order.begin() + static_cast<std::ptrdiff_t>(begin),
                             order.begin() + static_cast<std::ptrdiff_t>(mid),
                             order.begin() + static_cast<std::ptrdiff_t>(end),
                             [&](std::uint32_t a, std::uint32_t b) { return centroid(a)[axis] < centroid(b)[axis]; });
        }
        return mid;
    }

    // The lights of order[begin, end) in kBuckets buckets along `axis`: each bucket's box,
    // power and cone. A bucket's cone is the one around its lights' mean axis that holds
    // all of their cones: two passes of dot products and square roots, where uniting the
    // lights' cones one by one would take their angles.
    std::array<Bounds, kBuckets> bin(const std::vector<std::uint32_t>& order, std::size_t begin, std::size_t end,
                                     int axis, const Box& centroids, const glm::dvec3& extent) const
    {
        std::array<Bounds, kBuckets> buckets;
        std::array<glm::dvec3, kBuckets> axes{};
        std::array<const Cone*, kBuckets> spread{};
        for (std::size_t i = begin; i < end; ++i) {
            const std::uint32_t l = order[i];
            const int k = bucket_of(l, axis, centroids, extent);
            Bounds& b = buckets[k];
            b.box.extend(lights_[l].lo, lights_[l].hi);
            b.phi += lights_[l].phi;
            b.two_sided = b.two_sided || lights_[l].two_sided;
            b.any = true;
            axes[k] += cones_[l].axis;
            if (!spread[k] || cones_[l].cos_e < spread[k]->cos_e)
                spread[k] = &cones_[l];
        }
        std::array<double, kBuckets> cos_o;
        std::array<glm::dvec3, kBuckets> mean;
        for (int k = 0; k < kBuckets; ++k) {
            const double len = glm::length(axes[k]);
            mean[k] = len > 1e-9 ? axes[k] / len : glm::dvec3(0.0, 0.0, 1.0);
            cos_o[k] = len > 1e-9 ? 1.0 : -1.0;
        }
        for (std::size_t i = begin; i < end; ++i) {
            const std::uint32_t l = order[i];
            const int k = bucket_of(l, axis, centroids, extent);
            const Cone& c = cones_[l];
            if (cos_o[k] <= -1.0)
                continue;
            // cos(theta_d + theta_l): the farthest direction of the light's cone from the mean.
            const double cos_d = std::clamp(glm::dot(mean[k], c.axis), -1.0, 1.0);
            if (c.cos_o <= -1.0 || cos_d < -c.cos_o) { // theta_d + theta_l > pi
                cos_o[k] = -1.0;
                continue;
            }
            const double sin_d = std::sqrt(1.0 - cos_d * cos_d);
            cos_o[k] = std::min(cos_o[k], cos_d * c.cos_o - sin_d * c.sin_o);
        }
        for (int k = 0; k < kBuckets; ++k) {
            if (!buckets[k].any)
                continue;
            const double cos_k = std::max(-1.0, cos_o[k] - 1e-12); // rounding, on the safe side
            buckets[k].cone =
                with_spread(cos_k <= -1.0 ? Cone() : Cone(mean[k], std::acos(cos_k), *spread[k]), *spread[k]);
        }
        return buckets;
    }

    int bucket_of(std::uint32_t light, int axis, const Box& centroids, const glm::dvec3& extent) const
    {
        const double scale = kBuckets / extent[axis]; // hoisted out of the callers' loops by inlining
        return std::clamp(static_cast<int>((centroid(light)[axis] - centroids.lo[axis]) * scale), 0, kBuckets - 1);
    }

    const std::vector<LightBounds>& lights_;
    std::vector<Cone> cones_;
    std::vector<glm::dvec3> centroids_;
    std::vector<pcl_ulong>& trails_;
};

// x as a float no greater, and no smaller: a node's float bounds must hold every light
// they stand for (a sphere a little larger, a cone a little wider), or the device could
// judge a light unable to reach a point it reaches.
float float_down(double x)
{
    const float f = static_cast<float>(x);
    return static_cast<double>(f) > x ? std::nextafter(f, -INFINITY) : f;
}

float float_up(double x)
{
    const float f = static_cast<float>(x);
    return static_cast<double>(f) < x ? std::nextafter(f, INFINITY) : f;
}

// The eight-wide tree from the binary one. A node's lanes are binary descendants of the
// binary node it stands for: starting from its two children, the lane over the most
// lights is replaced by its two children until there are eight or only leaves. Each lane
// keeps its code, the bits of the binary path from the node down to it (LIGHT_TREE_CODE),
// by which a light's binary trail leads through the eight-wide nodes.
class Collapser {
public:
    Collapser(const std::vector<BinaryNode>& binary, LightTree& tree) : binary_(binary), tree_(tree) {}

    // Writes the eight-wide node for binary node b at `depth` and everything below it;
    // returns its index.
    std::uint32_t node(std::uint32_t b, std::uint32_t depth)
    {
        struct Lane {
            std::uint32_t binary, bits, length;
        };
        std::vector<Lane> lanes;
        if (binary_[b].light >= 0) {
            lanes.push_back({b, 0, 0}); // a tree of one light
        } else {
            lanes = {{binary_[b].first, 0, 1}, {binary_[b].second, 1, 1}};
            while (lanes.size() < LIGHT_TREE_WIDTH) {
                std::size_t widest = lanes.size();
                for (std::size_t k = 0; k < lanes.size(); ++k)
                    if (binary_[lanes[k].binary].light < 0 &&
                        (widest == lanes.size() ||
                         binary_[lanes[k].binary].lights > binary_[lanes[widest].binary].lights))
                        widest = k;
                if (widest == lanes.size())
                    break;
                const Lane w = lanes[widest];
                const BinaryNode& n = binary_[w.binary];
                lanes[widest] = {n.first, w.bits, w.length + 1};
                lanes.push_back({n.second, w.bits | (1u << w.length), w.length + 1});
            }
        }
        const auto index = static_cast<std::uint32_t>(tree_.nodes.size());
        tree_.nodes.emplace_back();
        tree_.depth = std::max(tree_.depth, depth + 1);
        for (std::size_t k = 0; k < lanes.size(); ++k) {
            const BinaryNode& n = binary_[lanes[k].binary];
            set_lane(index, k, n.bounds);
            tree_.nodes[index].code.s[k] = static_cast<pcl_int>(lanes[k].bits | (lanes[k].length << 8));
            const pcl_int child = n.light >= 0 ? -1 - static_cast<pcl_int>(n.light)
                                               : static_cast<pcl_int>(node(lanes[k].binary, depth + 1));
            tree_.nodes[index].child.s[k] = child;
        }
        return index;
    }

private:
    void set_lane(std::uint32_t index, std::size_t k, const Bounds& b)
    {
        LightTreeNode& node = tree_.nodes[index];
        const glm::dvec3 centre = (b.box.lo + b.box.hi) * 0.5;
        const glm::vec3 c(centre);
        double radius2 = 0.0; // of the sphere around the float centre that holds the box
        for (int corner = 0; corner < 8; ++corner) {
            const glm::dvec3 p((corner & 1) ? b.box.hi.x : b.box.lo.x, (corner & 2) ? b.box.hi.y : b.box.lo.y,
                               (corner & 4) ? b.box.hi.z : b.box.lo.z);
            const glm::dvec3 d = p - glm::dvec3(c);
            radius2 = std::max(radius2, glm::dot(d, d));
        }
        node.centre_x.s[k] = c.x;
        node.centre_y.s[k] = c.y;
        node.centre_z.s[k] = c.z;
        node.radius2.s[k] = float_up(radius2);
        node.phi.s[k] = static_cast<float>(b.phi);
        node.axis_x.s[k] = static_cast<float>(b.cone.axis.x);
        node.axis_y.s[k] = static_cast<float>(b.cone.axis.y);
        node.axis_z.s[k] = static_cast<float>(b.cone.axis.z);
        const float cos_o = float_down(b.cone.cos_o);
        node.cos_o.s[k] = cos_o;
        node.sin_o.s[k] = float_up(std::sqrt(std::max(0.0, 1.0 - double(cos_o) * double(cos_o))));
        node.cos_e.s[k] = float_down(b.cone.cos_e);
        node.two_sided.s[k] = b.two_sided ? -1 : 0;
    }

    const std::vector<BinaryNode>& binary_;
    LightTree& tree_;
};

} // namespace

LightCone cone_union(const LightCone& a, const LightCone& b)
{
    return unite(Cone(a), Cone(b)).light_cone();
}

std::vector<LightBounds> light_bounds(const std::vector<Light>& lights, const std::vector<double>& power)
{
    std::vector<LightBounds> out(lights.size());
    for (std::size_t i = 0; i < lights.size(); ++i) {
        const Light& l = lights[i];
        LightBounds& b = out[i];
        b.phi = power[i];
        switch (l.type) {
        case LIGHT_TRIANGLE: {
            const glm::dvec3 v0 = xyz(l.data.triangle.v0), v1 = xyz(l.data.triangle.v1), v2 = xyz(l.data.triangle.v2);
            b.lo = glm::min(v0, glm::min(v1, v2));
            b.hi = glm::max(v0, glm::max(v1, v2));
            const glm::dvec3 n = glm::cross(v1 - v0, v2 - v0);
            const double len = glm::length(n);
            // Front face only, as a Lambertian emitter: every direction within pi/2 of the
            // normal. A degenerate triangle gets the whole sphere.
            b.cone = len > 0.0 ? LightCone{n / len, 1.0, 0.0} : whole_sphere(0.0);
            break;
        }
        case LIGHT_SPHERE: {
            const glm::dvec3 c = xyz(l.data.sphere.centre);
            const double r = l.data.sphere.radius;
            b.lo = c - glm::dvec3(r);
            b.hi = c + glm::dvec3(r);
            b.cone = whole_sphere(0.0);
            break;
        }
        case LIGHT_POINT:
            b.lo = b.hi = xyz(l.data.point.position);
            b.cone = whole_sphere(0.0);
            break;
        case LIGHT_SPOT: {
            b.lo = b.hi = xyz(l.data.spot.position);
            const double theta = std::acos(std::clamp(static_cast<double>(l.data.spot.cos_outer), -1.0, 1.0));
            b.cone = {glm::normalize(xyz(l.data.spot.axis)), std::cos(std::min(theta + kConeSlack, kPi)),
                      std::cos(kConeSlack)};
            break;
        }
        case LIGHT_RECT_SPOT: {
            b.lo = b.hi = xyz(l.data.rect_spot.position);
            const double th = l.data.rect_spot.tan_half_h, tv = l.data.rect_spot.tan_half_v;
            const double corner = std::atan(std::sqrt(th * th + tv * tv)); // the frustum's widest direction
            b.cone = {glm::normalize(xyz(l.data.rect_spot.axis)), std::cos(std::min(corner + kConeSlack, kPi)),
                      std::cos(kConeSlack)};
            break;
        }
        default: // LIGHT_DIRECTIONAL, LIGHT_ENVIRONMENT
            b.infinite = true;
            break;
        }
    }
    return out;
}

LightTree build_light_tree(const std::vector<LightBounds>& lights)
{
    LightTree tree;
    tree.trails.assign(lights.size(), 0);
    std::vector<std::uint32_t> order;
    double bounded_power = 0.0, infinite_power = 0.0;
    for (std::size_t i = 0; i < lights.size(); ++i) {
        const LightBounds& b = lights[i];
        if (b.infinite) {
            tree.infinite.push_back(static_cast<pcl_int>(i));
            tree.trails[i] = kLightTreeInfiniteTrail;
            infinite_power += b.phi;
            continue;
        }
        const bool finite = std::isfinite(b.phi) && std::isfinite(b.lo.x) && std::isfinite(b.lo.y) &&
                            std::isfinite(b.lo.z) && std::isfinite(b.hi.x) && std::isfinite(b.hi.y) &&
                            std::isfinite(b.hi.z);
        if (!finite)
            throw Error("light " + std::to_string(i) + " has bounds or power that are not finite");
        order.push_back(static_cast<std::uint32_t>(i));
        bounded_power += b.phi;
    }
    if (!tree.infinite.empty())
        tree.infinite_pick =
            order.empty()
                ? 1.0
                : (infinite_power + bounded_power > 0.0 ? infinite_power / (infinite_power + bounded_power) : 0.5);
    if (!order.empty()) {
        std::vector<BinaryNode> binary;
        binary.reserve(2 * order.size() - 1);
        Builder(lights, tree.trails).build(binary, order, 0, order.size(), 0, 0);
        Collapser(binary, tree).node(0, 0);
    }
    return tree;
}

LightSampler resolve_light_sampler(const Scene& scene, const RenderOptions& options)
{
    if (options.light_sampler != LightSampler::Auto)
        return options.light_sampler;
    if (options.integrator == Integrator::Wavefront)
        return LightSampler::Power;
    glm::dvec3 lo(INFINITY), hi(-INFINITY);
    std::size_t placed = 0;
    auto add = [&](const glm::dvec3& p) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
        ++placed;
    };
    for (const SceneTriangle& t : scene.triangles)
        if (scene.materials[static_cast<std::size_t>(t.material)].emits())
            for (const glm::vec3& v : t.v)
                add(glm::dvec3(v));
    std::size_t emitters = placed / 3;
    placed = emitters;
    for (const SceneLight& l : scene.lights)
        if (l.type != SceneLight::Type::Directional)
            add(l.position);
    if (placed < 3)
        return LightSampler::Power;
    glm::vec3 scene_lo, scene_hi;
    scene_bounds(scene, scene_lo, scene_hi);
    const double scene_diagonal = glm::length(glm::dvec3(scene_hi) - glm::dvec3(scene_lo));
    const double light_diagonal = glm::length(hi - lo);
    return light_diagonal >= 0.25 * scene_diagonal ? LightSampler::Tree : LightSampler::Power;
}

} // namespace pathcl
