// Exact tests on triangles in space (collinear, normal_alignment), filtered: a rounded normal
// with a forward error bound answers most calls, the exact predicate the rest. Used by the
// surface operations (flip_edge.cpp, collapse_edge.cpp) and by simplex_orientation
// (orientation_checks.hpp) for triangles in space.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

#include "sxk/predicates.hpp"

namespace sxk::detail {

// sxk::collinear and sxk::normal_alignment are exact but not cheap: normal_alignment builds CGAL
// lazy-exact points (heap nodes) on every call, and the two were ~20% of a surface flip and of a
// surface collapse (perf on tools/bench/surface_ops, femur boundary). A surface operation asks
// them about the same few triangles again and again, so it computes each triangle's normal once
// in doubles with a forward error bound and calls the exact predicate only when the bound cannot
// decide. The answers are those of the exact predicates, always.
//
// Error bound (u = 2^-53, round to nearest; x = q - p, y = r - p): n_z = x_x y_y - x_y y_x is
// computed with two rounded differences, one rounded product and one rounded subtraction per
// monomial, so |n~_z - n_z| <= ((1+u)^4 - 1)(|x_x y_y| + |x_y y_x|) + (underflow: < 2^-1073)
// < 5u P_z + 1e-300, P_z the "permanent" |x_x y_y| + |x_y y_x| (its rounded value is within a
// few u of the exact one; 8u leaves the margin). For the dot product of two such normals, each
// product n0_i n1_i is off by <= P0_i e1_i + e0_i P1_i + e0_i e1_i ~ 8.02u P0_i P1_i and the
// product and two sums add ~3.01u, so |D~ - D| < 11.1u sum P0_i P1_i + (underflow terms
// <= 2^-1072 * 6 * 2e120 when every coordinate difference is <= 1e60, i.e. < 1e-200); the test
// uses 16u and 1e-200 and falls back to the exact predicate outside that range (and on NaN or
// infinity, which fail every comparison below).
struct TriangleNormal {
    std::array<double, 3> normal{};     // (q - p) x (r - p), rounded
    std::array<double, 3> permanent{};  // |products| summed per component, rounded
    bool in_range = false;              // every coordinate difference <= 1e60 in magnitude
};

inline TriangleNormal triangle_normal(const Point& p, const Point& q, const Point& r) {
    const double x0 = q[0] - p[0], x1 = q[1] - p[1], x2 = q[2] - p[2];
    const double y0 = r[0] - p[0], y1 = r[1] - p[1], y2 = r[2] - p[2];
    TriangleNormal t;
    t.normal = {x1 * y2 - x2 * y1, x2 * y0 - x0 * y2, x0 * y1 - x1 * y0};
    t.permanent = {std::abs(x1 * y2) + std::abs(x2 * y1), std::abs(x2 * y0) + std::abs(x0 * y2),
                   std::abs(x0 * y1) + std::abs(x1 * y0)};
    const double largest = std::max({std::abs(x0), std::abs(x1), std::abs(x2), std::abs(y0),
                                     std::abs(y1), std::abs(y2)});
    t.in_range = largest <= 1e60;  // false for NaN
    return t;
}

// True when the rounded normal proves the exact one is not zero (the triangle is not flat).
inline bool certainly_not_collinear(const TriangleNormal& t) {
    constexpr double eight_u = 0x1p-50;
    for (std::size_t i = 0; i < 3; ++i)
        if (std::abs(t.normal[i]) > eight_u * t.permanent[i] + 1e-300) return true;
    return false;
}

// sxk::collinear(p, q, r), exactly; t = triangle_normal(p, q, r).
inline bool collinear_filtered(const Point& p, const Point& q, const Point& r, const TriangleNormal& t) {
    return !certainly_not_collinear(t) && collinear(p, q, r);
}

// sxk::normal_alignment(a, b, c, d, e, f), exactly; s = triangle_normal(a, b, c),
// t = triangle_normal(d, e, f).
inline Sign normal_alignment_filtered(const Point& a, const Point& b, const Point& c,
                                      const TriangleNormal& s, const Point& d, const Point& e,
                                      const Point& f, const TriangleNormal& t) {
    if (s.in_range && t.in_range) {
        constexpr double sixteen_u = 0x1p-49;
        const double dot = s.normal[0] * t.normal[0] + s.normal[1] * t.normal[1] + s.normal[2] * t.normal[2];
        const double permanent = s.permanent[0] * t.permanent[0] + s.permanent[1] * t.permanent[1] +
                                 s.permanent[2] * t.permanent[2];
        const double bound = sixteen_u * permanent + 1e-200;
        if (dot > bound) return Sign::positive;
        if (dot < -bound) return Sign::negative;
    }
    return normal_alignment(a, b, c, d, e, f);
}

}  // namespace sxk::detail
