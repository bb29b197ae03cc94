// The few 3-vector operations the plug-in needs on sxk::Point (std::array<double, 3>), in one
// place. Internal to the plug-in and its tests.
#pragma once

#include <cmath>

#include "sxk/mesh.hpp"  // sxk::Point

namespace sxk::bezier {

inline Point minus(const Point& a, const Point& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline Point scaled(double s, const Point& a) { return {s * a[0], s * a[1], s * a[2]}; }
inline double dot(const Point& a, const Point& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline Point cross(const Point& a, const Point& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline double norm(const Point& a) { return std::sqrt(dot(a, a)); }
inline double distance(const Point& a, const Point& b) { return norm(minus(a, b)); }
// a / |a|, or the zero vector when a is zero.
inline Point unit_or_zero(const Point& a) {
    const double length = norm(a);
    return length > 0 ? scaled(1 / length, a) : Point{0, 0, 0};
}

}  // namespace sxk::bezier
