// The 3-vector operations the plug-in needs on sxk::Point beyond sxk/point_math.hpp's. Internal
// to the plug-in and its tests.
#pragma once

#include <cmath>

#include "sxk/mesh.hpp"  // sxk::Point
#include "sxk/point_math.hpp"

namespace sxk::bezier {

inline double distance(const Point& a, const Point& b) { return norm(minus(a, b)); }
// a / |a|, or the zero vector when a is zero.
inline Point unit_or_zero(const Point& a) {
    const double length = norm(a);
    return length > 0 ? scaled(1 / length, a) : Point{0, 0, 0};
}

}  // namespace sxk::bezier
