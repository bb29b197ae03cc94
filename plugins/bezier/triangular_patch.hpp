// Triangular Bernstein–Bézier patches of any degree (Roth's thesis §4.4): evaluation by de
// Casteljau, blossoms, directional derivatives and normals, subdivision with respect to three
// arbitrary barycentric points (eq. 4.33), degree elevation, and the conversion of a tensor
// product patch into two triangular ones (Goldman–Filip), the teapot's route from 32 bicubic
// to 64 sextic triangular patches. The ray tracer of issue 5 builds on this; the plug-in's
// Embree and rendering parts are not written yet.
//
//   control net of degree n = 2 (b_ijk, i + j + k = n):      b_002
//                                                            /    \          (r, s, t): the
//   b(r,s,t) = sum n!/(i!j!k!) r^i s^j t^k b_ijk          b_101   b_011      barycentric
//                                                        /    \  /    \      coordinates of a
//                                                     b_200 - b_110 - b_020   domain point
#pragma once

#include <array>
#include <cstddef>
#include <span>
#include <vector>

#include "sxk/mesh.hpp"  // sxk::Point

namespace sxk::bezier {

// Barycentric coordinates (r, s, t): points sum to 1, directions (differences of points) to 0.
using Barycentric = std::array<double, 3>;

class TriangularPatch {
public:
    // The patch of degree n whose control points are given in index order (index()); throws
    // std::invalid_argument when their number is not (n+1)(n+2)/2.
    TriangularPatch(int degree, std::vector<Point> control_points);

    int degree() const { return m_degree; }
    std::span<const Point> control_points() const { return m_points; }
    // Position of b_ijk (i = n - j - k) in control_points(); control_point(j, k) is b_ijk.
    static std::size_t index(int degree, int j, int k);
    const Point& control_point(int j, int k) const { return m_points[index(m_degree, j, k)]; }

    // One de Casteljau step with respect to x (a point or a direction): the patch of degree
    // n - 1 with c_ijk = x_r b_(i+1)jk + x_s b_i(j+1)k + x_t b_ij(k+1). Degree 0 has no step.
    TriangularPatch step(const Barycentric& x) const;
    // The blossom b[x_1, ..., x_L] (L <= n): L steps, a patch of degree n - L.
    TriangularPatch blossom(std::span<const Barycentric> arguments) const;

    Point evaluate(const Barycentric& at) const;
    // Derivative along the barycentric direction d (its components sum to 0): n b[d, at^(n-1)].
    Point derivative(const Barycentric& at, const Barycentric& direction) const;
    // Unit normal (D_u x D_v with u = (-1,1,0), v = (-1,0,1)). Where the two derivatives are
    // parallel or zero (a corner whose edge collapsed to a point, as at the teapot's lid knob),
    // the normal is the limit from inside: evaluated at points approaching `at` from the
    // centroid, the first that gives a normal. Zero only for a patch that is flat everywhere.
    Point normal(const Barycentric& at) const;

    // The same surface over the sub-triangle (r, s, t) of the domain (eq. 4.33):
    // c_ijk = b[r^i, s^j, t^k]. r, s, t need not lie inside the domain (extrapolation).
    TriangularPatch subdivided(const Barycentric& r, const Barycentric& s, const Barycentric& t) const;
    // The same surface with degree n + 1.
    TriangularPatch elevated() const;

private:
    int m_degree;
    std::vector<Point> m_points;
};

// A tensor product Bézier patch of degree m in u and n in v: points[a * (n + 1) + b] is P_ab,
// P(u, v) = sum B_a^m(u) B_b^n(v) P_ab over [0,1]^2.
struct TensorPatch {
    int degree_u = 0, degree_v = 0;
    std::vector<Point> points;
    Point evaluate(double u, double v) const;
};

// The two triangular patches of degree m + n that together are the tensor patch: the first
// over the domain triangle (0,0), (1,0), (1,1) of (u, v), the second over (0,0), (1,1), (0,1),
// their barycentric coordinates in that corner order (Goldman–Filip, by products of Bernstein
// polynomials: every control point a convex combination of the P_ab with binomial weights,
// (m+1)(m+2)(n+1)(n+2)/4 terms per half, about 0.3 ms for 20 x 20; docs/performance.md).
std::array<TriangularPatch, 2> to_triangular(const TensorPatch& patch);
// Every tensor patch's two halves, in order: patch p becomes triangular patches 2p and 2p + 1
// (the teapot's 32 bicubic patches its 64 sextic ones).
std::vector<TriangularPatch> to_triangular(const std::vector<TensorPatch>& patches);

}  // namespace sxk::bezier
