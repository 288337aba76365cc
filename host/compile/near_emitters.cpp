#include "compile/near_emitters.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <numeric>
#include <utility>
#include <vector>

#include <glm/geometric.hpp>

#include "compile/luminance.h"
#include "light/triangle_sampling.h"

namespace pathcl {
namespace {

// When auto samples by solid angle: where at least kNearPowerShare of the emitters'
// power lands near them, or where a surface comes so close to one that the emitter's area
// over the squared distance from its centroid to the surface reaches kNearCloseness.
// Measured (docs/accuracy.md, "Triangle sampling"), solid-angle against area sampling's
// error per sample: a 1 x 0.5 m panel parallel to a wall and a floor 3 cm to 40 cm away
// (share 1.0 to 0.85) 1.47-1.65x, at 80 cm (share 0.23, closeness 0.39) 1.08x, about what
// the test every light sample takes costs; the textured scene (0.14, 1.7) 1.01x for about
// 6 % of its speed; 384 lamps, a few against the walls (0.015, 58) 1.10x.
constexpr double kNearPowerShare = 0.5;
constexpr double kNearCloseness = 10.0;

// Where a point would make the kernels sample one emitter by solid angle, on its
// emitting side: the half ball of `radius` around its centroid.
struct NearRegion {
    glm::dvec3 centre, normal; // normal: unit, towards the side it emits to
    double radius = 0.0;
    std::size_t triangle = 0; // the emitter itself, which does not count
    double area = 0.0;
    double power = 0.0; // area x luminance of its emission (its texture left out)
    glm::dvec3 lo, hi;  // the ball's box
};

// A bounding-box hierarchy over the regions, queried with each triangle's box: emitters
// are as many as triangles at most, and usually far fewer. Median splits on the longest
// axis; leaves of up to kLeaf regions.
class RegionTree {
public:
    explicit RegionTree(std::vector<NearRegion> regions) : regions_(std::move(regions))
    {
        order_.resize(regions_.size());
        std::iota(order_.begin(), order_.end(), std::size_t{0});
        if (!regions_.empty())
            build(0, regions_.size());
    }

    // Calls visit(region) for every region whose box overlaps [lo, hi].
    template <typename Visit>
    void for_each_overlapping(const glm::dvec3& lo, const glm::dvec3& hi, Visit visit) const
    {
        if (nodes_.empty())
            return;
        std::array<std::uint32_t, 2 * kMaxDepth> stack;
        std::size_t top = 0;
        stack[top++] = 0;
        while (top > 0) {
            const Node& n = nodes_[stack[--top]];
            if (glm::any(glm::lessThan(hi, n.lo)) || glm::any(glm::greaterThan(lo, n.hi)))
                continue;
            if (n.count > 0) {
                for (std::uint32_t i = n.first; i < n.first + n.count; ++i) {
                    const NearRegion& r = regions_[order_[i]];
                    if (!glm::any(glm::lessThan(hi, r.lo)) && !glm::any(glm::greaterThan(lo, r.hi)))
                        visit(r);
                }
                continue;
            }
            stack[top++] = n.first;
            stack[top++] = n.first + 1;
        }
    }

private:
    static constexpr std::size_t kLeaf = 4;
    static constexpr std::size_t kMaxDepth = 64; // median splits: log2 of the regions, plus one
    struct Node {
        glm::dvec3 lo{INFINITY}, hi{-INFINITY};
        std::uint32_t first = 0, count = 0; // count 0: an inner node, children first, first + 1
    };

    // Builds the hierarchy over order_[begin, end), root first; each inner node's two
    // children are next to each other.
    void build(std::size_t begin, std::size_t end)
    {
        struct Task {
            std::size_t begin, end, node;
        };
        nodes_.emplace_back();
        std::vector<Task> tasks{{begin, end, 0}};
        while (!tasks.empty()) {
            const Task t = tasks.back();
            tasks.pop_back();
            Node n;
            glm::dvec3 centre_lo(INFINITY), centre_hi(-INFINITY);
            for (std::size_t i = t.begin; i < t.end; ++i) {
                const NearRegion& r = regions_[order_[i]];
                n.lo = glm::min(n.lo, r.lo);
                n.hi = glm::max(n.hi, r.hi);
                centre_lo = glm::min(centre_lo, r.centre);
                centre_hi = glm::max(centre_hi, r.centre);
            }
            if (t.end - t.begin <= kLeaf) {
                n.first = static_cast<std::uint32_t>(t.begin);
                n.count = static_cast<std::uint32_t>(t.end - t.begin);
                nodes_[t.node] = n;
                continue;
            }
            const glm::dvec3 extent = centre_hi - centre_lo;
            const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
            const std::size_t mid = t.begin + (t.end - t.begin) / 2;
            std::nth_element(
                order_.begin() + static_cast<std::ptrdiff_t>(t.begin),
                order_.begin() + static_cast<std::ptrdiff_t>(mid), order_.begin() + static_cast<std::ptrdiff_t>(t.end),
                [&](std::size_t a, std::size_t b) { return regions_[a].centre[axis] < regions_[b].centre[axis]; });
            n.first = static_cast<std::uint32_t>(nodes_.size());
            nodes_[t.node] = n;
            nodes_.emplace_back();
            nodes_.emplace_back();
            tasks.push_back({t.begin, mid, n.first});
            tasks.push_back({mid, t.end, n.first + 1});
        }
    }

    std::vector<NearRegion> regions_;
    std::vector<std::size_t> order_;
    std::vector<Node> nodes_;
};

// A triangle's corners in double, and their box.
using Corners = std::array<glm::dvec3, 3>;
Corners corners(const SceneTriangle& t)
{
    return {glm::dvec3(t.v[0]), glm::dvec3(t.v[1]), glm::dvec3(t.v[2])};
}

std::pair<glm::dvec3, glm::dvec3> box_of(const Corners& v)
{
    return {glm::min(v[0], glm::min(v[1], v[2])), glm::max(v[0], glm::max(v[1], v[2]))};
}

// The squared distance from p to the segment a b.
double segment_distance2(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b)
{
    const glm::dvec3 ab = b - a;
    const double len2 = glm::dot(ab, ab);
    const double t = len2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
    const glm::dvec3 d = p - (a + t * ab);
    return glm::dot(d, d);
}

// The squared distance from region r's centre to the nearest point of triangle v in
// front of the plane (x - centre) . normal = margin (INFINITY where none is). The margin
// (about 8 float ulps of the coordinates) keeps out neighbours that the rounding of float
// vertices puts in front of a curved mesh's triangle.
double front_distance2(const Corners& v, const NearRegion& r)
{
    const glm::dvec3 size = glm::abs(r.centre) + glm::dvec3(r.radius);
    const double margin = 1e-6 * std::max({size.x, size.y, size.z});
    std::array<glm::dvec3, 4> poly;
    std::size_t count = 0;
    for (std::size_t k = 0; k < 3; ++k) { // Sutherland-Hodgman against one plane
        const glm::dvec3 &a = v[k], &b = v[(k + 1) % 3];
        const double da = glm::dot(a - r.centre, r.normal) - margin, db = glm::dot(b - r.centre, r.normal) - margin;
        if (da > 0.0)
            poly[count++] = a;
        if ((da > 0.0) != (db > 0.0))
            poly[count++] = a + (da / (da - db)) * (b - a);
    }
    if (count == 0)
        return INFINITY;
    double best = INFINITY;
    for (std::size_t k = 0; k < count; ++k)
        best = std::min(best, segment_distance2(r.centre, poly[k], poly[(k + 1) % count]));
    // The centre's projection inside the clipped polygon: its distance is the plane's.
    const glm::dvec3 m = glm::cross(v[1] - v[0], v[2] - v[0]);
    const double m_len = glm::length(m);
    if (!(m_len > 0.0))
        return best;
    const glm::dvec3 unit = m / m_len;
    const double h = glm::dot(r.centre - v[0], unit);
    const glm::dvec3 q = r.centre - h * unit;
    for (std::size_t k = 0; k < count; ++k)
        if (glm::dot(glm::cross(poly[(k + 1) % count] - poly[k], q - poly[k]), unit) < 0.0)
            return best;
    return std::min(best, h * h);
}

// The distance along the ray o + t d (d unit) to triangle v, or INFINITY where it misses
// (Moller-Trumbore in double; both sides).
double ray_distance(const glm::dvec3& o, const glm::dvec3& d, const Corners& v)
{
    const glm::dvec3 e1 = v[1] - v[0], e2 = v[2] - v[0], p = glm::cross(d, e2);
    const double det = glm::dot(e1, p);
    if (det == 0.0)
        return INFINITY;
    const glm::dvec3 s = o - v[0];
    const double b1 = glm::dot(s, p) / det;
    const glm::dvec3 q = glm::cross(s, e1);
    const double b2 = glm::dot(d, q) / det;
    const double t = glm::dot(e2, q) / det;
    return b1 >= 0.0 && b2 >= 0.0 && b1 + b2 <= 1.0 && t > 0.0 ? t : INFINITY;
}

// kNearRays directions about +z with density cos / pi (a Fibonacci lattice on the unit
// disc, lifted onto the hemisphere): the same for every emitter, so the share is
// reproducible.
constexpr std::size_t kNearRays = 256;
std::array<glm::dvec3, kNearRays> cosine_directions()
{
    std::array<glm::dvec3, kNearRays> d;
    const double golden = std::numbers::pi * (3.0 - std::sqrt(5.0));
    for (std::size_t i = 0; i < kNearRays; ++i) {
        const double r2 = (static_cast<double>(i) + 0.5) / kNearRays, r = std::sqrt(r2);
        const double phi = golden * static_cast<double>(i);
        d[i] = {r * std::cos(phi), r * std::sin(phi), std::sqrt(1.0 - r2)};
    }
    return d;
}

// The triangles that reach a region, in groups of kChunk in their order in the scene
// (neighbours in a mesh, mostly), each group with its box: a ray skips the groups whose
// box it misses, so a dense mesh near a large emitter costs a box test per group.
constexpr std::size_t kChunk = 32;
struct Reaching {
    std::vector<Corners> triangles;
    std::vector<std::pair<glm::dvec3, glm::dvec3>> boxes; // of triangles [kChunk k, kChunk (k + 1))
    void clear()
    {
        triangles.clear();
        boxes.clear();
    }
    void add(const Corners& v)
    {
        const auto [lo, hi] = box_of(v);
        if (triangles.size() % kChunk == 0)
            boxes.emplace_back(lo, hi);
        boxes.back() = {glm::min(boxes.back().first, lo), glm::max(boxes.back().second, hi)};
        triangles.push_back(v);
    }
};

// Whether the ray o + t d, 0 < t < t_max, passes through the box (the slab test, with
// the reciprocals of the direction's components: see reciprocal).
bool ray_meets_box(const glm::dvec3& o, const glm::dvec3& inv_d, double t_max, const glm::dvec3& lo,
                   const glm::dvec3& hi)
{
    const glm::dvec3 t0 = (lo - o) * inv_d, t1 = (hi - o) * inv_d;
    const glm::dvec3 near = glm::min(t0, t1), far = glm::max(t0, t1);
    const double enter = std::max({near.x, near.y, near.z, 0.0}), leave = std::min({far.x, far.y, far.z, t_max});
    return enter <= leave;
}

// 1 / d per component, a zero component's as 1 / 1e-300: finite, so that a slab the ray's
// origin lies on gives 0 x that, not 0 x infinity (NaN, which would skip its box).
glm::dvec3 reciprocal(const glm::dvec3& d)
{
    glm::dvec3 inv;
    for (int k = 0; k < 3; ++k)
        inv[k] = 1.0 / (d[k] != 0.0 ? d[k] : 1e-300);
    return inv;
}

// The power of region r's emitter that, sent from its centroid in kNearRays directions,
// meets one of the triangles that reach the region within it.
double near_power(const NearRegion& r, const Reaching& reaching, const std::array<glm::dvec3, kNearRays>& directions)
{
    const glm::dvec3 n = r.normal;
    const glm::dvec3 a = std::abs(n.x) > 0.9 ? glm::dvec3(0.0, 1.0, 0.0) : glm::dvec3(1.0, 0.0, 0.0);
    const glm::dvec3 t = glm::normalize(glm::cross(a, n)), b = glm::cross(n, t);
    std::size_t hits = 0;
    for (const glm::dvec3& l : directions) {
        const glm::dvec3 d = l.x * t + l.y * b + l.z * n, inv_d = reciprocal(d);
        bool hit = false;
        for (std::size_t c = 0; c < reaching.boxes.size() && !hit; ++c) {
            if (!ray_meets_box(r.centre, inv_d, r.radius, reaching.boxes[c].first, reaching.boxes[c].second))
                continue;
            const std::size_t end = std::min(reaching.triangles.size(), (c + 1) * kChunk);
            for (std::size_t i = c * kChunk; i < end && !hit; ++i)
                hit = ray_distance(r.centre, d, reaching.triangles[i]) < r.radius;
        }
        hits += hit ? 1 : 0;
    }
    return r.power * static_cast<double>(hits) / kNearRays;
}

} // namespace

NearEmitters near_emitters(const Scene& scene)
{
    std::vector<NearRegion> regions;
    double total = 0.0;
    for (std::size_t i = 0; i < scene.triangles.size(); ++i) {
        const SceneTriangle& t = scene.triangles[i];
        const SceneMaterial& material = scene.materials[static_cast<std::size_t>(t.material)];
        if (!material.emits())
            continue;
        const glm::dvec3 v0(t.v[0]), v1(t.v[1]), v2(t.v[2]);
        const glm::dvec3 m = glm::cross(v1 - v0, v2 - v0);
        const double m_len = glm::length(m);
        if (!(m_len > 0.0))
            continue; // no area: never sampled
        NearRegion r;
        r.centre = (v0 + v1 + v2) / 3.0;
        r.normal = m / m_len;
        r.radius = std::sqrt(0.5 * m_len / static_cast<double>(TRIANGLE_SOLID_ANGLE_MIN));
        r.triangle = i;
        r.area = 0.5 * m_len;
        r.power = r.area * luminance(material.emission);
        r.lo = r.centre - glm::dvec3(r.radius);
        r.hi = r.centre + glm::dvec3(r.radius);
        total += r.power;
        regions.push_back(r);
    }
    if (regions.empty() || !(total > 0.0))
        return {};
    // Which triangles reach each region, as (emitter triangle, triangle) pairs, and how
    // close the nearest comes.
    NearEmitters result;
    const RegionTree tree(regions);
    std::vector<std::pair<std::size_t, std::uint32_t>> pairs;
    for (std::size_t i = 0; i < scene.triangles.size(); ++i) {
        const Corners v = corners(scene.triangles[i]);
        const auto [lo, hi] = box_of(v);
        tree.for_each_overlapping(lo, hi, [&](const NearRegion& r) {
            const double d2 = r.triangle != i ? front_distance2(v, r) : INFINITY;
            if (d2 < r.radius * r.radius) {
                pairs.emplace_back(r.triangle, static_cast<std::uint32_t>(i));
                result.closeness = std::max(result.closeness, r.area / d2);
            }
        });
    }
    std::sort(pairs.begin(), pairs.end());
    const std::array<glm::dvec3, kNearRays> directions = cosine_directions();
    Reaching reaching;
    auto p = pairs.begin();
    for (const NearRegion& r : regions) { // in the order of their triangles, as pairs is
        reaching.clear();
        for (; p != pairs.end() && p->first == r.triangle; ++p)
            reaching.add(corners(scene.triangles[p->second]));
        if (!reaching.triangles.empty())
            result.power_share += near_power(r, reaching, directions) / total;
    }
    return result;
}

TriangleSampling resolve_triangle_sampling(const Scene& scene, const RenderOptions& options)
{
    if (options.triangle_sampling != TriangleSampling::Auto)
        return options.triangle_sampling;
    if (options.integrator == Integrator::Wavefront)
        return TriangleSampling::Area;
    const NearEmitters near = near_emitters(scene);
    return near.power_share >= kNearPowerShare || near.closeness >= kNearCloseness ? TriangleSampling::SolidAngle
                                                                                   : TriangleSampling::Area;
}

} // namespace pathcl
