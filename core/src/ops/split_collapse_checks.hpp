// Private helpers shared by split_edge.cpp, split_face.cpp, split_element.cpp,
// collapse_edge.cpp and flip_edge.cpp: exact orientation of a simplex that is not (yet) an
// element, with some vertices at positions that are not (yet) in the mesh, filtered exact tests
// on triangles in space, the elements around a simplex (on the star walks of star_walk.hpp), and
// the common transaction of the three splits (split_parents).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "mesh_checks.hpp"
#include "sxk/mesh.hpp"
#include "sxk/ops/split_result.hpp"
#include "sxk/outcome.hpp"
#include "sxk/predicates.hpp"
#include "sxk/traversal.hpp"

namespace sxk::detail {

inline const char* positions_text(Positions positions) {
    return positions == Positions::reference ? "reference" : "deformed";
}

// A vertex whose position is about to change (the new vertex of a split, the surviving vertex
// of a collapse to a point): its two positions override the mesh's.
struct MovedVertex {
    VertexId vertex = invalid_id;
    Point reference{};
    Point deformed{};
};

inline const Point& position_of(const Mesh& mesh, VertexId v, Positions positions,
                                const MovedVertex& moved) {
    if (v == moved.vertex)
        return positions == Positions::reference ? moved.reference : moved.deformed;
    return positions == Positions::reference ? mesh.reference(v) : mesh.deformed(v);
}

// ---- exact tests on triangles in space, filtered ---------------------------------------------
// sxk::collinear and sxk::normal_alignment are exact but not cheap: normal_alignment builds CGAL
// lazy-exact points (heap nodes) on every call, and the two were ~20% of a surface flip and of a
// surface collapse (perf on tools/bench/surface_ops, femur boundary). A surface operation asks
// them about the same few triangles again and again, so it computes each triangle's normal once
// in doubles with a forward error bound and calls the exact predicate only when the bound cannot
// decide. The answers are those of the exact predicates, always.
//
// Error bound (u = 2^-53, round to nearest; x = q - p, y = r - p): n_z = x_x y_y - x_y y_x is
// computed with two rounded differences, one rounded product and one rounded subtraction per
// monomial, so |n~_z - n_z| <= ((1+u)^4 - 1)(|x_x y_y| + |x_y y_x|) + (underflow: < 2^-1073)
// < 5u P_z + 1e-300, P_z the "permanent" |x_x y_y| + |x_y y_x| (its rounded value is within a
// few u of the exact one; 8u leaves the margin). For the dot product of two such normals, each
// product n0_i n1_i is off by <= P0_i e1_i + e0_i P1_i + e0_i e1_i ~ 8.02u P0_i P1_i and the
// product and two sums add ~3.01u, so |D~ - D| < 11.1u sum P0_i P1_i + (underflow terms
// <= 2^-1072 * 6 * 2e120 when every coordinate difference is <= 1e60, i.e. < 1e-200); the test
// uses 16u and 1e-200 and falls back to the exact predicate outside that range (and on NaN or
// infinity, which fail every comparison below).
struct TriangleNormal {
    std::array<double, 3> normal{};     // (q - p) x (r - p), rounded
    std::array<double, 3> permanent{};  // |products| summed per component, rounded
    bool in_range = false;              // every coordinate difference <= 1e60 in magnitude
};

inline TriangleNormal triangle_normal(const Point& p, const Point& q, const Point& r) {
    const double x0 = q[0] - p[0], x1 = q[1] - p[1], x2 = q[2] - p[2];
    const double y0 = r[0] - p[0], y1 = r[1] - p[1], y2 = r[2] - p[2];
    TriangleNormal t;
    t.normal = {x1 * y2 - x2 * y1, x2 * y0 - x0 * y2, x0 * y1 - x1 * y0};
    t.permanent = {std::abs(x1 * y2) + std::abs(x2 * y1), std::abs(x2 * y0) + std::abs(x0 * y2),
                   std::abs(x0 * y1) + std::abs(x1 * y0)};
    const double largest = std::max({std::abs(x0), std::abs(x1), std::abs(x2), std::abs(y0),
                                     std::abs(y1), std::abs(y2)});
    t.in_range = largest <= 1e60;  // false for NaN
    return t;
}

// True when the rounded normal proves the exact one is not zero (the triangle is not flat).
inline bool certainly_not_collinear(const TriangleNormal& t) {
    constexpr double eight_u = 0x1p-50;
    for (std::size_t i = 0; i < 3; ++i)
        if (std::abs(t.normal[i]) > eight_u * t.permanent[i] + 1e-300) return true;
    return false;
}

// sxk::collinear(p, q, r), exactly; t = triangle_normal(p, q, r).
inline bool collinear_filtered(const Point& p, const Point& q, const Point& r, const TriangleNormal& t) {
    return !certainly_not_collinear(t) && collinear(p, q, r);
}

// sxk::normal_alignment(a, b, c, d, e, f), exactly; s = triangle_normal(a, b, c),
// t = triangle_normal(d, e, f).
inline Sign normal_alignment_filtered(const Point& a, const Point& b, const Point& c,
                                      const TriangleNormal& s, const Point& d, const Point& e,
                                      const Point& f, const TriangleNormal& t) {
    if (s.in_range && t.in_range) {
        constexpr double sixteen_u = 0x1p-49;
        const double dot = s.normal[0] * t.normal[0] + s.normal[1] * t.normal[1] + s.normal[2] * t.normal[2];
        const double permanent = s.permanent[0] * t.permanent[0] + s.permanent[1] * t.permanent[1] +
                                 s.permanent[2] * t.permanent[2];
        const double bound = sixteen_u * permanent + 1e-200;
        if (dot > bound) return Sign::positive;
        if (dot < -bound) return Sign::negative;
    }
    return normal_alignment(a, b, c, d, e, f);
}

// i such that mesh.face(t, i) == f (Mesh::face_slot when t = face_element(f), inline).
inline int slot_of(const Mesh& mesh, ElementId t, FaceId f) {
    const int k = mesh.element_vertex_count();
    for (int i = 0; i < k; ++i)
        if (mesh.face(t, i) == f) return i;
    return -1;
}

// True when c-d is an edge of a triangle mesh; t0 is a triangle containing c. On a valid
// triangle mesh the star of c is a fan (a path or a cycle of triangles, each joined to the next
// by an edge containing c: faces lie in at most two triangles and stars are face-connected), so
// it is walked from t0 both ways round at once (walk_fan_from), stopping at the first triangle
// holding d: each triangle once, no list of the ones seen (edge_exists' breadth-first walk keeps
// one), and two independent chains of loads instead of one (the walk is bound by cache misses
// on the triangles). A star that is not a fan (only on an invalid mesh) falls back to
// edge_exists.
inline bool fan_has_edge(const Mesh& mesh, ElementId t0, VertexId c, VertexId d) {
    bool found = false;
    const bool fan = walk_fan_from(mesh, c, t0, [&](ElementId t) {
        return found = mesh.simplex(t).contains(d);
    });
    return found || (!fan && edge_exists(mesh, c, d));
}

// elements_with_edge (below) into `out`, without allocation. In a triangle mesh an edge has at
// most two triangles: the walk of a's fan (walk_fan: star(a) order) stops at the first one met,
// and the other is its neighbour across the edge, which that order meets later.
template <std::size_t N>
void edge_elements_into(const Mesh& mesh, VertexId a, VertexId b, SmallVector<ElementId, N>& out) {
    if (mesh.topological_dimension() != 2 || a == b) {  // a == b: the whole star, as before
        SmallVector<ElementId, N> around;
        star_into(mesh, a, around);
        for (const ElementId t : around)
            if (mesh.simplex(t).contains(b)) out.push_back(t);
        return;
    }
    ElementId found = invalid_id;
    const bool fan = walk_fan(mesh, a, [&](ElementId t) {
        if (!mesh.simplex(t).contains(b)) return false;
        found = t;
        return true;
    });
    if (!fan) {  // not a fan (an invalid mesh): breadth first
        SmallVector<ElementId, N> around;
        star_into(mesh, a, around);
        for (const ElementId t : around)
            if (mesh.simplex(t).contains(b)) out.push_back(t);
        return;
    }
    if (found == invalid_id) return;
    out.push_back(found);
    // the third vertex's face is the edge ab
    const Simplex& tau = mesh.simplex(found);
    for (int i = 0; i < 3; ++i)
        if (tau.vertex(i) != a && tau.vertex(i) != b) {
            const ElementId other = mesh.neighbor(found, i);
            if (other != invalid_id) out.push_back(other);
        }
}

// Exact orientation of the oriented simplex tau as an element of `mesh`, with the same meaning
// as sxk::element_orientation: for planar triangles and tetrahedra the sign of orient2d /
// orient3d times the simplex sign; for triangles in space positive unless degenerate.
inline Sign simplex_orientation(const Mesh& mesh, const Simplex& tau, Positions positions,
                                const MovedVertex& moved = {}) {
    auto point = [&](int j) -> const Point& {
        return position_of(mesh, tau.vertex(j), positions, moved);
    };
    Sign raw = Sign::positive;
    if (mesh.topological_dimension() == 3)
        raw = orient3d(point(0), point(1), point(2), point(3));
    else if (mesh.ambient_dimension() == 2)
        raw = orient2d(point(0), point(1), point(2));
    else
        return collinear_filtered(point(0), point(1), point(2), triangle_normal(point(0), point(1), point(2)))
                   ? Sign::zero
                   : Sign::positive;
    if (raw == Sign::zero) return raw;
    return static_cast<int>(raw) * tau.sign() > 0 ? Sign::positive : Sign::negative;
}

// The elements containing both a and b (the star of the edge ab), in star(a) order.
inline std::vector<ElementId> elements_with_edge(const Mesh& mesh, VertexId a, VertexId b) {
    SmallVector<ElementId, 64> around;
    edge_elements_into(mesh, a, b, around);
    return {around.begin(), around.end()};
}

// ---- the link condition of an edge collapse (thesis Fig. 3.10; Dey et al.) ----------------
// link(from) ∩ link(to) == link(from-to), the boundary joined to a virtual vertex `outside`
// (so that a collapse cannot glue two boundary pieces either). star_from and star_to are the
// stars of the two ends.

// The virtual vertex standing for "outside": joined to every boundary face, it turns a mesh
// with boundary into a closed complex for the link condition.
constexpr VertexId link_outside = invalid_id;

// A simplex of a link: {size, its vertices sorted, 0 padding}. The links of one edge collapse
// have a few dozen simplexes of at most 3 vertices: flat sorted arrays searched by bisection,
// with no allocation for links of up to 128 simplexes.
using LinkSimplex = std::array<VertexId, 4>;
using Link = SmallVector<LinkSimplex, 128>;

// Adds every non-empty subset of the first n of `vertices` (which exclude the apex) to `link`.
inline void add_faces_of(std::array<VertexId, 3> vertices, std::size_t n, Link& link) {
    for (std::size_t i = 1; i < n; ++i)  // at most three: insertion sort
        for (std::size_t j = i; j > 0 && vertices[j] < vertices[j - 1]; --j)
            std::swap(vertices[j], vertices[j - 1]);
    for (unsigned mask = 1; mask < (1u << n); ++mask) {
        LinkSimplex s{};
        for (std::size_t i = 0; i < n; ++i)
            if (mask & (1u << i)) s[++s[0]] = vertices[i];
        link.push_back(s);
    }
}

// link(sigma) for sigma = {v} or {v, w}: the simplexes tau disjoint from sigma with tau * sigma
// in the closed star, the boundary joined to `link_outside`. Sorted, without repeats.
inline void link_of(const Mesh& mesh, std::span<const ElementId> around, std::span<const VertexId> sigma,
                    Link& link) {
    auto in_sigma = [&](VertexId v) { return std::find(sigma.begin(), sigma.end(), v) != sigma.end(); };
    for (const ElementId t : around) {
        const Simplex& tau = mesh.simplex(t);
        if (!std::all_of(sigma.begin(), sigma.end(), [&](VertexId v) { return tau.contains(v); }))
            continue;
        std::array<VertexId, 3> rest{};
        std::size_t rest_count = 0;
        for (const VertexId v : tau.vertices())
            if (!in_sigma(v)) rest[rest_count++] = v;
        add_faces_of(rest, rest_count, link);
        // boundary faces of t containing sigma, joined to the outside vertex
        for (int i = 0; i < tau.count(); ++i) {
            if (in_sigma(tau.vertex(i)) || mesh.neighbor(t, i) != invalid_id) continue;
            std::array<VertexId, 3> face_rest{link_outside};
            std::size_t face_count = 1;
            for (std::size_t j = 0; j < rest_count; ++j)
                if (rest[j] != tau.vertex(i)) face_rest[face_count++] = rest[j];
            add_faces_of(face_rest, face_count, link);
        }
    }
    std::sort(link.begin(), link.end());
    link.resize(static_cast<std::size_t>(std::unique(link.begin(), link.end()) - link.begin()));
}

// The link condition on all simplexes of the links, any dimension.
inline bool link_condition_holds(const Mesh& mesh, std::span<const ElementId> star_from,
                                 std::span<const ElementId> star_to, VertexId from, VertexId to) {
    const std::array<VertexId, 1> just_from{from}, just_to{to};
    const std::array<VertexId, 2> both{from, to};
    Link link_from, link_to, link_edge;
    link_of(mesh, star_from, just_from, link_from);
    link_of(mesh, star_to, just_to, link_to);
    link_of(mesh, star_from, both, link_edge);
    for (const LinkSimplex& s : link_from)
        if (std::binary_search(link_to.begin(), link_to.end(), s) &&
            !std::binary_search(link_edge.begin(), link_edge.end(), s))
            return false;
    return true;
}

// The same test for triangle meshes, without building the links. With T = {from, x, y} over
// star(from) (and likewise for `to`), the links are: vertices x, y; edges {x, y}; `outside`
// and edges {outside, y} for each boundary edge {from, y}; link(from-to) holds the third
// vertices of the triangles containing the edge, and `outside` when the edge is a boundary
// edge (no edges: a link of an edge in a surface has dimension 0). So the condition fails
// exactly when (1) a vertex x (not from, to) is in both stars without being opposite the edge,
// (2) both ends are on the boundary but the edge is not, (3) triangles {from, x, y} and
// {to, x, y} both exist, or (4) boundary edges {from, y} and {to, y} both exist.
inline bool link_condition_holds_2d(const Mesh& mesh, std::span<const ElementId> star_from,
                                    std::span<const ElementId> star_to, VertexId from, VertexId to) {
    // per star: the vertices other than the centre, the opposite edges {x, y} (sorted), and
    // the far ends y of boundary edges {centre, y}
    struct Side {
        SmallVector<VertexId, 64> vertices;
        SmallVector<std::array<VertexId, 2>, 64> opposite_edges;
        SmallVector<VertexId, 16> boundary_ends;
    };
    auto collect = [&](std::span<const ElementId> around, VertexId centre, Side& side) {
        for (const ElementId t : around) {
            const Simplex& tau = mesh.simplex(t);
            std::array<VertexId, 2> pair{};
            for (int i = 0, o = 0; i < 3; ++i) {
                const VertexId v = tau.vertex(i);
                if (v == centre) continue;
                side.vertices.push_back(v);
                pair[static_cast<std::size_t>(o++)] = v;  // canonical order: sorted
                // the face opposite v is the edge {centre, other}
                if (mesh.neighbor(t, i) == invalid_id) {
                    for (int j = 0; j < 3; ++j)
                        if (tau.vertex(j) != centre && tau.vertex(j) != v) side.boundary_ends.push_back(tau.vertex(j));
                }
            }
            side.opposite_edges.push_back(pair);
        }
    };
    Side at_from, at_to;
    collect(star_from, from, at_from);
    collect(star_to, to, at_to);
    auto holds = [](const auto& list, const auto& value) {
        return std::find(list.begin(), list.end(), value) != list.end();
    };
    // the third vertices of the triangles around the edge; is the edge on the boundary?
    SmallVector<VertexId, 4> opposite;
    bool edge_on_boundary = false;
    for (const ElementId t : star_from) {
        const Simplex& tau = mesh.simplex(t);
        if (!tau.contains(to)) continue;
        for (int i = 0; i < 3; ++i)
            if (tau.vertex(i) != from && tau.vertex(i) != to) {
                opposite.push_back(tau.vertex(i));
                edge_on_boundary = edge_on_boundary || mesh.neighbor(t, i) == invalid_id;
            }
    }
    for (const VertexId x : at_from.vertices)  // (1)
        if (x != to && holds(at_to.vertices, x) && !holds(opposite, x)) return false;
    if (!at_from.boundary_ends.empty() && !at_to.boundary_ends.empty() && !edge_on_boundary)
        return false;  // (2)
    for (const auto& pair : at_from.opposite_edges)  // (3)
        if (holds(at_to.opposite_edges, pair)) return false;
    for (const VertexId y : at_from.boundary_ends)  // (4)
        if (holds(at_to.boundary_ends, y)) return false;
    return true;
}

// Affine combination sum weights[i] * p_i of `vertices`, in both positions: the kernel's own
// formula, so that the point checked here is bit for bit the one add_interpolated_vertex adds.
inline std::pair<Point, Point> interpolate(const Mesh& mesh, std::span<const VertexId> vertices,
                                           std::span<const double> weights) {
    return mesh.interpolated_positions(vertices, weights);
}

// Splits share one rule: a child must keep its parent's orientation in both positions. In
// exact arithmetic a point strictly inside a simplex (or edge, or face) gives children of the
// parent's sign; the rounded new position can still make a child of a nearly flat parent flat,
// and that is refused rather than built. Nothing when all children are fine.
// Children of parents containing every vertex of `vanishing_with` (when not empty) are not
// checked (SplitOptions: the caller removes them in its next edit).
inline std::optional<Refusal> refuse_bad_children(const Mesh& mesh,
                                                  std::span<const Simplex> children,
                                                  std::span<const ElementId> parents_of_children,
                                                  const MovedVertex& moved, const char* operation,
                                                  std::span<const VertexId> vanishing_with = {}) {
    auto vanishing = [&](ElementId parent) {
        return !vanishing_with.empty() &&
               std::all_of(vanishing_with.begin(), vanishing_with.end(),
                           [&](VertexId v) { return mesh.simplex(parent).contains(v); });
    };
    for (const Positions positions : {Positions::reference, Positions::deformed}) {
        // children of one parent are consecutive: its orientation is computed once per run
        ElementId parent_id = invalid_id;
        Sign parent = Sign::zero;
        for (std::size_t i = 0; i < children.size(); ++i) {
            if (vanishing(parents_of_children[i])) continue;
            if (parents_of_children[i] != parent_id) {
                parent_id = parents_of_children[i];
                parent = simplex_orientation(mesh, mesh.simplex(parent_id), positions);
            }
            const Sign child = simplex_orientation(mesh, children[i], positions, moved);
            if (child == Sign::zero || child != parent)
                return Refusal{orientation_code(child),
                               std::string(operation) + ": new element " + to_text(children[i]) +
                                   (child == Sign::zero ? " would be flat" : " would be inverted") +
                                   " in the " + positions_text(positions) + " positions",
                               i};
        }
    }
    return std::nullopt;
}

// The common end of every split: the new vertex m = sum weights[i] * replaced[i] (positions
// and every vertex attribute, Mesh::add_interpolated_vertex); each parent is replaced by one
// child per vertex in `replaced` (the parent with that vertex swapped for m, so orientation and
// label follow the parent). The children are checked with m at its future position before it
// exists; then m is added and ONE replace_elements call (without its star walks, which the
// split has proven) makes the edit. Should that call refuse (it cannot on a valid mesh: every
// new face either was a face of a parent or contains the fresh vertex, which no other element
// has), m is removed again (Mesh::remove_last_vertex), so
// a refused split leaves the mesh exactly as it was in every case.
inline Outcome<SplitResult> split_parents(Mesh& mesh, std::span<const ElementId> parents,
                                          std::span<const VertexId> replaced,
                                          std::span<const double> weights, const char* operation,
                                          std::span<const VertexId> vanishing_with = {}) {
    const auto [reference, deformed] = interpolate(mesh, replaced, weights);
    const auto m = static_cast<VertexId>(mesh.vertex_count());
    const MovedVertex moved{m, reference, deformed};
    // scratch lists in place (a surface split has 4 children): the success path allocates only
    // what it returns
    SmallVector<Simplex, 16> children;
    SmallVector<ElementId, 16> parent_of_child;
    SmallVector<std::uint32_t, 16> origins;  // a child is its parent's: label and element attributes
    for (std::uint32_t p = 0; p < parents.size(); ++p)
        for (const VertexId v : replaced) {
            children.push_back(mesh.simplex(parents[p]).substituted(v, m));
            parent_of_child.push_back(parents[p]);
            origins.push_back(p);
        }
    if (auto refused =
            refuse_bad_children(mesh, children, parent_of_child, moved, operation, vanishing_with))
        return *refused;
    // Face labels (keyed by vertex set) on the faces of the parents that are split: a face in no
    // child (split_edge: those containing a and b; split_face: abc) passes its label to its
    // pieces, the face with one of its replaced vertices swapped for m.
    std::vector<std::pair<Simplex, int>> moved_labels;
    std::vector<Simplex> split_faces;
    if (!mesh.face_labels().empty())
        for (const ElementId parent : parents)
            for (int i = 0; i < mesh.simplex(parent).count(); ++i) {
                const Simplex face(+1, mesh.simplex(parent).subn(i).vertices());
                const auto label = mesh.face_labels().find(face);
                if (label == mesh.face_labels().end()) continue;
                const bool kept = std::any_of(children.begin(), children.end(), [&](const Simplex& child) {
                    return std::all_of(face.vertices().begin(), face.vertices().end(),
                                       [&](VertexId v) { return child.contains(v); });
                });
                if (kept || std::find(split_faces.begin(), split_faces.end(), face) != split_faces.end())
                    continue;
                split_faces.push_back(face);
                for (const VertexId v : replaced)
                    if (face.contains(v))
                        moved_labels.emplace_back(Simplex(+1, face.substituted(v, m).vertices()), label->second);
            }
    auto added = mesh.add_interpolated_vertex(replaced, weights);
    if (!added.ok()) return added.refusal().prefixed(std::string(operation) + ": ");
    // The star checks of replace_elements are proven (mesh_checks.hpp, ProvenEdit): (a) every
    // child and every new face that is not a face of a parent contains m, which no element has;
    // (b) around each vertex the children of a parent are face-connected among themselves
    // (through the faces containing m) and keep the parent's faces that do not contain the
    // split simplex, so every path through a star across the parents can be rerouted.
    auto result = ProvenEdit::replace(mesh, parents, children, {}, origins);
    if (!result.ok()) {
        (void)mesh.remove_last_vertex();  // m is in no element: the refused edit added nothing
        return result.refusal().prefixed(std::string(operation) + ": ");
    }
    for (const Simplex& face : split_faces) mesh.erase_face_label(face);
    for (const auto& [face, label] : moved_labels) mesh.set_face_label(face, label);
    return SplitResult{m, std::move(*result)};
}

// Every weight strictly positive and finite: the new point lies in the open simplex.
inline bool weights_inside(std::span<const double> weights) {
    return std::all_of(weights.begin(), weights.end(),
                       [](double w) { return w > 0 && w < 1e300; });
}

}  // namespace sxk::detail
