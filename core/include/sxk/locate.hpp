// Point location and spatial queries on a mesh that is being edited (issue 13, item 3).
//
// SpatialIndex is a Watcher (watcher.hpp) that keeps two R-trees (Boost.Geometry's bgi::rtree,
// which supports insertion and removal) in step with the mesh: one of element bounding boxes and
// one of boundary-face bounding boxes, over the reference OR the deformed positions (chosen at
// construction). Every element event re-boxes what it names, and vertices_moved re-boxes the
// elements and boundary faces around the moved vertices, so no query and no edit ever scans the
// whole mesh (docs/architecture.md "An edit, end to end"):
//
//        mesh edit ──► element_removed / changed / added ──► rtree remove / insert (one box each)
//        move_vertices ──► vertices_moved ──► re-box star(v) and its boundary faces: each box
//                                             tested where it is, re-entered with a margin only
//                                             when it left (a quarter of the vertices or more, a
//                                             simulation's frame: refit, every box so; the seed
//                                             grid of locate stays)
//        EditJournal rollback ──► the net change back, as one edit ──► the same
//
//        query ──► (a walk from the hint) ──► rtree candidates ──► exact test per candidate
//
// Boxes are stored in single precision, grown by about a millionth of their size and distance
// from the origin and rounded outward, so each box contains its element with a margin that
// absorbs the rounding of Boost's box tests (in double precision); which candidates qualify is
// then decided by the exact predicates of predicates.hpp (CGAL's filtered kernel), never by a box.
// Boxes are conservative: an id the edit frees and hands out again keeps its tree entry when the
// entry's box still holds the new element (and is at most 4 times as wide), so a flip or a split
// often costs the tree nothing (core/src/locate_trees.hpp).
//
// What "inside" means (every query):
//   * Elements and faces are CLOSED: a point on a face, an edge or a vertex shared by several
//     elements is inside each of them; locate returns ONE of them (the walk's, or the first the
//     rtree yields; no promise which), the other queries return all of them.
//   * A flat element (exact orientation zero in the index's positions) contains no point and is
//     hit by nothing; a walk that meets one gives up (the rtree decides) and the rtree's
//     candidates test false.
//   * Planar meshes (ambient dimension 2): every query point's z is ignored.
//   * Triangle surfaces in 3D have no inside. locate means "on the surface within a tolerance":
//     it returns a triangle whose distance to x is at most the index's surface tolerance
//     (SpatialIndexOptions; by default 1e-9 times the diagonal of the mesh's bounding box), with
//     the barycentric coordinates of the point of that triangle nearest x, or nothing when every
//     triangle is farther away. The segment and triangle queries test exact intersection with the
//     triangles; the boundary of a surface is its boundary edges (none on a closed surface); ray
//     picks hit the triangles themselves.
//   * Distances, hit parameters and barycentric coordinates are computed in double precision
//     (they are quantities, not decisions): the weights are clamped to [0, 1] and sum to 1 up to
//     rounding, and a weight the exact test found to be zero is exactly 0. Where the weights of
//     the double solve do not give the point back within 64 units in the last place of the
//     largest coordinate involved (thin elements), they are recomputed as ratios of exact
//     determinants, each then within a few units in the last place of its true value.
//
// Cost: an edit pays O(log n) per element (and boundary face) it removes, adds or re-boxes; a
// locate pays the walk from its hint, bounded, then O(log n) in the rtree; the other queries
// O(log n + candidates), where the candidates are the elements whose boxes meet the query
// (docs/performance.md "locate").
#pragma once

#include <array>
#include <cstddef>
#include <limits>
#include <memory>
#include <vector>

#include "sxk/config.hpp"
#include "sxk/mesh.hpp"
#include "sxk/outcome.hpp"
#include "sxk/predicates.hpp"
#include "sxk/watcher.hpp"

namespace sxk {

// An element containing a point, with the point's barycentric coordinates: barycentric[j] is the
// weight of simplex(element).vertex(j) (canonical order), j < d+1; unused entries are 0.
struct Location {
    ElementId element = invalid_id;
    std::array<double, 4> barycentric{};
    bool found() const { return element != invalid_id; }
};

// All the elements of a triangle sweep (a scalpel's blade moving over a frame), and the boundary
// faces the triangle meets, each sorted by id.
struct TriangleHits {
    std::vector<ElementId> elements;
    std::vector<FaceId> boundary_faces;
};

// What elements_hit_by_triangle looks for: a cutter that only selects among the elements skips
// the boundary faces' tree (an eighth of the query's time on the femur's scalpel sweeps); one
// that follows its blade through the elements asks only where the sweep meets the boundary.
enum class TriangleHitsOf { elements_and_boundary_faces, elements, boundary_faces };

// The point of the boundary nearest a query. barycentric[j] weighs face_simplex(face).vertex(j),
// j < d (a boundary face has d vertices).
struct BoundaryPoint {
    FaceId face = invalid_id;        // invalid_id: the mesh has no boundary
    ElementId element = invalid_id;  // the element the face belongs to
    Point point{};
    double distance = std::numeric_limits<double>::infinity();
    std::array<double, 3> barycentric{};
    bool found() const { return face != invalid_id; }
};

// The first boundary face a ray meets: origin + t * direction with t >= 0 the smallest. For a
// triangle surface in 3D the surface itself is hit: `face` is invalid_id and barycentric weighs
// the triangle's vertices (simplex(element).vertex(j)); otherwise it weighs the face's vertices
// (face_simplex(face).vertex(j)).
struct RayHit {
    ElementId element = invalid_id;  // invalid_id: no hit
    FaceId face = invalid_id;
    double t = std::numeric_limits<double>::infinity();
    Point point{};
    std::array<double, 3> barycentric{};
    bool found() const { return element != invalid_id; }
};

struct SpatialIndexOptions {
    Positions positions = Positions::reference;
    // Triangle surfaces in 3D: how far from a triangle a point may be for locate to return it.
    // 0 (the default): 1e-9 times the diagonal of the bounding box of the indexed elements.
    double surface_tolerance = 0;
};

class SXK_API SpatialIndex final : public Watcher {
public:
    // Builds the index over the whole mesh (one bulk load of each rtree, O(n log n)) and attaches
    // itself as a watcher of `mesh` until destroyed. The mesh must outlive the index and stay
    // where it is: a copy assigned to it rebuilds the index (Watcher::init), but moving a mesh
    // moves its watchers along, and an index keeps the address it was given.
    explicit SpatialIndex(Mesh& mesh, const SpatialIndexOptions& options = {});
    SpatialIndex(Mesh& mesh, Positions positions) : SpatialIndex(mesh, SpatialIndexOptions{positions, 0}) {}
    ~SpatialIndex() override;
    SpatialIndex(const SpatialIndex&) = delete;
    SpatialIndex& operator=(const SpatialIndex&) = delete;

    const Mesh& mesh() const { return *m_mesh; }
    Positions positions() const { return m_options.positions; }
    // The tolerance locate uses on a triangle surface in 3D (the option, or its default now).
    double surface_tolerance() const;

    // The element containing x (see "What inside means" above) with x's barycentric coordinates,
    // or none. With a live `hint` it first walks from the hint through face neighbours (exact
    // orientation tests, walk_to_point; at most 128 steps), which costs the distance walked, so
    // pass the previous answer when following a tool; when the walk leaves the mesh, meets a flat
    // element, gives up or there is no hint, a short walk from the seed of x's cell in a grid
    // (planar and tetrahedral meshes) and then the rtree's candidates at x decide. Non-finite
    // coordinates are in no element.
    Location locate(const Point& x, ElementId hint = invalid_id) const;

    // The elements whose closed simplex meets the closed segment [a, b] (exactly), sorted by id.
    // a == b asks for the elements containing that point (on a surface: exactly on it).
    std::vector<ElementId> elements_crossed(const Point& a, const Point& b) const;

    // The elements whose closed simplex meets the closed triangle (a, b, c), and the boundary
    // faces it meets (exactly; no faces with TriangleHitsOf::elements, no elements with
    // TriangleHitsOf::boundary_faces), sorted by id. A degenerate
    // triangle (collinear corners) is the segment between its two farthest corners. Candidates:
    // the elements whose boxes meet the boxes of pieces of the triangle.
    TriangleHits elements_hit_by_triangle(const Point& a, const Point& b, const Point& c,
                                          TriangleHitsOf what = TriangleHitsOf::elements_and_boundary_faces) const;

    // The elements with at least one vertex in the closed axis-aligned box [low, high] (each
    // coordinate compared exactly), sorted by id: what a brush of that size touches. Planar
    // meshes ignore z. Empty when low > high along an axis or a bound is NaN.
    std::vector<ElementId> elements_with_vertex_in_box(const Point& low, const Point& high) const;

    // The point of the boundary (the faces without a mate) nearest x, with its face, or none when
    // the mesh has no boundary. Ties between faces go to either.
    BoundaryPoint nearest_boundary_point(const Point& x) const;

    // The first boundary face (on a surface: the first triangle) hit by the ray from `origin`
    // along `direction` (any length but zero), decided by exact predicates; the nearest by t,
    // ties to either. A ray starting on a face hits it at t = 0.
    RayHit pick(const Point& origin, const Point& direction) const;

    // The live elements and boundary faces indexed (flat elements included).
    std::size_t indexed_elements() const;
    std::size_t indexed_boundary_faces() const;
    // Bytes held by the trees, their entries and the seed grid.
    std::size_t memory_bytes() const;
    // O(n), for tests: every live element and boundary face is a member of one tree entry whose
    // box holds the box its positions give now, nothing else is a member, the entries' member
    // lists and counts agree, and every tree value is its entry's box ("spatial index: element 7
    // has a stale box").
    Outcome<Done> validate() const;

    // ---- Watcher ------------------------------------------------------------------------------
    void init(const Mesh& mesh) override;
    void element_removed(const Mesh& mesh, ElementId element, const Simplex& was) override;
    void element_changed(const Mesh& mesh, ElementId element, const Simplex& was) override;
    void element_added(const Mesh& mesh, ElementId element) override;
    void boundary_removed(const Mesh& mesh, FaceId face, const Simplex& was) override;
    void boundary_changed(const Mesh& mesh, FaceId face, const Simplex& was) override;
    void boundary_added(const Mesh& mesh, FaceId face) override;
    void vertices_moved(const Mesh& mesh, std::span<const VertexId> vertices, PositionSet which) override;

    struct Trees;  // core/src/locate_trees.hpp

private:
    Mesh* m_mesh;
    SpatialIndexOptions m_options;
    std::unique_ptr<Trees> m_trees;
};

// ---- the element-level tests every query is built on, and the index-less walks -----------------
// A scan of the mesh with these is what the index must agree with (tests/core/locate_test.cpp).

// x in element t (closed; flat elements contain nothing), with its barycentric coordinates. On a
// triangle surface in 3D: the point of t nearest x when it is at most `surface_tolerance` away.
SXK_API Location locate_in_element(const Mesh& mesh, ElementId t, const Point& x, Positions positions,
                                   double surface_tolerance = 0);
// The closed element t (not flat) meets the closed segment [a, b], exactly.
SXK_API bool segment_meets_element(const Mesh& mesh, ElementId t, const Point& a, const Point& b,
                                   Positions positions);
// The closed element t (not flat) meets the closed triangle (a, b, c), exactly (collinear corners:
// the segment between the two farthest).
SXK_API bool triangle_meets_element(const Mesh& mesh, ElementId t, const Point& a, const Point& b,
                                    const Point& c, Positions positions);
// The same for a face f of the mesh (a triangle in a tetrahedral mesh, a segment otherwise).
SXK_API bool triangle_meets_face(const Mesh& mesh, FaceId f, const Point& a, const Point& b, const Point& c,
                                 Positions positions);
// The point of face f nearest x.
SXK_API BoundaryPoint nearest_point_on_face(const Mesh& mesh, FaceId f, const Point& x, Positions positions);
// Where the ray meets face f (decided exactly; RayHit::found() false when it misses), and where
// it meets the triangle t of a triangle mesh (what pick uses on a surface in 3D).
SXK_API RayHit ray_meets_face(const Mesh& mesh, FaceId f, const Point& origin, const Point& direction,
                              Positions positions);
SXK_API RayHit ray_meets_triangle_element(const Mesh& mesh, ElementId t, const Point& origin,
                                          const Point& direction, Positions positions);

// Barycentric coordinates (weights of a, b, c) of the point of triangle (a, b, c) nearest p, in
// any ambient dimension; a degenerate triangle gives the nearest point of its longest edge.
SXK_API std::array<double, 3> nearest_on_triangle(const Point& a, const Point& b, const Point& c, const Point& p);

// The visibility walk from `start` towards x (step through a face that has x strictly beyond it,
// exact orientation): the element containing x, or invalid_id when
// the walk leaves the mesh, meets a flat element or takes more than `max_steps` steps. Planar
// triangle meshes: the stochastic walk (the face tried first chosen by a small xorshift, so the
// walk cannot cycle on meshes that are not Delaunay); tetrahedral meshes: the face tried first
// rotates with the step. Triangle surfaces in 3D: a descent to a triangle nearest x (steps to the
// neighbour across the edge nearest x while that gets nearer); the triangle where it stops,
// whatever its distance. invalid_id for a dead start or non-finite x.
SXK_API ElementId walk_to_point(const Mesh& mesh, const Point& x, ElementId start, Positions positions,
                                std::size_t max_steps);

// The point locations refine_around and refine_around_tetrahedra use without an index: walk from
// the hint (planar meshes without one: from the nearest, by first vertex, of about cbrt(n)
// elements spread over the id range, jump-and-walk; tetrahedral meshes: from the first live
// element), and when the walk fails, a scan of every element: O(n) only then. Reference
// positions. invalid_id when x is in no element, or the mesh is not of the kind named.
SXK_API ElementId locate_triangle(const Mesh& mesh, const Point& x, ElementId hint = invalid_id);
SXK_API ElementId locate_tetrahedron(const Mesh& mesh, const Point& x, ElementId start);

}  // namespace sxk
