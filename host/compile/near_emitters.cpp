#include "compile/near_emitters.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <vector>

#include <glm/geometric.hpp>

#include "light/triangle_sampling.h"

namespace pathcl {
namespace {

// Where a point would make the kernels sample one emitter by solid angle, on its
// emitting side: the half ball of `radius` around its centroid.
struct NearRegion {
    glm::dvec3 centre, normal; // normal: unit, towards the side it emits to
    double radius = 0.0;
    std::size_t triangle = 0; // the emitter itself, which does not count
    glm::dvec3 lo, hi;        // the ball's box
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

    // Calls test(region) for every region whose box overlaps [lo, hi] until it returns true.
    template <typename Test>
    bool any_overlapping(const glm::dvec3& lo, const glm::dvec3& hi, Test test) const
    {
        if (nodes_.empty())
            return false;
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
                    if (!glm::any(glm::lessThan(hi, r.lo)) && !glm::any(glm::greaterThan(lo, r.hi)) && test(r))
                        return true;
                }
                continue;
            }
            stack[top++] = n.first;
            stack[top++] = n.first + 1;
        }
        return false;
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

// The squared distance from p to the segment a b.
double segment_distance2(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b)
{
    const glm::dvec3 ab = b - a;
    const double len2 = glm::dot(ab, ab);
    const double t = len2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
    const glm::dvec3 d = p - (a + t * ab);
    return glm::dot(d, d);
}

// Whether triangle v has a point in region r: the part of it in front of the plane
// (x - centre) . normal = margin, clipped, within r.radius of the centre. The margin
// (about 8 float ulps of the coordinates) keeps out neighbours that the rounding of float
// vertices puts in front of a curved mesh's triangle.
bool reaches_region(const std::array<glm::dvec3, 3>& v, const NearRegion& r)
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
        return false;
    const double radius2 = r.radius * r.radius;
    double best = INFINITY;
    for (std::size_t k = 0; k < count; ++k)
        best = std::min(best, segment_distance2(r.centre, poly[k], poly[(k + 1) % count]));
    if (best < radius2)
        return true;
    // The centre's projection inside the clipped polygon: its distance is the plane's.
    const glm::dvec3 m = glm::cross(v[1] - v[0], v[2] - v[0]);
    const double m_len = glm::length(m);
    if (!(m_len > 0.0))
        return false;
    const glm::dvec3 unit = m / m_len;
    const double h = glm::dot(r.centre - v[0], unit);
    const glm::dvec3 q = r.centre - h * unit;
    for (std::size_t k = 0; k < count; ++k)
        if (glm::dot(glm::cross(poly[(k + 1) % count] - poly[k], q - poly[k]), unit) < 0.0)
            return false;
    return h * h < radius2;
}

} // namespace

bool surfaces_near_emitters(const Scene& scene)
{
    std::vector<NearRegion> regions;
    for (std::size_t i = 0; i < scene.triangles.size(); ++i) {
        const SceneTriangle& t = scene.triangles[i];
        if (!scene.materials[static_cast<std::size_t>(t.material)].emits())
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
        r.lo = r.centre - glm::dvec3(r.radius);
        r.hi = r.centre + glm::dvec3(r.radius);
        regions.push_back(r);
    }
    if (regions.empty())
        return false;
    const RegionTree tree(std::move(regions));
    for (std::size_t i = 0; i < scene.triangles.size(); ++i) {
        const SceneTriangle& t = scene.triangles[i];
        const std::array<glm::dvec3, 3> v{glm::dvec3(t.v[0]), glm::dvec3(t.v[1]), glm::dvec3(t.v[2])};
        const glm::dvec3 lo = glm::min(v[0], glm::min(v[1], v[2])), hi = glm::max(v[0], glm::max(v[1], v[2]));
        if (tree.any_overlapping(lo, hi, [&](const NearRegion& r) { return r.triangle != i && reaches_region(v, r); }))
            return true;
    }
    return false;
}

TriangleSampling resolve_triangle_sampling(const Scene& scene, const RenderOptions& options)
{
    if (options.triangle_sampling != TriangleSampling::Auto)
        return options.triangle_sampling;
    if (options.integrator == Integrator::Wavefront)
        return TriangleSampling::Area;
    return surfaces_near_emitters(scene) ? TriangleSampling::SolidAngle : TriangleSampling::Area;
}

} // namespace pathcl
