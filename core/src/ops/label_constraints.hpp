// Private: labels are constraints the flips keep. A flip across an interface between materials
// (elements with different labels) would move the interface, and one that removes a labelled
// face would drop the label; both refuse.
//
// Mesh::face_labels() keys a label by the sorted vertex set of a (d-1)-face; validate() checks
// that every key is a face of the mesh. A label marks a constraint (a material interface drawn
// as faces, a boundary patch); the splits, collapse and dissect carry labels over to the faces
// that descend from a labelled one (split_parents.hpp, collapse_edge.cpp, dissect.cpp),
// but a flip removes a face and makes one across it: there is no descendant to carry the label,
// so the flips refuse, and make_delaunay_by_flips leaves such an edge (constrained Delaunay).
#pragma once

#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "sxk/mesh.hpp"
#include "sxk/outcome.hpp"
#include "sxk/simplex.hpp"

namespace sxk::detail {

// A flip across an interface between materials (elements with different labels) would move
// the interface: refused, so that flips keep every material region's shape.
inline std::optional<Refusal> refuse_material_interface(const Mesh& mesh,
                                                        std::span<const ElementId> elements,
                                                        const char* operation) {
    for (const ElementId t : elements)
        if (mesh.label(t) != mesh.label(elements[0]))
            return Refusal{
                RefusalCode::label_conflict,
                std::string(operation) + ": elements have different labels (a material interface)"};
    return std::nullopt;
}

inline Simplex label_key(const Simplex& face) { return Simplex(+1, face.vertices()); }

// The first labelled face of the elements `old` that is no face of any simplex in `created`,
// with its label; nullopt when no label would vanish.
inline std::optional<std::pair<Simplex, int>> vanishing_label(const Mesh& mesh,
                                                              std::span<const ElementId> old,
                                                              std::span<const Simplex> created) {
    if (mesh.face_labels().empty()) return std::nullopt;
    for (const ElementId t : old)
        for (int i = 0; i < mesh.element_vertex_count(); ++i) {
            const Simplex key = label_key(mesh.simplex(t).subn(i));
            const auto label = mesh.face_labels().find(key);
            if (label == mesh.face_labels().end()) continue;
            bool kept = false;
            for (const Simplex& tau : created)
                for (int j = 0; j < tau.count() && !kept; ++j) kept = label_key(tau.subn(j)) == key;
            if (!kept) return std::pair{key, label->second};
        }
    return std::nullopt;
}

// "<operation>: face <a,b,c> carries label 7 (a constraint: an interface or a boundary patch)",
// or nothing when no label would vanish.
inline std::optional<Refusal> refuse_vanishing_label(const Mesh& mesh,
                                                     std::span<const ElementId> old,
                                                     std::span<const Simplex> created,
                                                     const char* operation) {
    const auto vanishing = vanishing_label(mesh, old, created);
    if (!vanishing) return std::nullopt;
    return Refusal{RefusalCode::label_conflict,
                   std::string(operation) + ": face " + to_text(vanishing->first) +
                       " carries label " + std::to_string(vanishing->second) +
                       " (a constraint: an interface or a boundary patch)"};
}

}  // namespace sxk::detail
