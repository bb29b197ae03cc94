// Arithmetic of points and vectors as the mesh stores them (sxk::Point, three doubles): the one
// copy the kernel, the operations and the plug-ins use, so that the same expression gives the
// same bits everywhere (a tool's geometry and the checks it is tested against agree exactly).
// Plain doubles, no exactness: orientation and the other signs come from sxk/predicates.hpp.
#pragma once

#include <cmath>

#include "sxk/mesh.hpp"

namespace sxk {

inline Point minus(const Point& a, const Point& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline Point plus(const Point& a, const Point& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
inline Point scaled(double s, const Point& a) { return {s * a[0], s * a[1], s * a[2]}; }
inline double dot(const Point& a, const Point& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline Point cross(const Point& a, const Point& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
// sqrt(dot(a, a)): no guard against overflow of the squares (std::hypot has one, and other bits)
inline double norm(const Point& a) { return std::sqrt(dot(a, a)); }

}  // namespace sxk
