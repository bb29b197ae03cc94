// The moving blade against an edge (scalpel_sweep.hpp, thesis eq. 5.1).
#include "scalpel_sweep.hpp"

#include "sxk/point_math.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

namespace sxk::delaunaycut {

namespace {

using V = Point;

// The roots of c2 s^2 + c1 s + c0 in [0, 1] (within `slack`), ascending; `zero`: what counts as a
// vanishing coefficient. A discriminant negative by rounding only is a double root.
std::vector<double> roots_in_unit(double c2, double c1, double c0, double zero) {
    std::vector<double> roots;
    if (std::abs(c2) <= zero) {
        if (std::abs(c1) > zero) roots.push_back(-c0 / c1);
    } else {
        const double disc = c1 * c1 - 4 * c2 * c0;
        const double scale = c1 * c1 + std::abs(4 * c2 * c0);
        if (disc >= 0) {
            // the stable pair: no cancellation between -c1 and the root of the discriminant
            const double q = -0.5 * (c1 + std::copysign(std::sqrt(disc), c1));
            roots.push_back(q / c2);
            if (q != 0) roots.push_back(c0 / q);
        } else if (disc >= -1e-12 * scale) {
            roots.push_back(-c1 / (2 * c2));
        }
    }
    const double slack = 1e-12;
    std::vector<double> kept;
    for (const double s : roots)
        if (s >= -slack && s <= 1 + slack) kept.push_back(std::clamp(s, 0.0, 1.0));
    std::sort(kept.begin(), kept.end());
    return kept;
}

struct Frame {
    V h0, t0, dh, dt, a, v;  // the movement and the edge (v = b - a)
    double tolerance = 0;    // distances that count as touching
    V handle(double s) const { return plus(h0, scaled(s, dh)); }
    V tip(double s) const { return plus(t0, scaled(s, dt)); }
};

// Where the blade at time s meets the edge, if it does (the two segments in their common plane, or
// overlapping on one line).
std::optional<SweepHit> meeting_at(const Frame& f, double s) {
    const V p = f.handle(s), u = minus(f.tip(s), p), w = minus(p, f.a);
    const double uu = dot(u, u), vv = dot(f.v, f.v), uv = dot(u, f.v);
    const double det = uu * vv - uv * uv;
    double lambda = 0, mu = 0;
    if (det > 1e-14 * uu * vv) {
        // least squares of p + lambda u = a + mu v: the normal equations
        lambda = (uv * dot(f.v, w) - vv * dot(u, w)) / det;
        mu = (uu * dot(f.v, w) - uv * dot(u, w)) / det;
    } else {
        // parallel: on one line, the overlap's first point along the blade
        if (norm(cross(f.v, w)) > f.tolerance * std::sqrt(vv) || vv == 0) return std::nullopt;
        if (uu == 0) {
            lambda = 0;
            mu = -dot(w, f.v) / vv;
        } else {
            const double la = -dot(w, u) / uu, lb = dot(minus(plus(f.a, f.v), p), u) / uu;
            lambda = std::max(0.0, std::min(la, lb));
            if (lambda > std::max(la, lb)) return std::nullopt;
            mu = dot(minus(plus(p, scaled(lambda, u)), f.a), f.v) / vv;
        }
    }
    const double slack = 1e-9;
    if (lambda < -slack || lambda > 1 + slack || mu < -slack || mu > 1 + slack) return std::nullopt;
    lambda = std::clamp(lambda, 0.0, 1.0);
    mu = std::clamp(mu, 0.0, 1.0);
    const V on_blade = plus(p, scaled(lambda, u)), on_edge = plus(f.a, scaled(mu, f.v));
    if (norm(minus(on_blade, on_edge)) > 1e3 * f.tolerance) return std::nullopt;
    return SweepHit{s, lambda, mu, {on_edge[0], on_edge[1], on_edge[2]}};
}

// The times at which a vector quadratic q2 s^2 + q1 s + q0 vanishes in [0, 1] (roots of its
// largest component, checked against the others by the caller).
std::vector<double> vector_roots(const V& q2, const V& q1, const V& q0, double zero) {
    std::size_t k = 0;
    double largest = -1;
    for (std::size_t i = 0; i < 3; ++i) {
        const double m = std::max({std::abs(q2[i]), std::abs(q1[i]), std::abs(q0[i])});
        if (m > largest) largest = m, k = i;
    }
    if (largest <= zero) return {0.0};  // vanishes throughout: from the start
    return roots_in_unit(q2[k], q1[k], q0[k], zero);
}

}  // namespace

std::optional<SweepHit> first_sweep_hit(const Point& h0, const Point& t0, const Point& h1, const Point& t1,
                                        const Point& a, const Point& b) {
    Frame f{h0, t0, minus(h1, h0), minus(t1, t0), a, minus(b, a)};
    double size = 0;
    for (const Point* p : {&h0, &t0, &h1, &t1, &b})
        for (std::size_t k = 0; k < 3; ++k) size = std::max(size, std::abs((*p)[k] - a[k]));
    if (size == 0) return SweepHit{0, 0, 0, a};
    f.tolerance = 1e-12 * size;
    // det[h(s) - a, t(s) - a, b - a] = (H x T) . E with H = h0 - a + s dh, T = t0 - a + s dt
    const V H0 = minus(h0, a), T0 = minus(t0, a);
    const double c0 = dot(cross(H0, T0), f.v);
    const double c1 = dot(plus(cross(H0, f.dt), cross(f.dh, T0)), f.v);
    const double c2 = dot(cross(f.dh, f.dt), f.v);
    const double zero = 1e-12 * size * size * size;
    if (std::max({std::abs(c0), std::abs(c1), std::abs(c2)}) > zero) {
        for (const double s : roots_in_unit(c2, c1, c0, zero))
            if (auto hit = meeting_at(f, s)) return hit;
        return std::nullopt;
    }
    // In one plane with the edge throughout (or parallel to it): the first contact is an end of
    // one segment crossing the other.
    std::vector<double> times_found{0.0};  // meeting from the start
    // an end of the blade on the edge's line: (end(s) - a) x v = 0, linear in s
    for (const auto& [start, change] : {std::pair{H0, f.dh}, std::pair{T0, f.dt}})
        for (const double s : vector_roots({0, 0, 0}, cross(change, f.v), cross(start, f.v), zero / size))
            times_found.push_back(s);
    // an end of the edge on the blade's line: u(s) x (e - h(s)) = 0, quadratic in s
    const V u0 = minus(t0, h0), du = minus(f.dt, f.dh);
    for (const V& e : {f.a, plus(f.a, f.v)}) {
        const V w0 = minus(e, h0);
        const V q2 = scaled(-1, cross(du, f.dh));
        const V q1 = minus(cross(du, w0), cross(u0, f.dh));
        for (const double s : vector_roots(q2, q1, cross(u0, w0), zero / size)) times_found.push_back(s);
    }
    std::sort(times_found.begin(), times_found.end());
    for (const double s : times_found)
        if (auto hit = meeting_at(f, s)) return hit;
    return std::nullopt;
}

double largest_safe_move(const Point& h, const Point& t, std::span<const std::array<Point, 2>> edges) {
    double safe = std::numeric_limits<double>::infinity();
    const V u = minus(t, h);
    for (const auto& [x, y] : edges) {
        const V v = minus(y, x), w = minus(x, h);
        const V n = cross(u, v);
        const double nn = norm(n), uu = norm(u), vv = norm(v);
        double d = 0;
        if (nn > 1e-12 * uu * vv) {
            d = std::abs(dot(w, n)) / nn;  // skew or crossing lines: along their common normal
        } else if (uu > 0) {
            d = norm(cross(w, u)) / uu;  // parallel lines: from x to the blade's line
        } else if (vv > 0) {
            d = norm(cross(w, v)) / vv;  // a blade of no length: from h to the edge's line
        } else {
            d = norm(w);
        }
        safe = std::min(safe, d);
    }
    return safe;
}

}  // namespace sxk::delaunaycut
