// remove_elements (sxk/ops/remove_elements.hpp): replace_elements with nothing, labels kept true.
#include "sxk/ops/remove_elements.hpp"

#include <algorithm>
#include <vector>

#include "sxk/traversal.hpp"

namespace sxk {

namespace {

// Some element has every vertex of `face`.
bool is_mesh_face(const Mesh& mesh, const Simplex& face) {
    const VertexId first = face.vertex(0);
    if (first >= mesh.vertex_count() || mesh.vertex_element(first) == invalid_id) return false;
    for (const ElementId t : star(mesh, first))
        if (std::all_of(face.vertices().begin(), face.vertices().end(),
                        [&](VertexId v) { return mesh.simplex(t).contains(v); }))
            return true;
    return false;
}

}  // namespace

Outcome<Done> remove_elements(Mesh& mesh, std::span<const ElementId> elements) {
    std::vector<ElementId> doomed(elements.begin(), elements.end());
    std::sort(doomed.begin(), doomed.end());
    doomed.erase(std::unique(doomed.begin(), doomed.end()), doomed.end());
    std::vector<Simplex> labelled;  // faces of the doomed elements that carry a label
    if (!mesh.face_labels().empty())
        for (const ElementId t : doomed) {
            if (!mesh.is_element(t)) continue;  // replace_elements refuses it below
            for (int i = 0; i < mesh.element_vertex_count(); ++i) {
                const Simplex face(+1, mesh.simplex(t).subn(i).vertices());
                if (mesh.face_label(face)) labelled.push_back(face);
            }
        }
    const auto removed = mesh.replace_elements(doomed, {});
    if (!removed) return removed.refusal();
    for (const Simplex& face : labelled)
        if (!is_mesh_face(mesh, face)) mesh.erase_face_label(face);
    return Done{};
}

}  // namespace sxk
