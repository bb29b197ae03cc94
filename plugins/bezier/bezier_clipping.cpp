// Triangular Bézier clipping (bezier_clipping.hpp; Roth's thesis §6.2–6.4).
//
// Everything runs in the ray's frame: a control point b becomes q = (n0·(b−o), n1·(b−o), e·(b−o))
// with e the unit ray direction and n0, n1 unit and orthogonal to e and to each other. (q.x, q.y)
// are the distances to the two planes of eq. 6.2 (the 2D patch d of eq. 6.4, whose zero is the
// hit) and q.z is the position along the ray, so the range of q.z over a sub-net bounds the ray
// parameter of any hit inside it (convex hull property): the search keeps the nearest hit and
// skips sub-patches that lie beyond it. The frame is a change of orthonormal basis, so
// |(q.x, q.y)| is exactly the distance of b from the ray's line.
//
// Roth builds n0 from o × e; we take any vector orthogonal to e instead (the smallest component
// of e swapped out), which is the same construction without the special case for o ∥ e.
#include "bezier_clipping.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <span>
#include <utility>
#include <vector>

#include "de_casteljau.hpp"
#include "vector3.hpp"

namespace sxk::bezier {
namespace {

using Vec = Point;  // a control point in the ray frame

// The orthonormal frame (n0, n1, e) of a ray.
struct RayFrame {
    Vec n0, n1, e;
    double direction_length = 1;
};

RayFrame frame_of(const Ray& ray) {
    RayFrame f;
    f.direction_length = norm(ray.direction);
    f.e = scaled(1 / f.direction_length, ray.direction);
    // the axis along which e is smallest is far from parallel to e
    int axis = 0;
    for (int a = 1; a < 3; ++a)
        if (std::abs(f.e[a]) < std::abs(f.e[axis])) axis = a;
    Vec helper{0, 0, 0};
    helper[axis] = 1;
    const Vec c = cross(f.e, helper);
    f.n0 = scaled(1 / norm(c), c);
    f.n1 = cross(f.e, f.n0);
    return f;
}

// A sub-net waiting on the search stack: its control points (ray frame) at `offset` in the
// workspace's arena, and the sub-triangle of the original domain it covers: domain point
// (r, s, t) of the sub-net is r R + s S + t T of the original patch.
struct Candidate {
    std::size_t offset = 0;
    std::array<Barycentric, 3> corners;
    double tolerance = 0;  // stop clipping when the candidate is smaller than this (domain units)
};

Barycentric combine(const std::array<Barycentric, 3>& corners, const Barycentric& x) {
    Barycentric y{};
    for (int c = 0; c < 3; ++c) y[c] = x[0] * corners[0][c] + x[1] * corners[1][c] + x[2] * corners[2][c];
    return y;
}

// Per-thread buffers, so that a call allocates nothing once a thread has traced a few rays (the
// renderer calls intersect() for every leaf every ray meets).
struct Workspace {
    // control points of the candidates pushed during one call; append-only within the call, so
    // reordering the stack never moves a net
    std::vector<Vec> arena;
    std::vector<Candidate> stack;
    std::vector<Vec> original, clipped, quarter, jet;
    NetScratch nets;
};

// Smallest x where the convex hull of the points (c/n, y), y in [lo_c, hi_c] for each column c,
// meets the axis y = 0 (§6.2.4, Fig. 6.8); values within eps of 0 count as 0 (a ray through a
// patch's edge). When column 0 reaches the axis the answer is 0. When it lies below, the
// leftmost crossing is on the upper hull of the column maxima h_c, found by one monotone chain
// pass; above, on the lower hull of the minima l_c (the same pass on -l_c). +infinity when the
// hull misses the axis.
double hull_minimum(int n, const double* lo, const double* hi, double eps) {
    if (lo[0] <= eps && hi[0] >= -eps) return 0;
    const bool below = hi[0] < -eps;
    auto y = [&](int c) { return below ? hi[c] : -lo[c]; };
    // upper hull of (c, y(c)), c = 0..n, in column units
    int hull[65];
    std::vector<int> heap;
    int* chain = hull;
    if (n + 1 > 65) {
        heap.resize(static_cast<std::size_t>(n + 1));
        chain = heap.data();
    }
    int size = 0;
    for (int c = 0; c <= n; ++c) {
        while (size >= 2) {
            const int a = chain[size - 2], b = chain[size - 1];
            // b is not above the segment a -> c: it is no vertex of the upper hull
            if ((b - a) * (y(c) - y(a)) - (y(b) - y(a)) * (c - a) >= 0) {
                --size;
            } else {
                break;
            }
        }
        chain[size++] = c;
    }
    for (int e = 1; e < size; ++e) {
        const int a = chain[e - 1], b = chain[e];
        const double ya = y(a), yb = y(b);
        // b within eps below the axis counts as on it: the crossing is then b itself, not the
        // extension of a -> b past it
        if (yb >= -eps) return std::min<double>(b, a + (b - a) * (-ya) / (yb - ya)) / n;
    }
    return std::numeric_limits<double>::infinity();
}

// The direction of row `row` of control points running parallel to one domain edge (row 0 is the
// edge itself): the 2D vector from its first to its last point. A collapsed edge has none, and
// Roth (§6.4) then takes the neighbouring control points; rows further in follow if those
// coincide too. Any line through the origin keeps every hit (the hull property holds for each),
// so the choice only affects how fast clipping converges.
enum class Side { r, s, t };

std::array<std::size_t, 2> row_ends(Side side, int n, int row) {
    switch (side) {
        case Side::r:  // i = row: j + k = n - row, from (j = n - row, k = 0) to (j = 0, k = n - row)
            return {net_index(n, n - row, 0), net_index(n, 0, n - row)};
        case Side::s:  // j = row: from k = 0 to k = n - row
            return {net_index(n, row, 0), net_index(n, row, n - row)};
        case Side::t:  // k = row: from j = 0 to j = n - row
            return {net_index(n, 0, row), net_index(n, n - row, row)};
    }
    return {0, 0};
}

// Unit normal (a, b) of the line L for one side: the distance of q to L is a q.x + b q.y.
std::array<double, 2> line_normal(Side side, int n, std::span<const Vec> q, double extent) {
    for (int row = 0; row < n; ++row) {
        const auto [from, to] = row_ends(side, n, row);
        const double dx = q[to][0] - q[from][0], dy = q[to][1] - q[from][1];
        const double length = std::sqrt(dx * dx + dy * dy);
        if (length > 1e-12 * extent && length > 0) return {-dy / length, dx / length};
    }
    return {1, 0};
}

double magnitude(double x, double y) { return std::sqrt(x * x + y * y); }  // hypot without its overflow care

struct Minima {
    double r = 0, s = 0, t = 0;
};

// r_min, s_min, t_min of the net (§6.2.3): for each side, the distances to its line L projected
// along that side's edges onto the side's parameter, and the hull's first crossing.
Minima clip(int n, std::span<const Vec> q, double extent, double eps) {
    std::array<double, 64> lo_buffer, hi_buffer;  // filled per side below
    std::vector<double> lo_heap, hi_heap;
    double* lo = lo_buffer.data();
    double* hi = hi_buffer.data();
    if (n + 1 > static_cast<int>(lo_buffer.size())) {
        lo_heap.resize(static_cast<std::size_t>(n + 1));
        hi_heap.resize(static_cast<std::size_t>(n + 1));
        lo = lo_heap.data();
        hi = hi_heap.data();
    }
    Minima minima;
    for (const Side side : {Side::r, Side::s, Side::t}) {
        const auto [a, b] = line_normal(side, n, q, extent);
        std::fill(lo, lo + n + 1, std::numeric_limits<double>::infinity());
        std::fill(hi, hi + n + 1, -std::numeric_limits<double>::infinity());
        for (int k = 0; k <= n; ++k)
            for (int j = 0; j <= n - k; ++j) {
                const Vec& p = q[net_index(n, j, k)];
                const double d = a * p[0] + b * p[1];
                const int column = side == Side::r ? n - j - k : side == Side::s ? j : k;
                lo[column] = std::min(lo[column], d);
                hi[column] = std::max(hi[column], d);
            }
        const double m = hull_minimum(n, lo, hi, eps);
        (side == Side::r ? minima.r : side == Side::s ? minima.s : minima.t) = m;
        // the ray misses: the other sides cannot change that
        if (!(m <= 1 + 1e-6)) return {m, m, m};
    }
    return minima;
}

// The net's value and its derivatives along the domain directions (1, 0, -1) and (0, 1, -1) at x:
// de Casteljau down to degree 1, whose three points give both (the derivative of a degree-n
// patch along d is n times the degree-1 net's combination with d).
struct Jet {
    Vec value, along_r, along_s;
};

Jet jet(int n, const std::vector<Vec>& net, const Barycentric& x, std::vector<Vec>& scratch) {
    scratch.assign(net.begin(), net.end());
    if (n == 0) return {scratch[0], {0, 0, 0}, {0, 0, 0}};
    for (int m = n; m > 1; --m) de_casteljau_step(m, scratch.data(), x, scratch.data());
    const Vec& pr = scratch[0];  // b_100
    const Vec& ps = scratch[1];  // b_010
    const Vec& pt = scratch[2];  // b_001
    Jet j;
    for (int c = 0; c < 3; ++c) {
        j.value[c] = x[0] * pr[c] + x[1] * ps[c] + x[2] * pt[c];
        j.along_r[c] = n * (pr[c] - pt[c]);
        j.along_s[c] = n * (ps[c] - pt[c]);
    }
    return j;
}

}  // namespace

std::optional<PatchHit> intersect(const TriangularPatch& patch, const Ray& ray, const ClippingOptions& options) {
    const int n = patch.degree();
    const std::size_t count = net_size(n);
    const RayFrame f = frame_of(ray);
    if (!(f.direction_length > 0) || !std::isfinite(f.direction_length)) return std::nullopt;
    thread_local Workspace w;

    // the original net in the ray frame, and its size for the relative tolerances
    w.original.resize(count);
    Vec lower{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
              std::numeric_limits<double>::infinity()};
    Vec upper = scaled(-1, lower);
    for (std::size_t p = 0; p < count; ++p) {
        const Point& b = patch.control_points()[p];
        const Vec d = minus(b, ray.origin);
        w.original[p] = {dot(f.n0, d), dot(f.n1, d), dot(f.e, d)};
        for (int c = 0; c < 3; ++c) {
            lower[c] = std::min(lower[c], b[c]);
            upper[c] = std::max(upper[c], b[c]);
        }
    }
    const double extent = std::max(norm(minus(upper, lower)), std::numeric_limits<double>::min());
    const double eps = 1e-13 * extent;  // distances this small are zero (rays through an edge)

    // along-ray window of the hits we want, in frame units (q.z)
    const double z_near = ray.t_near * f.direction_length;
    double z_far = ray.t_far * f.direction_length;

    w.arena.assign(w.original.begin(), w.original.end());
    w.stack.clear();
    w.stack.push_back({0, {Barycentric{1, 0, 0}, Barycentric{0, 1, 0}, Barycentric{0, 0, 1}},
                       options.parametric_tolerance});
    auto push = [&](const std::vector<Vec>& net, const std::array<Barycentric, 3>& corners, double tolerance) {
        w.stack.push_back({w.arena.size(), corners, tolerance});
        w.arena.insert(w.arena.end(), net.begin(), net.end());
    };

    std::optional<PatchHit> best;
    int iterations = 0;
    while (!w.stack.empty() && iterations++ < options.max_iterations) {
        const Candidate candidate = w.stack.back();
        w.stack.pop_back();
        // the candidate's net, read in place: valid until the first push below may move the arena
        const std::span<const Vec> net(w.arena.data() + candidate.offset, count);

        // the net's box (in scalars: the compiler keeps them in registers)
        double x_lo = net[0][0], x_hi = x_lo, y_lo = net[0][1], y_hi = y_lo, z_lo = net[0][2], z_hi = z_lo;
        for (const Vec& p : net) {
            x_lo = std::min(x_lo, p[0]);
            x_hi = std::max(x_hi, p[0]);
            y_lo = std::min(y_lo, p[1]);
            y_hi = std::max(y_hi, p[1]);
            z_lo = std::min(z_lo, p[2]);
            z_hi = std::max(z_hi, p[2]);
        }
        if (z_lo > z_far || z_hi < z_near) continue;
        // the ray's line misses the net's box: no hit (cheaper than the three hulls)
        if (x_lo > eps || x_hi < -eps || y_lo > eps || y_hi < -eps) continue;
        const double net_extent = std::max({x_hi - x_lo, y_hi - y_lo, z_hi - z_lo});

        Minima m = clip(n, net, extent, eps);
        const double sum = m.r + m.s + m.t;
        if (!std::isfinite(sum) || sum > 1 + 1e-6) continue;
        if (sum > 1) {
            // a point, perhaps overshot by rounding (a hit at a corner of the candidate: the hulls
            // only touch the axis there); Newton's residual below decides
            m.r /= sum;
            m.s /= sum;
            m.t /= sum;
        }

        // the candidate sub-triangle r >= r_min, s >= s_min, t >= t_min (Fig. 6.7)
        const std::array<Barycentric, 3> clipped{Barycentric{1 - m.s - m.t, m.s, m.t},
                                                 Barycentric{m.r, 1 - m.r - m.t, m.t},
                                                 Barycentric{m.r, m.s, 1 - m.r - m.s}};
        const std::array<Barycentric, 3> corners{combine(candidate.corners, clipped[0]),
                                                 combine(candidate.corners, clipped[1]),
                                                 combine(candidate.corners, clipped[2])};
        double size = 0;
        for (int c = 0; c < 3; ++c)
            for (int a = 0; a < 3; ++a)
                for (int b = a + 1; b < 3; ++b) size = std::max(size, std::abs(corners[a][c] - corners[b][c]));

        // small in the domain, or already a point in space (a collapsed corner maps a large part of the
        // domain to almost one point): the hit, polished by Newton steps on the original net
        if (size < candidate.tolerance || net_extent * (1 - m.r - m.s - m.t) < eps) {
            Barycentric at = combine(corners, {1.0 / 3, 1.0 / 3, 1.0 / 3});
            Jet j = jet(n, w.original, at, w.jet);
            const double converged = 1e-3 * options.distance_tolerance * extent;
            for (int step_count = 0; step_count < options.newton_steps; ++step_count) {
                if (magnitude(j.value[0], j.value[1]) <= converged) break;
                // J (dr, ds) = -(x, y) with J = [along_r along_s] in the two plane distances, solved
                // as (J^T J + mu) (dr, ds) = -J^T (x, y): Newton where J is regular, and where an edge
                // collapsed (J of rank 1 next to it) the least-squares step along the direction
                // that still moves the surface
                // (divided by the trace of J^T J, so that its determinant cannot overflow)
                double a11 = j.along_r[0] * j.along_r[0] + j.along_r[1] * j.along_r[1];
                double a12 = j.along_r[0] * j.along_s[0] + j.along_r[1] * j.along_s[1];
                double a22 = j.along_s[0] * j.along_s[0] + j.along_s[1] * j.along_s[1];
                const double trace = a11 + a22;
                if (!(trace > 0) || !std::isfinite(trace)) break;
                a11 /= trace, a12 /= trace, a22 /= trace;
                constexpr double mu = 1e-14;
                const double det = (a11 + mu) * (a22 + mu) - a12 * a12;
                if (!(det > 0)) break;
                const double g1 = (j.along_r[0] * j.value[0] + j.along_r[1] * j.value[1]) / trace;
                const double g2 = (j.along_s[0] * j.value[0] + j.along_s[1] * j.value[1]) / trace;
                const double dr = (-(a22 + mu) * g1 + a12 * g2) / det;
                const double ds = (a12 * g1 - (a11 + mu) * g2) / det;
                if (!std::isfinite(dr) || !std::isfinite(ds)) break;
                const Barycentric next{at[0] + dr, at[1] + ds, at[2] - dr - ds};
                // Newton left the neighbourhood clipping proved: keep the clipped point
                if (std::abs(dr) + std::abs(ds) > 10 * std::max(size, options.parametric_tolerance)) break;
                const Jet polished = jet(n, w.original, next, w.jet);
                if (magnitude(polished.value[0], polished.value[1]) > magnitude(j.value[0], j.value[1])) break;
                at = next;
                j = polished;
            }
            // Newton may step just outside the domain (a hit on an edge, or next to a collapsed
            // edge where a whole strip of the domain maps to nearly one point): the nearest domain
            // point, if it is still on the ray, is the hit
            if (at[0] < 0 || at[1] < 0 || at[2] < 0) {
                for (double& c : at) c = std::max(c, 0.0);
                const double total = at[0] + at[1] + at[2];
                for (double& c : at) c /= total;
                j = jet(n, w.original, at, w.jet);
            }
            if (magnitude(j.value[0], j.value[1]) > options.distance_tolerance * extent) {
                // not on the ray yet: a wrong intersection (§6.3: the hulls reached the axis, the
                // patch does not), or a grazing ray where Newton cannot polish. Clip on, finer.
                if (candidate.tolerance > 1e-13 && size > 0) {
                    subdivide_net(n, w.original, corners, w.clipped, w.nets);
                    push(w.clipped, corners, candidate.tolerance * 1e-3);
                }
                continue;
            }
            const double z = j.value[2];
            if (z < z_near || z > z_far) continue;
            PatchHit hit;
            hit.t = z / f.direction_length;
            hit.at = at;
            // the normal from the frame derivatives, mapped back to world axes; the patch's own
            // normal() where they are parallel (a collapsed corner): its limit from inside
            const Vec nf = cross(j.along_r, j.along_s);
            const double length = norm(nf);
            if (length > 1e-12 * norm(j.along_r) * norm(j.along_s) && length > 0) {
                for (int c = 0; c < 3; ++c)
                    hit.normal[c] = (nf[0] * f.n0[c] + nf[1] * f.n1[c] + nf[2] * f.e[c]) / length;
            } else {
                hit.normal = patch.normal(at);
            }
            best = hit;
            z_far = z;  // only nearer hits from now on
            continue;
        }

        subdivide_net(n, net, clipped, w.clipped, w.nets);
        if (m.r + m.s + m.t >= 0.5) {
            // clipped enough: go on with the candidate
            push(w.clipped, corners, candidate.tolerance);
            continue;
        }
        // too little clipped, perhaps because two hits are in the candidate: split it into four at
        // the edge midpoints (§6.2.3); the one whose net comes nearest along the ray goes on the
        // stack last, to be visited first (a hit there prunes the others)
        const Barycentric r{1, 0, 0}, s{0, 1, 0}, t{0, 0, 1};
        const Barycentric rs{0.5, 0.5, 0}, st{0, 0.5, 0.5}, rt{0.5, 0, 0.5};
        const std::array<std::array<Barycentric, 3>, 4> quarters{{{r, rs, rt}, {rs, s, st}, {rt, st, t}, {rt, rs, st}}};
        std::array<double, 4> nearest{};
        const std::size_t first = w.stack.size();
        for (std::size_t c = 0; c < 4; ++c) {
            subdivide_net(n, w.clipped, quarters[c], w.quarter, w.nets);
            nearest[c] = std::numeric_limits<double>::infinity();
            for (const Vec& p : w.quarter) nearest[c] = std::min(nearest[c], p[2]);
            std::array<Barycentric, 3> child_corners;
            for (int a = 0; a < 3; ++a) child_corners[a] = combine(corners, quarters[c][a]);
            push(w.quarter, child_corners, candidate.tolerance);
        }
        // order the four records by decreasing nearest z (their nets stay where they are in the arena)
        std::array<std::size_t, 4> order{0, 1, 2, 3};
        std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return nearest[a] > nearest[b]; });
        const std::array<Candidate, 4> records{w.stack[first], w.stack[first + 1], w.stack[first + 2],
                                               w.stack[first + 3]};
        for (std::size_t c = 0; c < 4; ++c) w.stack[first + c] = records[order[c]];
    }
    return best;
}

}  // namespace sxk::bezier
