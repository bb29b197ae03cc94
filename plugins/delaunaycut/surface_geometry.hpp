// What the surface cutter (surface_cut.hpp) asks of the surface near the blade: where the blade
// pierces triangles, where a new node goes on a triangle, and where an existing node may move.
// Decisions that keep the mesh valid are exact (segment_meets_triangle, collinear,
// normal_alignment); the points where things meet are computed in doubles.
#pragma once

#include <cmath>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "surface_cut.hpp"
#include "sxk/mesh.hpp"
#include "sxk/outcome.hpp"
#include "sxk/point_math.hpp"

namespace sxk::delaunaycut {

inline double length3(const Point& a) { return norm(a); }
inline double distance3(const Point& a, const Point& b) { return length3(minus(a, b)); }
inline Point lerp3(const Point& a, const Point& b, double s) {
    return {a[0] + s * (b[0] - a[0]), a[1] + s * (b[1] - a[1]), a[2] + s * (b[2] - a[2])};
}
inline Blade lerp(const Blade& a, const Blade& b, double s) {
    return {lerp3(a.handle, b.handle, s), lerp3(a.tip, b.tip, s)};
}
// The point of segment a-b nearest p, as the fraction of the way from a to b.
double nearest_on_segment(const Point& a, const Point& b, const Point& p);

// The distance from p to the blade (the segment).
inline double distance_to_blade(const Blade& blade, const Point& p) {
    return distance3(p, lerp3(blade.handle, blade.tip, nearest_on_segment(blade.handle, blade.tip, p)));
}

// Where the blade crosses triangle (p, q, r): none when they do not meet (decided exactly); the
// point where the blade's line crosses the triangle's plane, or for a blade in that plane the
// point of the blade nearest the triangle's centroid.
std::optional<Point> blade_meets_triangle(const Blade& blade, const Point& p, const Point& q, const Point& r);

// The blade's pierce points in `triangles` (deformed positions), each with a triangle holding it;
// points nearer than `merge` to one already found (the blade through an edge or a corner shared by
// several of them) are the same point.
std::vector<std::pair<ElementId, Point>> pierce_points(const Mesh& mesh, std::span<const ElementId> triangles,
                                                       const Blade& blade, double merge);

// The point of `triangles` nearest p (deformed positions): its triangle (the first of the nearest),
// its barycentric weights there (of simplex(triangle).vertex(j)), the point; no triangle for none.
struct NearestPoint {
    ElementId triangle = invalid_id;
    std::array<double, 3> weights{};
    Point point{};
};
NearestPoint nearest_point(const Mesh& mesh, std::span<const ElementId> triangles, const Point& p);

// A node at `point` on triangle t (on it or near it): t's corner when the point is within `snap` of
// it, else a split of t's edge when within `snap` of it, else a split of t (the node where the
// point's nearest point on t is, barycentric weights in both position sets).
Outcome<VertexId> node_on_triangle(Mesh& mesh, ElementId t, const Point& point, double snap);

// Moves v to `point` in the deformed positions and to the matching point in the reference ones
// (the point itself where the two sets agree on star(v), else the barycentric coordinates of its
// nearest point on the nearest triangle of star(v), mapped to that triangle's reference corners).
// Refused (nothing moves) when a triangle of star(v) would become collinear in either set, or
// would face against a triangle next to it that it faced along with before (normal_alignment,
// exact): the surface would fold.
Outcome<Done> place_on_surface(Mesh& mesh, VertexId v, const Point& point);

// The pairs of a triangle of `triangles` and a neighbour that face against each other (exactly,
// normal_alignment; each pair once): what a flip or a node removal must not add, as flip_edge and
// remove_node check the new triangles among themselves only.
std::size_t folds_at(const Mesh& mesh, std::span<const ElementId> triangles);

// The blade one triangle beyond v's star: the first triangle of star(v) whose neighbour across the
// edge opposite v the blade pierces, with the point of that edge nearest the pierce point; none
// when the blade pierces no such neighbour.
struct Beyond {
    ElementId triangle = invalid_id;  // of star(v)
    Point on_edge{};
};
std::optional<Beyond> pierced_beyond(const Mesh& mesh, VertexId v, const Blade& blade);

// The edges of star(v) opposite v, as point pairs (deformed positions).
std::vector<std::array<Point, 2>> far_edges(const Mesh& mesh, VertexId v);

}  // namespace sxk::delaunaycut
