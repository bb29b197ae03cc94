// Orientation signs on CGAL's points, shared by the exact tests of a triangle and of a segment
// against a tetrahedron (triangle_meets_tetrahedron.cpp, segment_meets_tetrahedron.cpp).
#pragma once

#include <array>
#include <cstddef>

#include "cgal_kernel.hpp"

namespace sxk::detail {

// The signs are taken on CGAL's points, so that each is the kernel's inlined orientation with its
// static filter: through sxk::orient3d, a library call converting its four points each time, the
// triangle test cost 364 ns per meeting pair instead of 302 (tools/bench/sweep_tests).
inline int orientation_sign(const Kernel::Point_3& a, const Kernel::Point_3& b, const Kernel::Point_3& c,
                            const Kernel::Point_3& d) {
    return static_cast<int>(CGAL::orientation(a, b, c, d));  // NEGATIVE -1, COPLANAR 0, POSITIVE 1
}

// The line through x and y passes through the closed triangle (p, q, r). Preconditions: the
// triangle is proper (not collinear) and the line crosses its plane in one point (x and y are
// not both in the plane, and the caller knows the crossing lies between them when it asks of a
// segment). The crossing lies in the triangle when the line turns the same way about its three
// edges: orient3d(x, y, p, q), (x, y, q, r), (x, y, r, p) agree, a zero meaning the crossing is
// on that edge's line (two zeros: on a corner; three cannot happen across a proper triangle).
inline bool line_through_triangle(const Kernel::Point_3& x, const Kernel::Point_3& y, const Kernel::Point_3& p,
                                  const Kernel::Point_3& q, const Kernel::Point_3& r) {
    const int u = orientation_sign(x, y, p, q);
    const int v = orientation_sign(x, y, q, r);
    if (u * v < 0) return false;
    const int w = orientation_sign(x, y, r, p);
    return u * w >= 0 && v * w >= 0;
}

// Face i of the tetrahedron (p0, p1, p2, p3) is opposite corner i, ordered so that
// orient3d(face, p_i) has the sign of orient3d(p0, p1, p2, p3): an even permutation each.
inline constexpr std::array<std::array<std::size_t, 3>, 4> faces{{{1, 3, 2}, {0, 2, 3}, {0, 3, 1}, {0, 1, 2}}};

}  // namespace sxk::detail
