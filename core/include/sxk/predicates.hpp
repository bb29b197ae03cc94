// Exact geometric predicates (CGAL Exact_predicates_inexact_constructions_kernel, behind one
// internal header: no CGAL type appears here). Inputs are doubles; results are exact signs.
#pragma once

#include <span>

#include "sxk/config.hpp"
#include "sxk/mesh.hpp"

namespace sxk {

enum class Sign : int { negative = -1, zero = 0, positive = 1 };

// Sign of det[b-a, c-a]: positive when a, b, c turn counter-clockwise (x, y only).
SXK_API Sign orient2d(const Point& a, const Point& b, const Point& c);
// Sign of det[b-a, c-a, d-a]: positive when d lies on the side of plane (a,b,c) that
// sees a, b, c clockwise... i.e. the tetrahedron (a,b,c,d) has positive volume.
SXK_API Sign orient3d(const Point& a, const Point& b, const Point& c, const Point& d);
// Positive when d lies inside the circle through a, b, c, which must be counter-clockwise.
SXK_API Sign incircle(const Point& a, const Point& b, const Point& c, const Point& d);
// Positive when e lies inside the sphere through a, b, c, d, which must be positively oriented.
SXK_API Sign insphere(const Point& a, const Point& b, const Point& c, const Point& d,
                      const Point& e);

// The empty-circle test of two triangles (a, b, c) and (b, a, d) that share the edge a-b, unfolded
// into one plane about that edge (thesis §5.3.1: "the incident triangles are unfolded to be
// coplanar, and then the two-dimensional criterion is used"): positive when the angles at c and d
// opposite the edge sum to more than pi (d would lie inside the circle through a, b and c: the edge
// is not locally Delaunay), zero when they sum to pi exactly, negative when less. Any ambient
// dimension; in the plane, for a convex quadrilateral a d b c, it is incircle(a, b, c, d). Decided
// exactly: sin(gamma_c + gamma_d) has the sign of |u x v| (s . t) + (u . v) |s x t| (u, v the
// edges from c, s, t those from d), whose sign the squares of its two terms decide when theirs
// differ. A degenerate triangle (c or d on the line a-b) counts as an angle of 0 or pi.
SXK_API Sign unfolded_incircle(const Point& a, const Point& b, const Point& c, const Point& d);

// True when a, b, c lie on one line (exactly; any ambient dimension).
SXK_API bool collinear(const Point& a, const Point& b, const Point& c);
// Sign of the dot product of the normals (b-a)x(c-a) and (e-d)x(f-d) of two triangles in
// space: negative when the triangles face opposite ways (a surface folding over an edge). A
// degree-4 polynomial no orientation test decides; evaluated exactly.
SXK_API Sign normal_alignment(const Point& a, const Point& b, const Point& c, const Point& d,
                              const Point& e, const Point& f);

enum class Positions { reference, deformed };

// "reference" or "deformed", as messages name the set.
inline const char* to_string(Positions positions) {
    return positions == Positions::reference ? "reference" : "deformed";
}
// The position of v in `positions`.
inline const Point& position(const Mesh& mesh, VertexId v, Positions positions) {
    return positions == Positions::reference ? mesh.reference(v) : mesh.deformed(v);
}

// Compares the distances of a and b from the plane through p, q, r, exactly: negative when a
// is nearer, positive when b is, zero when they are equally far (or p, q, r are collinear).
// For a segment ab that crosses the plane it tells which end is nearer the crossing, measured
// along the segment (the crossing divides ab in the ratio of the two distances): the node a
// snap cut marks for a cut edge (thesis §3.2.1), with ties (exact halves) left to the caller.
SXK_API Sign compare_distances_to_plane(const Point& a, const Point& b, const Point& p, const Point& q,
                                        const Point& r);

// The closed segment [a, b] meets the closed triangle (p, q, r) in space, exactly: what a snap cut
// asks of every mesh edge near a sweep triangle (thesis §3.2.1). A degenerate triangle (collinear
// corners) is the segment between its two farthest corners; a = b is a point.
SXK_API bool segment_meets_triangle(const Point& a, const Point& b, const Point& p, const Point& q,
                                    const Point& r);

// The closed triangle (a, b, c) meets the closed tetrahedron (p0, p1, p2, p3), exactly: what the
// spatial index asks of every element along a scalpel's sweep. Decided by orientation signs, each
// through its static filter, with an early exit for a tetrahedron on one side of the triangle's
// plane. A collinear triangle is the segment between its two farthest corners; a flat
// tetrahedron meets nothing (the index's elements_hit_by_triangle skips flat elements too).
SXK_API bool triangle_meets_tetrahedron(const Point& a, const Point& b, const Point& c, const Point& p0,
                                        const Point& p1, const Point& p2, const Point& p3);

// The closed segment [a, b] meets the closed tetrahedron (p0, p1, p2, p3), exactly, by orientation
// signs: the elements a scalpel's blade lies in. a = b is a point; a flat tetrahedron meets
// nothing (as in triangle_meets_tetrahedron).
SXK_API bool segment_meets_tetrahedron(const Point& a, const Point& b, const Point& p0, const Point& p1,
                                       const Point& p2, const Point& p3);

// Exact orientation of element t in the chosen positions, taking the simplex sign into account:
// positive means the element is correctly oriented (counter-clockwise triangle, positive
// volume tetrahedron). Only defined when topological == ambient dimension; for triangle
// surfaces in 3D it returns Sign::positive unless the triangle is degenerate (collinear
// vertices: Sign::zero).
SXK_API Sign element_orientation(const Mesh& mesh, ElementId t,
                                 Positions positions = Positions::deformed);
// The same for a simplex at given points: points[j] is the position of s.vertex(j). What moves
// and cuts use to ask how an element would be oriented after a change of positions.
SXK_API Sign simplex_orientation(const Simplex& s, int ambient_dimension, std::span<const Point* const> points);

}  // namespace sxk
