// Private helpers shared by split_edge.cpp, split_face.cpp, split_element.cpp and
// collapse_edge.cpp: exact orientation of a simplex that is not (yet) an element, with some
// vertices at positions that are not (yet) in the mesh, the elements around a simplex, and the
// common transaction of the three splits (split_parents).
#pragma once

#include <algorithm>
#include <array>
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
        return collinear(point(0), point(1), point(2)) ? Sign::zero : Sign::positive;
    if (raw == Sign::zero) return raw;
    return static_cast<int>(raw) * tau.sign() > 0 ? Sign::positive : Sign::negative;
}

// The elements containing both a and b (the star of the edge ab), in star(a) order.
inline std::vector<ElementId> elements_with_edge(const Mesh& mesh, VertexId a, VertexId b) {
    std::vector<ElementId> around = star(mesh, a);
    std::erase_if(around, [&](ElementId t) { return !mesh.simplex(t).contains(b); });
    return around;
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
// and that is refused rather than built. Empty reason when all children are fine.
inline Refusal refuse_bad_children(const Mesh& mesh, std::span<const Simplex> children,
                                   std::span<const ElementId> parents_of_children,
                                   const MovedVertex& moved, const char* operation) {
    for (const Positions positions : {Positions::reference, Positions::deformed})
        for (std::size_t i = 0; i < children.size(); ++i) {
            const Sign parent = simplex_orientation(mesh, mesh.simplex(parents_of_children[i]), positions);
            const Sign child = simplex_orientation(mesh, children[i], positions, moved);
            if (child == Sign::zero || child != parent)
                return {std::string(operation) + ": new element " + to_text(children[i]) +
                            (child == Sign::zero ? " would be flat" : " would be inverted") +
                            " in the " + positions_text(positions) + " positions",
                        i};
        }
    return {};
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
                                          std::span<const double> weights, const char* operation) {
    const auto [reference, deformed] = interpolate(mesh, replaced, weights);
    const auto m = static_cast<VertexId>(mesh.vertex_count());
    const MovedVertex moved{m, reference, deformed};
    std::vector<Simplex> children;
    std::vector<ElementId> parent_of_child;
    std::vector<int> labels;
    for (const ElementId parent : parents)
        for (const VertexId v : replaced) {
            children.push_back(mesh.simplex(parent).substituted(v, m));
            parent_of_child.push_back(parent);
            labels.push_back(mesh.label(parent));
        }
    if (Refusal r = refuse_bad_children(mesh, children, parent_of_child, moved, operation);
        !r.reason.empty())
        return r;
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
    if (!added.ok()) return Refusal{std::string(operation) + ": " + added.reason()};
    // The star checks of replace_elements are proven (mesh_checks.hpp, ProvenEdit): (a) every
    // child and every new face that is not a face of a parent contains m, which no element has;
    // (b) around each vertex the children of a parent are face-connected among themselves
    // (through the faces containing m) and keep the parent's faces that do not contain the
    // split simplex, so every path through a star across the parents can be rerouted.
    auto result = ProvenEdit::replace(mesh, parents, children, labels);
    if (!result.ok()) {
        (void)mesh.remove_last_vertex();  // m is in no element: the refused edit added nothing
        return Refusal{std::string(operation) + ": " + result.reason()};
    }
    for (const Simplex& face : split_faces) mesh.face_labels().erase(face);
    for (const auto& [face, label] : moved_labels) mesh.face_labels()[face] = label;
    return SplitResult{m, std::move(*result)};
}

// Every weight strictly positive and finite: the new point lies in the open simplex.
inline bool weights_inside(std::span<const double> weights) {
    return std::all_of(weights.begin(), weights.end(),
                       [](double w) { return w > 0 && w < 1e300; });
}

}  // namespace sxk::detail
