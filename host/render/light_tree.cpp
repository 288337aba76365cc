#include "render/light_tree.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

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

// A node's bounds while building: box, power, cone (and whether every light is two-sided).
struct Bounds {
    Box box;
    double phi = 0.0;
    LightCone cone;
    bool any = false;
    bool two_sided = false;
    void extend(const LightBounds& b)
    {
        box.extend(b.lo, b.hi);
        phi += b.phi;
        cone = any ? cone_union(cone, b.cone) : b.cone;
        two_sided = any ? (two_sided || b.two_sided) : b.two_sided;
        any = true;
    }
    void extend(const Bounds& b)
    {
        if (!b.any)
            return;
        box.extend(b.box.lo, b.box.hi);
        phi += b.phi;
        cone = any ? cone_union(cone, b.cone) : b.cone;
        two_sided = any ? (two_sided || b.two_sided) : b.two_sided;
        any = true;
    }
};

// The orientation measure of a cone of normals theta_o wide emitting theta_e past it (the
// paper's M_Omega): the solid angle its directions sweep, weighted by their cosine.
double orientation_measure(const LightCone& c)
{
    const double theta_o = std::acos(std::clamp(c.cos_o, -1.0, 1.0));
    const double theta_e = std::acos(std::clamp(c.cos_e, -1.0, 1.0));
    const double theta_w = std::min(theta_o + theta_e, kPi);
    const double sin_o = std::sin(theta_o);
    return 2.0 * kPi * (1.0 - c.cos_o) +
           kPi / 2.0 * (2.0 * theta_w * sin_o - std::cos(theta_o - 2.0 * theta_w) - 2.0 * theta_o * sin_o + c.cos_o);
}

double saoh_cost(const Bounds& b)
{
    return b.any ? b.phi * orientation_measure(b.cone) * b.box.area() : 0.0;
}

// x as a float no greater, and no smaller: the node's float bounds must hold every light
// they stand for (a box a little larger, a cone a little wider), or the device could judge a
// light unable to reach a point it reaches.
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

LightTreeNode make_node(const Bounds& b)
{
    LightTreeNode n{};
    n.lo = {float_down(b.box.lo.x), float_down(b.box.lo.y), float_down(b.box.lo.z), static_cast<float>(b.phi)};
    n.hi = {float_up(b.box.hi.x), float_up(b.box.hi.y), float_up(b.box.hi.z), float_down(b.cone.cos_o)};
    n.axis = {static_cast<float>(b.cone.axis.x), static_cast<float>(b.cone.axis.y), static_cast<float>(b.cone.axis.z),
              float_down(b.cone.cos_e)};
    n.two_sided = b.two_sided ? 1 : 0;
    return n;
}

constexpr int kBuckets = 12;
// Past this depth, splits are in the middle by count, which halves what is left: no tree
// of fewer than 2^32 lights is deeper than 62, so every trail fits 64 bits.
constexpr std::uint32_t kMedianDepth = 30;

class Builder {
public:
    Builder(const std::vector<LightBounds>& lights, LightTree& tree) : lights_(lights), tree_(tree) {}

    // Builds the subtree over order[begin, end) at `depth`, reached by `trail`; returns its
    // bounds.
    Bounds build(std::vector<std::uint32_t>& order, std::size_t begin, std::size_t end, std::uint32_t depth,
                 pcl_ulong trail)
    {
        const std::size_t index = tree_.nodes.size();
        tree_.nodes.emplace_back();
        tree_.depth = std::max(tree_.depth, depth);
        if (end - begin == 1) {
            const std::uint32_t light = order[begin];
            Bounds b;
            b.extend(lights_[light]);
            tree_.nodes[index] = make_node(b);
            tree_.nodes[index].child = -1 - static_cast<pcl_int>(light);
            tree_.trails[light] = trail;
            return b;
        }
        const std::size_t mid = split(order, begin, end, depth);
        Bounds b = build(order, begin, mid, depth + 1, trail);
        const std::size_t second = tree_.nodes.size();
        b.extend(build(order, mid, end, depth + 1, trail | (pcl_ulong(1) << depth)));
        tree_.nodes[index] = make_node(b);
        tree_.nodes[index].child = static_cast<pcl_int>(second);
        return b;
    }

private:
    glm::dvec3 centroid(std::uint32_t light) const { return (lights_[light].lo + lights_[light].hi) * 0.5; }

    // Partitions order[begin, end) and returns where the second child starts.
    std::size_t split(std::vector<std::uint32_t>& order, std::size_t begin, std::size_t end, std::uint32_t depth)
    {
        Box centroids;
        Bounds all;
        for (std::size_t i = begin; i < end; ++i) {
            const glm::dvec3 c = centroid(order[i]);
            centroids.extend(c, c);
            all.box.extend(lights_[order[i]].lo, lights_[order[i]].hi);
        }
        const glm::dvec3 extent = centroids.hi - centroids.lo;
        const glm::dvec3 box_extent = all.box.hi - all.box.lo;
        const double max_extent = std::max({box_extent.x, box_extent.y, box_extent.z});
        double best_cost = INFINITY;
        int best_axis = -1, best_bucket = 0;
        if (depth < kMedianDepth) {
            for (int axis = 0; axis < 3; ++axis) {
                if (!(extent[axis] > 0.0))
                    continue;
                std::array<Bounds, kBuckets> buckets;
                for (std::size_t i = begin; i < end; ++i)
                    buckets[bucket_of(order[i], axis, centroids, extent)].extend(lights_[order[i]]);
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
                // The paper's regularizer: splits across a thin box's long side are preferred.
                const double thinness = box_extent[axis] > 0.0 ? max_extent / box_extent[axis] : 1.0;
                for (int k = 0; k < kBuckets - 1; ++k) {
                    const double c = cost[k] * thinness;
                    if (c < best_cost) {
                        best_cost = c;
                        best_axis = axis;
                        best_bucket = k;
                    }
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
            int axis = 0;
            for (int a = 1; a < 3; ++a)
                if (extent[a] > extent[axis])
                    axis = a;
            std::nth_element(order.begin() + static_cast<std::ptrdiff_t>(begin),
                             order.begin() + static_cast<std::ptrdiff_t>(mid),
                             order.begin() + static_cast<std::ptrdiff_t>(end),
                             [&](std::uint32_t a, std::uint32_t b) { return centroid(a)[axis] < centroid(b)[axis]; });
        }
        return mid;
    }

    int bucket_of(std::uint32_t light, int axis, const Box& centroids, const glm::dvec3& extent) const
    {
        const double t = (centroid(light)[axis] - centroids.lo[axis]) / extent[axis];
        return std::clamp(static_cast<int>(t * kBuckets), 0, kBuckets - 1);
    }

    const std::vector<LightBounds>& lights_;
    LightTree& tree_;
};

} // namespace

LightCone cone_union(const LightCone& a, const LightCone& b)
{
    const double cos_e = std::min(a.cos_e, b.cos_e);
    if (a.cos_o <= -1.0 || b.cos_o <= -1.0)
        return whole_sphere(cos_e);
    const double theta_a = std::acos(std::clamp(a.cos_o, -1.0, 1.0));
    const double theta_b = std::acos(std::clamp(b.cos_o, -1.0, 1.0));
    const double theta_d = angle_between(a.axis, b.axis);
    if (std::min(theta_d + theta_b, kPi) <= theta_a)
        return {a.axis, a.cos_o, cos_e};
    if (std::min(theta_d + theta_a, kPi) <= theta_b)
        return {b.axis, b.cos_o, cos_e};
    // The cone that just holds both: half-angle (theta_a + theta_d + theta_b) / 2, its axis
    // turned from a's towards b's.
    const double theta_o = (theta_a + theta_d + theta_b) / 2.0;
    if (theta_o >= kPi)
        return whole_sphere(cos_e);
    const glm::dvec3 w = glm::cross(a.axis, b.axis);
    const double w_len = glm::length(w);
    if (!(w_len > 1e-12))
        return whole_sphere(cos_e);
    const glm::dvec3 k = w / w_len;
    const double turn = theta_o - theta_a;
    // Rodrigues: a.axis (orthogonal to k) turned by `turn` about k.
    const glm::dvec3 axis = a.axis * std::cos(turn) + glm::cross(k, a.axis) * std::sin(turn);
    return {glm::normalize(axis), std::cos(theta_o), cos_e};
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
        tree.nodes.reserve(2 * order.size() - 1);
        Builder(lights, tree).build(order, 0, order.size(), 0, 0);
    }
    return tree;
}

} // namespace pathcl
