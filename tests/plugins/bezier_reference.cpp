// The reference intersector (bezier_reference.hpp).
//
// Bisection is written here on flat arrays rather than with TriangularPatch::subdivided, for two
// reasons. The oracle shares no code with what it checks: Bézier clipping subdivides through
// the same de Casteljau kernels (de_casteljau.hpp) as subdivided(), so a slip there would hide
// from a reference built on them. And it is cheaper: two subdivided() calls (one bisection) took
// 4.0 us on a sextic teapot patch, a whole bisection step here (pyramid, both children, their
// boxes) 1.4 us (RelWithDebInfo-like -O2, 2026-12-01); the 512² test runs some 7M of them.
#include "bezier_reference.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>
#include <utility>
#include <vector>

#include "sxk/predicates.hpp"

namespace sxk::bezier::oracle {
namespace {

Point minus(const Point& a, const Point& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Point cross(const Point& a, const Point& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double dot(const Point& a, const Point& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

// TriangularPatch::index, here where the compiler sees it: it is defined out of line, and the
// call was a seventh of the descent's time.
inline std::size_t net_index(int degree, int j, int k) {
    return static_cast<std::size_t>(k * (degree + 1) - k * (k - 1) / 2 + j);
}

using Box = ReferencePatches::Box;

Box box_of(const Point* points, std::size_t count, double widen) {
    Box box{points[0], points[0]};
    for (std::size_t i = 1; i < count; ++i)
        for (std::size_t q = 0; q < 3; ++q) {
            box.lower[q] = std::min(box.lower[q], points[i][q]);
            box.upper[q] = std::max(box.upper[q], points[i][q]);
        }
    for (std::size_t q = 0; q < 3; ++q) box.lower[q] -= widen, box.upper[q] += widen;
    return box;
}

// The ray parameter where the ray enters the box, if it meets it within [t_low, t_high].
std::optional<double> entry(const Box& box, const Ray& ray, double t_low, double t_high) {
    for (std::size_t q = 0; q < 3; ++q) {
        if (ray.direction[q] == 0) {
            if (ray.origin[q] < box.lower[q] || ray.origin[q] > box.upper[q]) return std::nullopt;
            continue;
        }
        const double inverse = 1 / ray.direction[q];
        double a = (box.lower[q] - ray.origin[q]) * inverse, b = (box.upper[q] - ray.origin[q]) * inverse;
        if (a > b) std::swap(a, b);
        t_low = std::max(t_low, a);
        t_high = std::min(t_high, b);
        if (t_low > t_high) return std::nullopt;
    }
    return t_low;
}

// Whether segment p q meets the closed triangle a b c, exactly. A segment in the triangle's plane
// (or a triangle without area) counts as a miss: see the header.
bool segment_crosses_triangle(const Point& p, const Point& q, const Point& a, const Point& b, const Point& c) {
    const Sign side_p = orient3d(a, b, c, p), side_q = orient3d(a, b, c, q);
    if (side_p == side_q) return false;  // one side, or both in the plane
    // the line p q passes through the closed triangle when it turns the same way (or not at
    // all) around each of its edges
    const Sign around[3] = {orient3d(p, q, a, b), orient3d(p, q, b, c), orient3d(p, q, c, a)};
    bool positive = false, negative = false;
    for (Sign s : around) positive |= s == Sign::positive, negative |= s == Sign::negative;
    return !(positive && negative);
}

// One ray's descent through the patches: per level a de Casteljau pyramid and the two children's
// nets, allocated once per ray for the largest degree (uninitialised: no per-ray clearing).
class Descent {
public:
    Descent(int max_degree, const Ray& ray, const ReferenceOptions& options, double widen, double t_far,
            ReferenceStats& stats)
        : m_ray(ray), m_options(options), m_widen(widen), m_t_far(t_far), m_stats(stats) {
        m_near_point = at(ray.t_near);
        m_far_point = at(t_far);
        const auto levels = static_cast<std::size_t>(options.depth + 1);
        m_pyramid_size = static_cast<std::size_t>((max_degree + 1) * (max_degree + 2) * (max_degree + 3) / 6);
        m_max_count = static_cast<std::size_t>((max_degree + 1) * (max_degree + 2) / 2);
        m_pyramids.reset(new Point[levels * m_pyramid_size]);
        m_children.reset(new Point[levels * 2 * m_max_count]);
    }

    // The nearest hit so far: ray parameter and patch.
    std::optional<ReferenceHit> nearest() const { return m_best; }
    double t_high() const { return m_best ? std::min(m_best->t, m_t_far) : m_t_far; }

    // Descends into a patch whose box the ray enters at `enter`.
    void descend(std::uint32_t patch, const TriangularPatch& net, double enter) {
        if (enter > t_high()) return;
        m_patch = patch;
        m_degree = net.degree();
        m_count = net.control_points().size();
        visit(net.control_points().data(), 0);
    }

private:
    // Descends into the node with control net `net` at `level`; the caller checked its box.
    void visit(const Point* net, int level) {
        if (level == m_options.depth) {
            leaf(net);
            return;
        }
        ++m_stats.bisections;
        Point* children = &m_children[static_cast<std::size_t>(level) * 2 * m_max_count];
        bisect(net, &m_pyramids[static_cast<std::size_t>(level) * m_pyramid_size], children,
               children + m_max_count);
        std::optional<double> enter[2];
        for (int child = 0; child < 2; ++child)
            enter[child] = entry(box_of(children + child * m_max_count, m_count, m_widen), m_ray, m_ray.t_near,
                                 t_high());
        // nearer child first, so that the farther one is often pruned by a hit found in it
        const int first = enter[0] && enter[1] && *enter[1] < *enter[0] ? 1 : 0;
        for (int child : {first, 1 - first})
            if (enter[child] && *enter[child] <= t_high()) visit(children + child * m_max_count, level + 1);
    }

    Point at(double t) const {
        return {m_ray.origin[0] + t * m_ray.direction[0], m_ray.origin[1] + t * m_ray.direction[1],
                m_ray.origin[2] + t * m_ray.direction[2]};
    }
    static const Point& point(const Point* net, int degree, int j, int k) { return net[net_index(degree, j, k)]; }

    // Halves the node (P0, P1, P2) at the midpoint m of P1 P2 (newest-vertex bisection):
    // pyramid level a is b[m^a] (degree n - a); child (m, P0, P1) takes b[m^a P0^i P1^j] from
    // level a, child (m, P2, P0) takes b[m^a P2^k P0^i] from level a.
    void bisect(const Point* net, Point* pyramid, Point* first, Point* second) const {
        const int n = m_degree;
        std::copy(net, net + m_count, pyramid);
        Point* level_start = pyramid;
        for (int a = 0; a <= n; ++a) {
            const int degree = n - a;  // of pyramid level a
            for (int k = 0; k <= degree; ++k)
                for (int j = 0; j <= degree - k; ++j) {
                    const int i = degree - j - k;
                    const Point& p = point(level_start, degree, j, k);
                    // child (m, P0, P1): multiplicities (a, i, j), those with k = 0
                    if (k == 0) first[net_index(n, i, j)] = p;
                    // child (m, P2, P0): multiplicities (a, k, i), those with j = 0
                    if (j == 0) second[net_index(n, k, i)] = p;
                }
            if (degree == 0) break;
            Point* next = level_start + (degree + 1) * (degree + 2) / 2;
            for (int k = 0; k < degree; ++k)
                for (int j = 0; j < degree - k; ++j) {
                    const Point& s = point(level_start, degree, j + 1, k);
                    const Point& t = point(level_start, degree, j, k + 1);
                    next[net_index(degree - 1, j, k)] = {0.5 * (s[0] + t[0]), 0.5 * (s[1] + t[1]),
                                                                      0.5 * (s[2] + t[2])};
                }
            level_start = next;
        }
    }

    // The distance of the net from the linear patch of its corners (flatness, see the header).
    double deviation(const Point* net) const {
        const int n = m_degree;
        const Point& c0 = point(net, n, 0, 0);
        const Point& c1 = point(net, n, n, 0);
        const Point& c2 = point(net, n, 0, n);
        double worst = 0;
        for (int k = 0; k <= n; ++k)
            for (int j = 0; j <= n - k; ++j) {
                const double wi = double(n - j - k) / n, wj = double(j) / n, wk = double(k) / n;
                const Point& b = point(net, n, j, k);
                double squared = 0;
                for (std::size_t q = 0; q < 3; ++q) {
                    const double d = b[q] - (wi * c0[q] + wj * c1[q] + wk * c2[q]);
                    squared += d * d;
                }
                worst = std::max(worst, squared);
            }
        return std::sqrt(worst);
    }

    void leaf(const Point* net) {
        ++m_stats.leaves;
        const double flatness = m_degree > 1 ? deviation(net) : 0;
        m_stats.worst_deviation = std::max(m_stats.worst_deviation, flatness);
        if (flatness > m_options.tolerance) ++m_stats.coarse_leaves;
        const int n = m_degree;
        const Point& a = point(net, n, 0, 0);
        const Point& b = point(net, n, n, 0);
        const Point& c = point(net, n, 0, n);
        if (!segment_crosses_triangle(m_near_point, m_far_point, a, b, c)) return;
        // t by the plane of the triangle: only reported, never decides hit or miss
        const Point normal = cross(minus(b, a), minus(c, a));
        const double along = dot(m_ray.direction, normal);
        double t = along != 0 ? dot(minus(a, m_ray.origin), normal) / along : m_ray.t_near;
        t = std::clamp(t, m_ray.t_near, m_t_far);
        if (!m_best || t < m_best->t) m_best = ReferenceHit{t, m_patch};
    }

    const Ray& m_ray;
    const ReferenceOptions& m_options;
    double m_widen, m_t_far;
    ReferenceStats& m_stats;
    Point m_near_point{}, m_far_point{};
    std::size_t m_pyramid_size = 0, m_max_count = 0;
    std::unique_ptr<Point[]> m_pyramids, m_children;
    int m_degree = 0;
    std::size_t m_count = 0;
    std::uint32_t m_patch = 0;
    std::optional<ReferenceHit> m_best;
};

}  // namespace

void ReferenceStats::add(const ReferenceStats& other) {
    rays += other.rays;
    bisections += other.bisections;
    leaves += other.leaves;
    coarse_leaves += other.coarse_leaves;
    worst_deviation = std::max(worst_deviation, other.worst_deviation);
}

ReferencePatches::ReferencePatches(std::vector<TriangularPatch> patches) : m_patches(std::move(patches)) {
    if (m_patches.empty()) return;
    m_box = box_of(m_patches[0].control_points().data(), 1, 0);
    for (const TriangularPatch& patch : m_patches) {
        const Box own = box_of(patch.control_points().data(), patch.control_points().size(), 0);
        m_boxes.push_back(own);
        for (std::size_t q = 0; q < 3; ++q) {
            m_box.lower[q] = std::min(m_box.lower[q], own.lower[q]);
            m_box.upper[q] = std::max(m_box.upper[q], own.upper[q]);
        }
        m_max_degree = std::max(m_max_degree, patch.degree());
    }
    const Point size = minus(m_box.upper, m_box.lower);
    m_diagonal = std::sqrt(dot(size, size));
    // widened boxes: rounding in the slab test never prunes a node the segment touches
    for (Box& box : m_boxes)
        for (std::size_t q = 0; q < 3; ++q) box.lower[q] -= widening(), box.upper[q] += widening();
}

std::optional<ReferenceHit> reference_intersect(const ReferencePatches& patches, const Ray& ray,
                                                const ReferenceOptions& options, ReferenceStats* stats) {
    if (!(options.tolerance > 0))
        throw std::invalid_argument("reference_intersect: the tolerance must be positive");
    if (options.depth < 0 || options.depth > 60 || options.depth % 2 != 0)
        throw std::invalid_argument("reference_intersect: the depth must be even and in [0, 60]");
    if (ray.direction == Point{0, 0, 0}) throw std::invalid_argument("reference_intersect: zero ray direction");
    ReferenceStats own;
    ReferenceStats& counted = stats ? *stats : own;
    ++counted.rays;
    if (patches.patches().empty()) return std::nullopt;

    // an infinite ray ends where it leaves the box of all control points, widened so that the
    // segment's far end never lies on a leaf
    const Box& all = patches.box();
    const double margin = 1e-3 * patches.diagonal();
    double t_far = ray.t_far;
    if (!std::isfinite(t_far)) {
        t_far = std::numeric_limits<double>::infinity();
        for (std::size_t q = 0; q < 3; ++q) {
            if (ray.direction[q] == 0) continue;
            const double bound = ray.direction[q] > 0 ? all.upper[q] + margin : all.lower[q] - margin;
            t_far = std::min(t_far, (bound - ray.origin[q]) / ray.direction[q]);
        }
    }
    if (!(t_far > ray.t_near)) return std::nullopt;

    // patches in the order the ray enters their boxes: a near hit prunes the farther patches
    std::vector<std::pair<double, std::uint32_t>> order;
    for (std::size_t index = 0; index < patches.patches().size(); ++index)
        if (const auto enter = entry(patches.boxes()[index], ray, ray.t_near, t_far))
            order.emplace_back(*enter, static_cast<std::uint32_t>(index));
    std::sort(order.begin(), order.end());
    Descent descent(patches.max_degree(), ray, options, patches.widening(), t_far, counted);
    for (const auto& [enter, index] : order) descent.descend(index, patches.patches()[index], enter);
    return descent.nearest();
}

}  // namespace sxk::bezier::oracle
