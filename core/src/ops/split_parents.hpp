// The common transaction of the three splits (split_edge.cpp, split_face.cpp,
// split_element.cpp): the new vertex at an affine combination of the split simplex's vertices,
// the children checked (orientation_checks.hpp) before the vertex exists, one proven
// replace_elements call (ProvenEdit, mesh_checks.hpp), and the face labels moved to the pieces.
#pragma once

#include <algorithm>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "mesh_checks.hpp"
#include "ops/orientation_checks.hpp"
#include "small_vector.hpp"
#include "sxk/mesh.hpp"
#include "sxk/ops/split_result.hpp"
#include "sxk/outcome.hpp"

namespace sxk::detail {

// Affine combination sum weights[i] * p_i of `vertices`, in both positions: the kernel's own
// formula, so that the point checked here is bit for bit the one add_interpolated_vertex adds.
inline std::pair<Point, Point> interpolate(const Mesh& mesh, std::span<const VertexId> vertices,
                                           std::span<const double> weights) {
    return mesh.interpolated_positions(vertices, weights);
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
