// Where a line crossing a triangle's plane passes, by orientation signs only: the building block
// of the segment/triangle and triangle/tetrahedron tests (predicates.hpp). Include only from .cpp
// files in core/src.
#pragma once

#include "sxk/predicates.hpp"

namespace sxk::detail {

inline int sign_of(Sign s) { return static_cast<int>(s); }

// The line through x and y passes through the closed triangle (p, q, r). Preconditions: the
// triangle is proper (not collinear) and the line crosses its plane in one point (x and y are
// not both in the plane, and the caller knows the crossing lies between them when it asks of a
// segment). The crossing lies in the triangle when the line turns the same way about its three
// edges: orient3d(x, y, p, q), (x, y, q, r), (x, y, r, p) agree, a zero meaning the crossing is
// on that edge's line (two zeros: on a corner; three cannot happen across a proper triangle).
inline bool line_through_triangle(const Point& x, const Point& y, const Point& p, const Point& q, const Point& r) {
    const int u = sign_of(orient3d(x, y, p, q));
    const int v = sign_of(orient3d(x, y, q, r));
    if (u * v < 0) return false;
    const int w = sign_of(orient3d(x, y, r, p));
    return u * w >= 0 && v * w >= 0;
}

}  // namespace sxk::detail
