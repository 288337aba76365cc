#include "compile/light_tree.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <mutex>
#include <numbers>
#include <type_traits>
#include <utility>

#include <glm/geometric.hpp>

#include "common/error.h"
#include "common/shared_work.h"
#include "compile/alias_table.h"

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

// std::acos, without the call for the cosines of a triangle's cone (1: one direction; 0:
// its emission, pi/2 past it), which every emissive triangle's record takes.
double arc_cosine(double c)
{
    static const double zero = std::acos(0.0);
    return c == 1.0 ? 0.0 : c == 0.0 ? zero : std::acos(c);
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
          theta_o(arc_cosine(cos_o)), cos_e(std::clamp(c.cos_e, -1.0, 1.0)), theta_e(arc_cosine(cos_e))
    {}
    Cone(const glm::dvec3& a, double theta, const Cone& spread)
        : axis(a), cos_o(std::cos(theta)), sin_o(std::sin(theta)), theta_o(theta), cos_e(spread.cos_e),
          theta_e(spread.theta_e)
    {}
    // Every field given (a LightRecord's).
    Cone(const glm::dvec3& a, double cos_o_, double sin_o_, double theta_o_, double cos_e_, double theta_e_)
        : axis(a), cos_o(cos_o_), sin_o(sin_o_), theta_o(theta_o_), cos_e(cos_e_), theta_e(theta_e_)
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
    if (!(w_len > 1e-12)) {
        // Axes parallel to rounding (the normals of coplanar triangles): the wider cone
        // widened by their angle holds both. Opposite axes: the whole sphere.
        if (cos_d < 0.0)
            return with_spread(Cone(), spread);
        const Cone& wide = a.theta_o >= b.theta_o ? a : b;
        return Cone(wide.axis, wide.theta_o + theta_d, spread);
    }
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

// A light as the build reads it. The records are kept in the order the partitions leave
// them, so that each pass over a node's lights walks contiguous memory, two cache lines a
// record. It holds its cone as Cone's fields, not a Cone, so that a record has no default
// values: the records are made on every core, each page first written by the core that
// fills it (page faults on 128 MB took 50 ms on one core of the 2-core VM).
struct alignas(64) LightRecord {
    glm::dvec3 axis;
    double cos_o, sin_o, theta_o, cos_e, theta_e;
    glm::dvec3 lo, hi;
    double phi;
    std::uint32_t light;
    bool two_sided;

    LightRecord() {} // NOLINT(modernize-use-equals-default): no values, see above
    LightRecord(const LightBounds& b, std::uint32_t l) : LightRecord(b, Cone(b.cone), l) {}
    Cone cone() const { return {axis, cos_o, sin_o, theta_o, cos_e, theta_e}; }
    glm::dvec3 centroid() const { return (lo + hi) * 0.5; }

private:
    LightRecord(const LightBounds& b, const Cone& c, std::uint32_t l)
        : axis(c.axis), cos_o(c.cos_o), sin_o(c.sin_o), theta_o(c.theta_o), cos_e(c.cos_e), theta_e(c.theta_e),
          lo(b.lo), hi(b.hi), phi(b.phi), light(l), two_sided(b.two_sided)
    {}
};

// A node's bounds while building: box, power, cone (and whether any light is two-sided),
// and the sum of its lights' axes weighted by power, the axis tighten_cone tries.
struct Bounds {
    Box box;
    double phi = 0.0;
    Cone cone;
    glm::dvec3 axis_sum{0.0};
    bool any = false;
    bool two_sided = false;
    void extend(const LightRecord& r)
    {
        box.extend(r.lo, r.hi);
        phi += r.phi;
        cone = any ? unite(cone, r.cone()) : r.cone();
        axis_sum += r.phi * r.axis;
        two_sided = two_sided || r.two_sided;
        any = true;
    }
    void extend(const Bounds& b)
    {
        if (!b.any)
            return;
        box.extend(b.box.lo, b.box.hi);
        phi += b.phi;
        cone = any ? unite(cone, b.cone) : b.cone;
        axis_sum += b.axis_sum;
        two_sided = two_sided || b.two_sided;
        any = true;
    }
};

// The orientation measure of a cone of normals theta_o wide emitting theta_e past it (the
// paper's M_Omega): the solid angle its directions sweep, weighted by their cosine.
double orientation_measure(const Cone& c)
{
    // The paper's cos(theta_o - 2 theta_w), theta_w = min(theta_o + theta_e, pi), without
    // a cosine: cos(theta_o) where theta_w is pi, else cos(theta_o + 2 theta_e) from the
    // double angle's cosine and sine.
    double theta_w = kPi, cos_ow = c.cos_o;
    if (c.theta_o + c.theta_e < kPi) {
        theta_w = c.theta_o + c.theta_e;
        const double sin_e = std::sqrt(std::max(0.0, 1.0 - c.cos_e * c.cos_e));
        cos_ow = c.cos_o * (2.0 * c.cos_e * c.cos_e - 1.0) - c.sin_o * (2.0 * sin_e * c.cos_e);
    }
    return 2.0 * kPi * (1.0 - c.cos_o) +
           kPi / 2.0 * (2.0 * theta_w * c.sin_o - cos_ow - 2.0 * c.theta_o * c.sin_o + c.cos_o);
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
// A range of at most this many lights is split by power and box area alone (the paper's
// SAH), without the cones: the eight-wide tree gives most such ranges a node of their own,
// each light a lane whatever the halves were, or a cluster picked by power, so the
// orientation measure decides little there; and most binary nodes are this small, so
// binning their cones took about a sixth of the build's time. Over randomly turned glowing
// cubes the picks' second moment went from 1.295 to 1.300 (1 is ideal;
// LightTreeSampling.PicksAmongGlowingCubesComeCloseToTheIdeal); the trees of the glowing
// sphere and of the lamps are the same but for ulps of a few cones and the bits of some
// lights' paths past their cluster, which nothing reads.
constexpr std::uint32_t kPlacedLights = LIGHT_TREE_WIDTH;
// Trees of more lights than this are built on every core (SharedWork): subtrees of more
// than kShareLights are handed to a core that has nothing left to build, and the records
// are made that many at a time.
constexpr std::size_t kParallelLights = 4096;
constexpr std::size_t kShareLights = 1024;

// A node of the binary tree the eight-wide one is collapsed from. A child is a node or,
// with kLeaf set, a light: the position of its record. Every field is set when the node
// is built (no default values, as in LightRecord).
struct BinaryNode {
    std::array<std::uint32_t, 2> child;
    std::uint32_t first;  // its lights' first record
    std::uint32_t lights; // below it
    bool pending;         // its bounds wait for a subtree built on another thread
    BinaryNode() {}       // NOLINT(modernize-use-equals-default)
};

// A node's Bounds, stored without default values (as in LightRecord).
class StoredBounds {
public:
    StoredBounds() {} // NOLINT(modernize-use-equals-default)
    void set(const Bounds& b) { std::memcpy(bytes_, &b, sizeof(Bounds)); }
    Bounds get() const
    {
        Bounds b;
        std::memcpy(&b, bytes_, sizeof(Bounds));
        return b;
    }

private:
    static_assert(std::is_trivially_copyable_v<Bounds>);
    alignas(Bounds) unsigned char bytes_[sizeof(Bounds)];
};

constexpr std::uint32_t kLeaf = 1u << 31;

// A leaf's bounds: those of its light.
Bounds light_bounds(const LightRecord& r)
{
    Bounds b;
    b.extend(r);
    return b;
}

// The binary tree: its nodes, depth first (a node over n lights is followed by the n - 2
// nodes of its subtrees, the first child's before the second's), their bounds (apart:
// laying out the eight-wide tree reads only the nodes) and the lights' records.
struct BinaryTree {
    std::vector<BinaryNode> nodes;
    std::vector<StoredBounds> bounds; // by node
    std::vector<LightRecord> records;

    Bounds of(std::uint32_t child) const
    {
        return child & kLeaf ? light_bounds(records[child & ~kLeaf]) : bounds[child].get();
    }
};

bool finite(const LightBounds& b)
{
    return std::isfinite(b.phi) && std::isfinite(b.lo.x) && std::isfinite(b.lo.y) && std::isfinite(b.lo.z) &&
           std::isfinite(b.hi.x) && std::isfinite(b.hi.y) && std::isfinite(b.hi.z);
}

// Builds the binary tree. A subtree's nodes have their place before it is built (the
// depth-first layout), so that subtrees built on different threads need no merging.
class Builder {
public:
    // Over the lights of `order`, in that order: those of `lights` (a BoundsList or a
    // LightList) that are not infinite. Throws pathcl::Error naming the first whose bounds
    // or power are not finite.
    template <class Lights>
    Builder(const Lights& lights, const std::vector<std::uint32_t>& order, std::vector<pcl_ulong>& trails)
        : work_(order.size() > kParallelLights ? 0 : 1), trails_(trails)
    {
        const std::size_t n = order.size();
        records_.resize(n);
        buckets_.resize(n);
        nodes_.resize(n - 1);
        tree_.bounds.resize(n - 1);
        // The centroids' box of each piece, merged in the order of the pieces: the box one
        // pass over all would make, down to which of +0 and -0 it holds.
        std::mutex mutex;
        std::vector<std::pair<std::size_t, Box>> boxes;
        std::size_t not_finite = n;
        SharedWork::for_pieces(n, kShareLights, n > kParallelLights ? 0 : 1, [&](std::size_t begin, std::size_t end) {
            Box box;
            std::size_t bad = n;
            for (std::size_t i = begin; i < end; ++i) {
                const LightBounds& b = lights.bounds(order[i]); // a BoundsList's own, a LightList's made here
                if (bad == n && !finite(b))
                    bad = i;
                records_[i] = LightRecord(b, order[i]);
                const glm::dvec3 c = records_[i].centroid();
                box.extend(c, c);
            }
            const std::lock_guard<std::mutex> lock(mutex);
            boxes.emplace_back(begin, box);
            not_finite = std::min(not_finite, bad);
        });
        if (not_finite < n)
            throw Error("light " + std::to_string(order[not_finite]) + " has bounds or power that are not finite");
        std::sort(boxes.begin(), boxes.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
        for (const auto& [begin, box] : boxes)
            centroids_.extend(box.lo, box.hi);
    }

    // Builds the tree; returns its root.
    std::uint32_t build()
    {
        if (records_.size() == 1) {
            trails_[records_[0].light] = 0;
            return kLeaf;
        }
        work_.run([this] { subtree(0, 0, records_.size(), 0, 0, centroids_); });
        finish(0);
        return 0;
    }

    const BinaryTree& tree() const { return tree_; }

private:
    // Where the second child starts, and the boxes of the children's centroids.
    struct Split {
        std::size_t mid;
        Box first, second;
    };

    // The subtree over records_[begin, end), whose centroids `centroids` bounds, reached
    // from the root by `trail` (bit k: the child taken at depth k) at `depth`: a light, or
    // the node at nodes_[index] and those below it. Returns whether its bounds are set
    // (not while a part of it is being built on another thread).
    bool subtree(std::size_t index, std::size_t begin, std::size_t end, std::uint32_t depth, pcl_ulong trail,
                 const Box& centroids)
    {
        if (end - begin == 1) {
            trails_[records_[begin].light] = trail;
            return true;
        }
        const Split s = split(begin, end, depth, centroids);
        const pcl_ulong second_trail = trail | (pcl_ulong(1) << depth);
        const std::size_t first = index + 1, second = index + (s.mid - begin);
        const bool shared = end - s.mid > kShareLights && work_.wanted();
        if (shared)
            work_.share([=, this] { subtree(second, s.mid, end, depth + 1, second_trail, s.second); });
        const bool first_set = subtree(first, begin, s.mid, depth + 1, trail, s.first);
        const bool second_set = !shared && subtree(second, s.mid, end, depth + 1, second_trail, s.second);
        const bool complete = first_set && second_set;
        BinaryNode& n = nodes_[index];
        n.child = {reference(first, begin, s.mid), reference(second, s.mid, end)};
        n.first = static_cast<std::uint32_t>(begin);
        n.lights = static_cast<std::uint32_t>(end - begin);
        n.pending = !complete;
        if (complete)
            tree_.bounds[index].set(node_bounds(n));
        return complete;
    }

    // The child over records_[begin, end) whose node (if it is one) is nodes_[index].
    static std::uint32_t reference(std::size_t index, std::size_t begin, std::size_t end)
    {
        return static_cast<std::uint32_t>(end - begin == 1 ? kLeaf | begin : index);
    }

    // The union of the children's bounds, its cone tightened around its lights.
    Bounds node_bounds(const BinaryNode& n) const
    {
        const Bounds first = tree_.of(n.child[0]), second = tree_.of(n.child[1]);
        Bounds b = first;
        b.extend(second);
        // A child whose lights need the whole sphere of directions (a point light) leaves
        // no tighter cone to find.
        if (first.cone.cos_o > -1.0 && second.cone.cos_o > -1.0)
            b.cone = tighten_cone(b, n.first, n.first + n.lights);
        return b;
    }

    // The tighter of the cones about b's axis and about its lights' power-weighted mean
    // axis that hold every light of records_[begin, end). The cone of a union of two cones
    // holds each whole, so unions of unions up the tree grow wider than the lights need:
    // over a UV sphere turned off the axes (tests/test_light_tree.cpp) a lane of 602
    // triangles took 109 degrees where 87 hold them. One pass over the lights for both
    // axes; a node's lights are contiguous, so the passes add O(n log n) to the build.
    Cone tighten_cone(const Bounds& b, std::size_t begin, std::size_t end) const
    {
        const double sum_length = glm::length(b.axis_sum);
        const glm::dvec3 united = b.cone.axis, mean = sum_length > 1e-9 * b.phi ? b.axis_sum / sum_length : united;
        double cos_united = 1.0, cos_mean = 1.0; // cos of the widest angle from each axis
        for (std::size_t i = begin; i < end; ++i) {
            const LightRecord& r = records_[i];
            cos_united = std::min(cos_united, cos_of_widest(united, r));
            cos_mean = std::min(cos_mean, cos_of_widest(mean, r));
        }
        const bool mean_tighter = cos_mean > cos_united;
        const double cos_k = (mean_tighter ? cos_mean : cos_united) - 1e-12; // rounding, on the safe side
        if (!(cos_k > b.cone.cos_o))
            return b.cone;
        return Cone(mean_tighter ? mean : united, std::acos(cos_k), b.cone);
    }

    // cos(theta_d + theta_l): the direction of light r's cone farthest from `axis`; -1
    // where that passes pi.
    static double cos_of_widest(const glm::dvec3& axis, const LightRecord& r)
    {
        const double cos_d = std::clamp(glm::dot(axis, r.axis), -1.0, 1.0);
        if (r.cos_o <= -1.0 || cos_d < -r.cos_o)
            return -1.0;
        if (r.sin_o == 0.0) // a cone of one direction (a triangle's): sin_d * sin_o is +0, which changes nothing
            return cos_d * r.cos_o;
        const double sin_d = std::sqrt(1.0 - cos_d * cos_d);
        return cos_d * r.cos_o - sin_d * r.sin_o;
    }

    // Sets the bounds the threads left pending, below the subtrees they built.
    void finish(std::uint32_t index)
    {
        BinaryNode& n = nodes_[index];
        if (!n.pending)
            return;
        for (std::uint32_t c : n.child)
            if (!(c & kLeaf))
                finish(c);
        tree_.bounds[index].set(node_bounds(n));
        n.pending = false;
    }

    Box centroid_box(std::size_t begin, std::size_t end) const
    {
        Box box;
        for (std::size_t i = begin; i < end; ++i) {
            const glm::dvec3 c = records_[i].centroid();
            box.extend(c, c);
        }
        return box;
    }

    // Partitions records_[begin, end).
    Split split(std::size_t begin, std::size_t end, std::uint32_t depth, const Box& centroids)
    {
        const glm::dvec3 extent = centroids.hi - centroids.lo;
        // Binned along the centroids' longest axis only: a third of the work of trying all
        // three, which the build's speed needs.
        int axis = 0;
        for (int a = 1; a < 3; ++a)
            if (extent[a] > extent[axis])
                axis = a;
        const auto first = records_.begin() + static_cast<std::ptrdiff_t>(begin);
        const auto last = records_.begin() + static_cast<std::ptrdiff_t>(end);
        if (end - begin == 2) {
            // Whatever the costs, two lights end up ordered along the axis, the first
            // kept first where they tie (as the partition and the halving by count below
            // leave them).
            if (last[-1].centroid()[axis] < first->centroid()[axis])
                std::iter_swap(first, last - 1);
            const glm::dvec3 a = first->centroid(), b = last[-1].centroid();
            return {begin + 1, {a, a}, {b, b}};
        }
        if (depth < kMedianDepth && extent[axis] > 0.0) {
            const bool oriented = end - begin > kPlacedLights;
            const Bins bins = oriented ? bin<true>(begin, end, axis, centroids, extent)
                                       : bin<false>(begin, end, axis, centroids, extent);
            const int best = oriented ? best_bucket<true>(bins.buckets) : best_bucket<false>(bins.buckets);
            if (best >= 0) {
                const std::size_t mid = partition(begin, end, best);
                if (mid != begin && mid != end) {
                    Split s{mid, {}, {}};
                    for (int k = 0; k < kBuckets; ++k) {
                        Box& side = k <= best ? s.first : s.second;
                        side.extend(bins.centroids[k].lo, bins.centroids[k].hi);
                    }
                    return s;
                }
            }
        }
        // No split of the centroids: halves by count, along the widest axis.
        const std::size_t mid = begin + (end - begin) / 2;
        std::nth_element(
            first, records_.begin() + static_cast<std::ptrdiff_t>(mid), last,
            [&](const LightRecord& a, const LightRecord& b) { return a.centroid()[axis] < b.centroid()[axis]; });
        return {mid, centroid_box(begin, mid), centroid_box(mid, end)};
    }

    // The bucket after which a split costs least, -1 if none has a cost below infinity:
    // by the SAOH where `Oriented`, else by power and box area alone.
    template <bool Oriented>
    static int best_bucket(const std::array<Bounds, kBuckets>& buckets)
    {
        // Costs of splitting after bucket k: a sweep from each side; an empty bucket leaves
        // the cost as it was.
        std::array<double, kBuckets - 1> cost{};
        Bounds below;
        double below_cost = 0.0;
        for (int k = 0; k < kBuckets - 1; ++k) {
            if (buckets[k].any)
                below_cost = extended_cost<Oriented>(below, buckets[k]);
            cost[k] = below_cost;
        }
        Bounds above;
        double above_cost = 0.0;
        for (int k = kBuckets - 1; k > 0; --k) {
            if (buckets[k].any)
                above_cost = extended_cost<Oriented>(above, buckets[k]);
            cost[k - 1] += above_cost;
        }
        double best_cost = INFINITY;
        int best = -1;
        for (int k = 0; k < kBuckets - 1; ++k) {
            if (cost[k] < best_cost) {
                best_cost = cost[k];
                best = k;
            }
        }
        return best;
    }

    // The lights of a range in kBuckets buckets: each bucket's box, power and cone, and the
    // box of its lights' centroids.
    struct Bins {
        std::array<Bounds, kBuckets> buckets;
        std::array<Box, kBuckets> centroids;
    };

    // Extends `side` of a split by bucket b; returns its cost.
    template <bool Oriented>
    static double extended_cost(Bounds& side, const Bounds& b)
    {
        if constexpr (Oriented) {
            side.extend(b);
            return saoh_cost(side);
        } else {
            side.box.extend(b.box.lo, b.box.hi);
            side.phi += b.phi;
            return side.phi * side.box.area();
        }
    }

    // The lights of records_[begin, end) in kBuckets buckets along `axis`. Where
    // `Oriented`, a bucket's cone is the one around its lights' mean axis that holds all of
    // their cones: two passes of dot products and square roots, where uniting the lights'
    // cones one by one would take their angles; otherwise only boxes and power are binned.
    template <bool Oriented>
    Bins bin(std::size_t begin, std::size_t end, int axis, const Box& centroids, const glm::dvec3& extent)
    {
        Bins bins;
        std::array<Bounds, kBuckets>& buckets = bins.buckets;
        std::array<glm::dvec3, kBuckets> axes{};
        std::array<const LightRecord*, kBuckets> spread{}; // the first of the widest emission spread
        const double lo = centroids.lo[axis], scale = kBuckets / extent[axis];
        for (std::size_t i = begin; i < end; ++i) {
            const LightRecord& r = records_[i];
            const glm::dvec3 c = r.centroid();
            const int k = bucket_of(c[axis], lo, scale);
            buckets_[i] = static_cast<std::uint8_t>(k);
            Bounds& b = buckets[k];
            b.box.extend(r.lo, r.hi);
            b.phi += r.phi;
            b.two_sided = b.two_sided || r.two_sided;
            b.any = true;
            if constexpr (Oriented) {
                axes[k] += r.axis;
                if (!spread[k] || r.cos_e < spread[k]->cos_e)
                    spread[k] = &r;
            }
            bins.centroids[k].extend(c, c);
        }
        if constexpr (!Oriented)
            return bins;
        std::array<double, kBuckets> cos_o;
        std::array<glm::dvec3, kBuckets> mean;
        for (int k = 0; k < kBuckets; ++k) {
            const double len = glm::length(axes[k]);
            mean[k] = len > 1e-9 ? axes[k] / len : glm::dvec3(0.0, 0.0, 1.0);
            cos_o[k] = len > 1e-9 ? 1.0 : -1.0;
        }
        for (std::size_t i = begin; i < end; ++i) {
            const LightRecord& r = records_[i];
            const int k = buckets_[i];
            if (cos_o[k] > -1.0)
                cos_o[k] = std::min(cos_o[k], cos_of_widest(mean[k], r));
        }
        for (int k = 0; k < kBuckets; ++k) {
            if (!buckets[k].any)
                continue;
            const Cone s = spread[k]->cone();
            const double cos_k = std::max(-1.0, cos_o[k] - 1e-12); // rounding, on the safe side
            buckets[k].cone = with_spread(cos_k <= -1.0 ? Cone() : Cone(mean[k], std::acos(cos_k), s), s);
        }
        return bins;
    }

    static int bucket_of(double centroid, double lo, double scale)
    {
        return std::clamp(static_cast<int>((centroid - lo) * scale), 0, kBuckets - 1);
    }

    // Moves the records of records_[begin, end) whose bucket (buckets_, as bin() left it)
    // is at most `best` before the others; returns where the others start. The partition
    // of std::partition (libstdc++'s, for random-access iterators): swaps from both ends,
    // each record's bucket read where bin() wrote it, before the record moves.
    std::size_t partition(std::size_t begin, std::size_t end, int best)
    {
        std::size_t first = begin, last = end;
        for (;;) {
            for (;; ++first) {
                if (first == last)
                    return first;
                if (buckets_[first] > best)
                    break;
            }
            for (--last;; --last) {
                if (first == last)
                    return first;
                if (buckets_[last] <= best)
                    break;
            }
            const LightRecord moved = records_[first]; // (std::swap on records is a call, not inlined)
            records_[first] = records_[last];
            records_[last] = moved;
            ++first;
        }
    }

    SharedWork work_;
    BinaryTree tree_;
    Box centroids_;                                     // of every light
    std::vector<LightRecord>& records_ = tree_.records; // in the order the partitions leave them
    std::vector<BinaryNode>& nodes_ = tree_.nodes;
    std::vector<pcl_ulong>& trails_;
    // By record: its bucket in the last binning of a range that holds it, which the second
    // binning pass and the partition read instead of working it out again.
    std::vector<std::uint8_t> buckets_;
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
// lights is replaced by its two children until there are eight or only leaves; in a node
// over more than eight lights, only lanes worth it are split (worth_splitting), and a lane
// not worth it whose lights face nearly one way is a cluster leaf (cluster). Each lane
// keeps its code, the bits of the binary path from the node down to it (LIGHT_TREE_CODE),
// by which a light's binary trail leads through the eight-wide nodes. The nodes are laid
// out depth first on one thread; their lanes' bounds are then set on every core (trees of
// more than kParallelNodes nodes, in pieces of at least kShareNodes).
constexpr std::size_t kParallelNodes = 1024;
constexpr std::size_t kShareNodes = 256;
// The widest cone (theta_o, radians) of a cluster's normals: 14 degrees. A cluster of more
// than eight lights spans at most 1 / kClusterExtent of the diagonal of every light's box.
constexpr double kClusterCone = 0.25;
constexpr double kClusterExtent = 16.0;

class Collapser {
public:
    Collapser(const BinaryTree& binary, LightTree& tree) : binary_(binary), tree_(tree) {}

    // Writes the eight-wide tree under binary node `root` (Builder's reference: a node or
    // a light).
    void collapse(std::uint32_t root)
    {
        lanes_.reserve(binary_.nodes.size() + 1); // at most one node for each binary one
        const Box all = binary_.of(root).box;
        const glm::dvec3 diagonal = all.hi - all.lo;
        cluster_extent2_ = glm::dot(diagonal, diagonal) / (kClusterExtent * kClusterExtent);
        lay_out(root, 0);
        tree_.nodes.resize(lanes_.size()); // unwritten: write() fills each node on the core that writes it
        SharedWork::for_pieces(lanes_.size(), kShareNodes, lanes_.size() > kParallelNodes ? 0 : 1,
                               [this](std::size_t begin, std::size_t end) {
                                   for (std::size_t i = begin; i < end; ++i)
                                       write(i);
                               });
    }

private:
    // A node's lanes: the binary node (or light) each stands for, its code, its child node.
    struct Lanes {
        std::array<std::uint32_t, LIGHT_TREE_WIDTH> binary;
        std::array<pcl_int, LIGHT_TREE_WIDTH> code, child;
        std::uint32_t count = 0;
    };

    // Lays out the eight-wide node for binary node b at `depth` and everything below it;
    // returns its index.
    std::uint32_t lay_out(std::uint32_t b, std::uint32_t depth)
    {
        struct Lane {
            std::uint32_t binary, bits, length;
            bool splits; // replaced by its two children when it is the widest such lane
        };
        std::array<Lane, LIGHT_TREE_WIDTH> lanes;
        std::size_t count = 0;
        if (b & kLeaf) {
            lanes[count++] = {b, 0, 0, false}; // a tree of one light
        } else {
            const bool many = binary_.nodes[b].lights > LIGHT_TREE_WIDTH;
            const auto splits = [&](std::uint32_t lane) { return !(lane & kLeaf) && (!many || worth_splitting(lane)); };
            const BinaryNode& root = binary_.nodes[b];
            lanes[count++] = {root.child[0], 0, 1, splits(root.child[0])};
            lanes[count++] = {root.child[1], 1, 1, splits(root.child[1])};
            while (count < LIGHT_TREE_WIDTH) {
                std::size_t widest = count;
                for (std::size_t k = 0; k < count; ++k)
                    if (lanes[k].splits && (widest == count || binary_.nodes[lanes[k].binary].lights >
                                                                   binary_.nodes[lanes[widest].binary].lights))
                        widest = k;
                if (widest == count)
                    break;
                const Lane w = lanes[widest];
                const BinaryNode& n = binary_.nodes[w.binary];
                lanes[widest] = {n.child[0], w.bits, w.length + 1, splits(n.child[0])};
                lanes[count++] = {n.child[1], w.bits | (1u << w.length), w.length + 1, splits(n.child[1])};
            }
        }
        const auto index = static_cast<std::uint32_t>(lanes_.size());
        lanes_.emplace_back();
        tree_.depth = std::max(tree_.depth, depth + 1);
        for (std::size_t k = 0; k < count; ++k) {
            const std::uint32_t lane = lanes[k].binary;
            pcl_int child = 0; // a light's is set by write(), on every core
            if (!(lane & kLeaf))
                child = !lanes[k].splits && cluster(lane) ? -1 - add_cluster(lane)
                                                          : static_cast<pcl_int>(lay_out(lane, depth + 1));
            Lanes& l = lanes_[index];
            l.binary[k] = lane;
            l.code[k] = static_cast<pcl_int>(lanes[k].bits | (lanes[k].length << 8));
            l.child[k] = child;
            l.count = static_cast<std::uint32_t>(k + 1);
        }
        return index;
    }

    // Whether a lane over binary node b is split in a node over more than eight lights. A
    // half that is one light needs no node below, and halves that lie apart (lamps in
    // different places) sharpen the weights; halves that touch (neighbouring triangles of
    // one surface) would each still need a node, emptier than the one the whole lane leads
    // to. Over more than eight lights such a lane is split all the same, unless it is a
    // cluster.
    bool worth_splitting(std::uint32_t b) const
    {
        const BinaryNode& n = binary_.nodes[b];
        if ((n.child[0] & kLeaf) || (n.child[1] & kLeaf))
            return true;
        const Box first = binary_.of(n.child[0]).box, second = binary_.of(n.child[1]).box;
        if (glm::any(glm::lessThan(first.hi, second.lo)) || glm::any(glm::lessThan(second.hi, first.lo)))
            return true;
        return n.lights > LIGHT_TREE_WIDTH && !cluster(b);
    }

    // Whether the lane over binary node b, in a node over more than eight lights and not
    // worth splitting (neighbouring lights of one surface), ends the descent as a cluster:
    // where its lights face within kClusterCone of one direction, so that power alone
    // weighs them nearly as their importance would at any point that sees them, and where
    // the cluster array can still index its header. Up to eight such lights always do;
    // up to LIGHT_TREE_CLUSTER_MAX where their box is small beside every light's (its
    // diagonal at most 1 / kClusterExtent of theirs), so that a large panel of many
    // triangles is not picked among by power alone from close by.
    bool cluster(std::uint32_t b) const
    {
        const std::uint32_t lights = binary_.nodes[b].lights;
        if (lights > LIGHT_TREE_CLUSTER_MAX || tree_.cluster.size() > LIGHT_TREE_MAX_LEAF_INDEX)
            return false;
        const Bounds bounds = binary_.of(b);
        const glm::dvec3 diagonal = bounds.box.hi - bounds.box.lo;
        return bounds.cone.theta_o <= kClusterCone &&
               (lights <= LIGHT_TREE_WIDTH || glm::dot(diagonal, diagonal) <= cluster_extent2_);
    }

    // Appends binary node b's lights to the clusters' array (LightTreeClusterLight: a
    // header, then the lights in the order of their indices, each with its slot of their
    // alias table by power and its probability as the kernel realizes that table: the
    // slot's share of 1 / lights kept with the keep stored as a float, the rest of it
    // given to its alias); returns the leaf that stands for them.
    pcl_int add_cluster(std::uint32_t b)
    {
        const BinaryNode& n = binary_.nodes[b];
        std::array<std::pair<std::uint32_t, double>, LIGHT_TREE_CLUSTER_MAX> lights;
        for (std::uint32_t i = 0; i < n.lights; ++i)
            lights[i] = {binary_.records[n.first + i].light, binary_.records[n.first + i].phi};
        std::sort(lights.begin(), lights.begin() + n.lights);
        std::vector<double> power(n.lights);
        for (std::uint32_t i = 0; i < n.lights; ++i)
            power[i] = lights[i].second;
        const AliasTable table = build_alias_table(power);
        const double slot = 1.0 / static_cast<double>(n.lights);
        std::vector<double> pmf(n.lights, 0.0);
        for (std::uint32_t i = 0; i < n.lights; ++i) {
            const double keep = static_cast<float>(table.keep[i]);
            pmf[i] += slot * keep;
            pmf[table.alias[i]] += slot * (1.0 - keep);
        }
        const auto header = static_cast<pcl_int>(tree_.cluster.size());
        tree_.cluster.push_back({static_cast<pcl_int>(n.lights), 1.0f, 1.0f, 0});
        for (std::uint32_t i = 0; i < n.lights; ++i)
            tree_.cluster.push_back({static_cast<pcl_int>(lights[i].first), static_cast<pcl_float>(pmf[i]),
                                     static_cast<pcl_float>(table.keep[i]), static_cast<pcl_int>(table.alias[i])});
        return header | LIGHT_TREE_CLUSTER;
    }

    void write(std::size_t index)
    {
        tree_.nodes[index] = LightTreeNode{}; // lanes past the last: no light, no power
        const Lanes& l = lanes_[index];
        for (std::size_t k = 0; k < l.count; ++k) {
            const std::uint32_t lane = l.binary[k];
            set_lane(index, k, binary_.of(lane));
            tree_.nodes[index].code.s[k] = l.code[k];
            tree_.nodes[index].child.s[k] =
                lane & kLeaf ? -1 - static_cast<pcl_int>(binary_.records[lane & ~kLeaf].light) : l.child[k];
        }
    }

private:
    void set_lane(std::size_t index, std::size_t k, const Bounds& b)
    {
        LightTreeNode& node = tree_.nodes[index];
        const glm::dvec3 centre = (b.box.lo + b.box.hi) * 0.5;
        const glm::vec3 c(centre);
        // Of the sphere around the float centre that holds the box: the farthest corner's
        // squared distance, (dx^2 + dy^2) + dz^2, from the farther side on each axis (the
        // rounded sums grow with their terms, so this is the largest of the eight).
        const glm::dvec3 to_lo = b.box.lo - glm::dvec3(c), to_hi = b.box.hi - glm::dvec3(c);
        const glm::dvec3 d2 = glm::max(to_lo * to_lo, to_hi * to_hi);
        const double radius2 = std::max(0.0, d2.x + d2.y + d2.z);
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
        // The mean axis, for the estimate between the bounds; none where the cone holds
        // every direction (its lights' axes say nothing: a point light's is arbitrary) or
        // where lights emit from both sides.
        float along = 0.0f, across = 0.0f;
        if (!b.two_sided && b.cone.cos_o > -1.0 && b.phi > 0.0) {
            const glm::dvec3 m = b.axis_sum / b.phi;
            const double a = glm::dot(m, b.cone.axis);
            along = static_cast<float>(a);
            across = static_cast<float>(glm::length(m - a * b.cone.axis));
        }
        node.mean_axis_along.s[k] = along;
        node.mean_axis_across.s[k] = across;
    }

    const BinaryTree& binary_;
    LightTree& tree_;
    std::vector<Lanes> lanes_;     // by node
    double cluster_extent2_ = 0.0; // the largest squared diagonal of a cluster of more than eight
};

// Whether a light has bounds in the tree: every kind with a position. The others
// (directional, environment) are infinite, picked beside it.
bool has_position(const Light& l)
{
    return l.type == LIGHT_TRIANGLE || l.type == LIGHT_SPHERE || l.type == LIGHT_POINT || l.type == LIGHT_SPOT ||
           l.type == LIGHT_RECT_SPOT;
}

LightBounds bounds_of(const Light& l, double power)
{
    LightBounds b;
    b.phi = power;
    if (!has_position(l)) {
        b.infinite = true;
        return b;
    }
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
    }
    return b;
}

// The lights a tree is built over, as bounds made beforehand.
struct BoundsList {
    const std::vector<LightBounds>& lights;
    std::size_t size() const { return lights.size(); }
    bool infinite(std::size_t i) const { return lights[i].infinite; }
    double power(std::size_t i) const { return lights[i].phi; }
    const LightBounds& bounds(std::size_t i) const { return lights[i]; }
};

// The lights a tree is built over, as light records and their powers: each light's bounds
// are made where its build record is, on every core, never all at once.
struct LightList {
    const std::vector<Light>& lights;
    const std::vector<double>& powers;
    std::size_t size() const { return lights.size(); }
    bool infinite(std::size_t i) const { return !has_position(lights[i]); }
    double power(std::size_t i) const { return powers[i]; }
    LightBounds bounds(std::size_t i) const { return bounds_of(lights[i], powers[i]); }
};

template <class Lights>
LightTree build(const Lights& lights)
{
    LightTree tree;
    if (lights.size() > std::size_t(LIGHT_TREE_MAX_LEAF_INDEX) + 1)
        throw Error("the light tree takes at most " + std::to_string(LIGHT_TREE_MAX_LEAF_INDEX + 1) + " lights, not " +
                    std::to_string(lights.size()));
    tree.trails.assign(lights.size(), 0);
    std::vector<std::uint32_t> order;
    order.reserve(lights.size());
    double bounded_power = 0.0, infinite_power = 0.0;
    for (std::size_t i = 0; i < lights.size(); ++i) {
        if (lights.infinite(i)) {
            tree.infinite.push_back(static_cast<pcl_int>(i));
            tree.trails[i] = kLightTreeInfiniteTrail;
            infinite_power += lights.power(i);
        } else {
            order.push_back(static_cast<std::uint32_t>(i));
            bounded_power += lights.power(i);
        }
    }
    if (!tree.infinite.empty())
        tree.infinite_pick =
            order.empty()
                ? 1.0
                : (infinite_power + bounded_power > 0.0 ? infinite_power / (infinite_power + bounded_power) : 0.5);
    if (!order.empty()) {
        Builder builder(lights, order, tree.trails);
        const std::uint32_t root = builder.build();
        Collapser(builder.tree(), tree).collapse(root);
    }
    return tree;
}

} // namespace

LightCone cone_union(const LightCone& a, const LightCone& b)
{
    return unite(Cone(a), Cone(b)).light_cone();
}

LightTree build_light_tree(const std::vector<LightBounds>& lights)
{
    return build(BoundsList{lights});
}

LightTree build_light_tree(const std::vector<Light>& lights, const std::vector<double>& power)
{
    return build(LightList{lights, power});
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
