// A segment's walk through a planar triangle mesh, and where a vertex may go:
// what both cutting methods ask of the mesh near the scalpel (planar_cut.hpp). Every decision is an
// exact orientation test (orient2d) on the deformed positions; only the points where a segment
// crosses an edge are computed in doubles.
#pragma once

#include <array>
#include <cmath>
#include <optional>
#include <vector>

#include "sxk/mesh.hpp"
#include "sxk/outcome.hpp"
#include "sxk/predicates.hpp"
#include "sxk/traversal.hpp"

namespace sxk::delaunaycut {

inline const Point& at(const Mesh& mesh, VertexId v) { return mesh.deformed(v); }
inline double distance(const Point& a, const Point& b) { return std::hypot(a[0] - b[0], a[1] - b[1]); }
inline Point lerp(const Point& a, const Point& b, double s) {
    return {a[0] + s * (b[0] - a[0]), a[1] + s * (b[1] - a[1]), 0};
}
// Twice the signed area of (a, b, c), in doubles: a quantity, for where things cross.
inline double area2(const Point& a, const Point& b, const Point& c) {
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

// The corners of triangle t counter-clockwise (as every triangle of a valid oriented planar mesh
// is), starting at `first` (a corner of t).
std::array<VertexId, 3> corners_from(const Mesh& mesh, ElementId t, VertexId first);

bool on_boundary(const Mesh& mesh, VertexId v);
// The edge u-v, as one of its faces (the mesh on its left when it is on the boundary), or none.
std::optional<FaceId> edge_face(const Mesh& mesh, VertexId u, VertexId v);

// Where the segment from `from` to `to` leaves triangle t, which holds `from`.
struct Leaving {
    enum class Kind {
        stays,      // `to` is in t: the segment ends there
        edge,       // it crosses edge (u, v) at `point`, `on_edge` of the way from u to v
        vertex,     // it passes exactly through corner `u`
    } kind = Kind::stays;
    VertexId u = invalid_id, v = invalid_id;
    double on_edge = 0;
    Point point{};
};
// `behind`: a corner the segment comes from (its two edges are not where it leaves), or invalid_id;
// `came_through`: the edge it entered t by, as the corner opposite it, or invalid_id.
Leaving leave_triangle(const Mesh& mesh, ElementId t, const Point& from, const Point& to, VertexId behind,
                       VertexId came_through);

// The triangle around v that the segment from `from` (a point of star(v)) towards `to` goes into:
// it holds `from` and the segment does not leave it at once. When there is none (`from` on the
// star's rim and the segment going out of it, or out of the mesh at a boundary vertex) a triangle
// around v that holds `from`, which the segment then leaves where it starts; invalid_id when no
// triangle around v holds `from`.
ElementId triangle_entered(const Mesh& mesh, VertexId v, const Point& from, const Point& to);

// The point of the segment a-b where it crosses the segment c-d (both in doubles), as the fraction
// of the way from a to b; none when they do not cross (or are parallel).
std::optional<double> crossing(const Point& a, const Point& b, const Point& c, const Point& d);

// Moves v to p in the deformed positions and to the matching point in the reference ones: p itself
// where the two position sets agree on star(v) (a mesh no simulation deformed), else p's
// barycentric coordinates in the triangle of star(v) that holds it (or that it is least outside
// of, the coordinates extended), mapped to that triangle's reference corners. Refuses (nothing
// moves) when a triangle of the star would be inverted or flat in either set.
Outcome<Done> place_vertex(Mesh& mesh, VertexId v, const Point& p);

}  // namespace sxk::delaunaycut
