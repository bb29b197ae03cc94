// The needle's frame (thesis Fig. 6.5): a point as d_needle along the axis from the tip and d_perp
// across it, and back; and how an offset across the needle turns when the needle turns (§6.7:
// "computing d_perp and d_needle relative to the old needle position, and using them as
// coordinates relative to the new needle position"). Vectors are Eigen's.
#pragma once

#include <Eigen/Core>

#include "needle.hpp"

namespace sxk::needle {

inline Eigen::Vector3d vec(const Point& p) { return {p[0], p[1], p[2]}; }
inline Point point(const Eigen::Vector3d& v) { return {v[0], v[1], v[2]}; }

struct Frame {
    Eigen::Vector3d tip;
    Eigen::Vector3d axis;  // unit, base to tip
    double length = 0;

    explicit Frame(const Needle& needle);
    // d_needle: signed distance from the tip along the axis.
    double along(const Point& x) const { return (vec(x) - tip).dot(axis); }
    // d_perp: the offset of x from the axis, perpendicular to it.
    Point perp(const Point& x) const;
    // tip + along * axis + perp
    Point place(double along, const Point& perp) const;
};

// The offset `perp` (across the axis of `from`) turned by the least rotation that takes from's
// axis to to's, then made exactly perpendicular to to's axis (rounding). A reversal of the needle
// (axes opposite) has no least rotation: the offset is only made perpendicular.
Point turned(const Point& perp, const Frame& from, const Frame& to);

}  // namespace sxk::needle
