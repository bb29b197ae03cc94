// Where a moving line scalpel first meets an edge (thesis §5.3.2, Fig. 5.15, eq. 5.1): the blade
// runs from its handle h to its tip t, and over a movement both ends move linearly,
//
//     h(s) = h0 + s (h1 - h0),   t(s) = t0 + s (t1 - t0),   s in [0, 1] (the movement's time),
//
// so the blade sweeps a bilinear patch. It meets the edge a-b at time s where a point of the blade
// h(s) + lambda (t(s) - h(s)) is a point of the edge a + mu (b - a), lambda and mu in [0, 1].
//
// The thesis solves eq. 5.1 as a linear system in (lambda gamma, lambda, gamma, mu) with a
// one-dimensional kernel, which fails where the 3 x 3 matrix is singular ("various failures" when
// events coincide). Here the time comes first: the blade meets the edge's line only when a, b, h(s)
// and t(s) are coplanar, det[h(s) - a, t(s) - a, b - a] = 0, a quadratic in s whose roots in [0, 1]
// are taken in order; at each the two segments are intersected in their common plane. When the
// determinant vanishes for every s (the whole movement in one plane with the edge, or the blade
// parallel to it throughout) the first contact is found in that plane instead: an end of the blade
// crossing the edge, or an end of the edge crossing the blade. Quantities, not decisions: computed
// in doubles with tolerances relative to the configuration's size.
#pragma once

#include <array>
#include <optional>
#include <span>

#include "sxk/mesh.hpp"

namespace sxk::delaunaycut {

struct SweepHit {
    double time = 0;         // s: 0 at the movement's start, 1 at its end
    double along_blade = 0;  // lambda: 0 at the handle, 1 at the tip
    double along_edge = 0;   // mu: 0 at a, 1 at b
    Point point{};           // where they meet
};

// The first meeting of the moving blade with the segment a-b, or none in [0, 1].
std::optional<SweepHit> first_sweep_hit(const Point& h0, const Point& t0, const Point& h1, const Point& t1,
                                        const Point& a, const Point& b);

// Thesis Fig. 5.11, d_max: how far each end of the blade (h, t) may move without the blade meeting
// the line of any of `edges` (the edges opposite the active node): the least distance between the
// blade's line and those lines. The thesis' argument: if the ends move by p and q, |p|, |q| < d_max,
// the blade's point lambda h + (1 - lambda) t moves by lambda p + (1 - lambda) q, shorter than
// d_max, so it cannot reach a line at least d_max from the blade's line. Infinity for no edges.
double largest_safe_move(const Point& h, const Point& t, std::span<const std::array<Point, 2>> edges);

}  // namespace sxk::delaunaycut
