// The 2-2 edge flip (thesis §5.2.1, Fig. 5.9; one replace-elements call as in §7.3, Fig. 7.4).
#include "sxk/ops/flip_edge.hpp"

#include <algorithm>
#include <array>
#include <string>

#include "mesh_checks.hpp"
#include "ops/edge_star.hpp"
#include "ops/filtered_triangle_tests.hpp"
#include "ops/label_constraints.hpp"
#include "sxk/predicates.hpp"
#include "sxk/traversal.hpp"

namespace sxk {
namespace {

// i such that mesh.face(t, i) == f (Mesh::face_slot when t = face_element(f), inline).
int slot_of(const Mesh& mesh, ElementId t, FaceId f) {
    const int k = mesh.element_vertex_count();
    for (int i = 0; i < k; ++i)
        if (mesh.face(t, i) == f) return i;
    return -1;
}

std::string vertex_set(std::array<VertexId, 3> v) {
    std::sort(v.begin(), v.end());
    return "{" + std::to_string(v[0]) + "," + std::to_string(v[1]) + "," + std::to_string(v[2]) + "}";
}
std::string vertex_set(VertexId u, VertexId v) {
    if (v < u) std::swap(u, v);
    return "{" + std::to_string(u) + "," + std::to_string(v) + "}";
}


}  // namespace

Outcome<std::array<ElementId, 2>> flip_edge(Mesh& mesh, FaceId edge, const FlipOptions& options) {
    if (mesh.topological_dimension() != 2)
        return Refusal{RefusalCode::wrong_dimension,
                       "flip_edge: needs a triangle mesh (topological dimension 2), this one has "
                       "dimension " + std::to_string(mesh.topological_dimension())};
    if (!mesh.is_face(edge))
        return Refusal{RefusalCode::not_found,
                       "flip_edge: " + std::to_string(edge) + " is not a face of the mesh"};

    // face_simplex(edge), c and d without Mesh::face_slot calls: t0's slot of `edge` is the
    // index of c (invariant 7.1)
    const ElementId t0 = mesh.face_element(edge);
    const int slot0 = slot_of(mesh, t0, edge);
    const Simplex edge_simplex = mesh.simplex(t0).subn(slot0);
    // the oriented edge <a,b> as t0 = <a,b,c> sees it (t0 = edge_simplex.sup(c))
    const VertexId a = edge_simplex.sign() > 0 ? edge_simplex.vertex(0) : edge_simplex.vertex(1);
    const VertexId b = edge_simplex.sign() > 0 ? edge_simplex.vertex(1) : edge_simplex.vertex(0);
    const FaceId mate = mesh.mate(edge);
    if (mate == invalid_id)
        return Refusal{RefusalCode::not_applicable,
                       "flip_edge: edge " + vertex_set(a, b) + " is on the boundary"};

    const ElementId t1 = mesh.face_element(mate);
    const std::array<ElementId, 2> pair{t0, t1};
    if (auto refused = detail::refuse_material_interface(mesh, pair, "flip_edge"))
        return *refused;
    const VertexId c = mesh.simplex(t0).vertex(slot0);
    const VertexId d = mesh.simplex(t1).vertex(slot_of(mesh, t1, mate));

    // Thesis Fig. 5.9: when c-d is already an edge the flip would represent it twice (on a
    // surface: anywhere; in the plane: a vertex of degree 3). Walking around c (its fan of
    // triangles, from t0) says what is actually wrong, and proves what replace_elements would
    // otherwise check (see below).
    if (detail::fan_has_edge(mesh, t0, c, d))
        return Refusal{RefusalCode::not_manifold,
                       "flip_edge: new edge " + vertex_set(c, d) +
                           " already exists (thesis Fig. 5.9), flipping edge " + vertex_set(a, b) +
                           " is topologically impossible"};

    const std::array<std::array<VertexId, 3>, 2> new_triangles{{{a, d, c}, {d, b, c}}};
    for (Positions positions : {Positions::reference, Positions::deformed}) {
        auto p = [&](VertexId v) -> const Point& { return position(mesh, v, positions); };
        if (mesh.ambient_dimension() == 2) {
            if (options.topology_only) continue;
            // both new triangles must turn counter-clockwise, strictly: a flat or inverted one
            // means the quadrilateral a d b c is not strictly convex (§5.2.1)
            for (const auto& triangle : new_triangles) {
                const Sign s = orient2d(p(triangle[0]), p(triangle[1]), p(triangle[2]));
                if (s != Sign::positive)
                    return Refusal{detail::orientation_code(s),
                                   "flip_edge: new triangle " + vertex_set(triangle) +
                                       " would be " + (s == Sign::zero ? "flat" : "inverted") +
                                       " in the " + to_string(positions) + " positions"};
            }
        } else {
            // a triangle in space has no orientation of its own, but a collinear one has no
            // normal and is never a valid element, whatever the caller decided. Each normal is
            // computed once (filtered exact tests, filtered_triangle_tests.hpp) for both the
            // collinearity and the fold test.
            const std::array<detail::TriangleNormal, 2> normals{
                detail::triangle_normal(p(a), p(d), p(c)), detail::triangle_normal(p(d), p(b), p(c))};
            for (std::size_t i = 0; i < 2; ++i) {
                const auto& triangle = new_triangles[i];
                if (detail::collinear_filtered(p(triangle[0]), p(triangle[1]), p(triangle[2]), normals[i]))
                    return Refusal{RefusalCode::would_flatten,
                                   "flip_edge: new triangle " + vertex_set(triangle) +
                                   " would be degenerate (collinear vertices) in the " +
                                   to_string(positions) + " positions"};
            }
            // the new triangles' normals point in opposite directions: the surface would fold
            // over the new edge (thesis §5.3: flips on 3D surfaces must be checked for failure
            // cases); normals of <a,d,c> and <d,b,c>
            if (!options.topology_only &&
                detail::normal_alignment_filtered(p(a), p(d), p(c), normals[0], p(d), p(b), p(c),
                                                  normals[1]) == Sign::negative)
                return Refusal{RefusalCode::would_invert,
                               "flip_edge: flipping edge " + vertex_set(a, b) + " to " +
                                   vertex_set(c, d) +
                                   " would fold the surface (the new triangles' normals are "
                                   "opposite) in the " +
                                   to_string(positions) + " positions"};
        }
    }

    // the sign of <a,d,c> and <d,b,c> follows from the order of a, b taken from the oriented
    // face, so the new elements have the orientation of the old ones
    const std::array<ElementId, 2> old_elements{t0, t1};
    const std::array<Simplex, 2> new_simplexes{Simplex(+1, {a, d, c}), Simplex(+1, {d, b, c})};
    if (auto refused =
            detail::refuse_vanishing_label(mesh, old_elements, new_simplexes, "flip_edge"))
        return *refused;
    // Both new triangles and the new edge pair contain the edge c-d, which is not in the mesh
    // (checked above), and the hull edges are reused: the star checks of replace_elements are
    // proven (mesh_checks.hpp, ProvenEdit).
    auto replaced = ProvenEdit::replace(mesh, old_elements, new_simplexes, {});
    if (!replaced) return replaced.refusal().prefixed("flip_edge: ");
    return std::array<ElementId, 2>{replaced.value()[0], replaced.value()[1]};
}

}  // namespace sxk
