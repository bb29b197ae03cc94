// Cutting elements free (thesis §3.2.3: "the remaining degeneracies are considered
// incollapsible, and they are removed by cutting them free, and removing them"): dissect along
// every face of the elements (thesis §7.3; vertices whose stars fall apart get copies), then
// remove the elements, now joined to nothing. The faces their neighbours had with them become
// boundary: the cracks of Fig. 3.16.
#include <vector>

#include "removal_steps.hpp"
#include "sxk/ops/dissect.hpp"
#include "sxk/ops/remove_elements.hpp"

namespace sxk::degeneracy::detail {

Outcome<Done> cut_free(Mesh& mesh, std::span<const ElementId> elements) {
    std::vector<Simplex> faces;
    for (const ElementId t : elements)
        for (int i = 0; i < mesh.element_vertex_count(); ++i)
            if (mesh.mate(mesh.face(t, i)) != invalid_id) faces.push_back(mesh.simplex(t).subn(i));
    if (!faces.empty()) {
        const auto dissected = dissect(mesh, faces);
        if (!dissected) return dissected.refusal().prefixed("cut free: ");
    }
    // Each element is now alone in the star of each of its vertices (all its faces are cut),
    // so removing it pinches no star. One edit removes them all.
    // Labels of faces that go with the elements (each was theirs alone after the dissection)
    // are dropped; a face with the same vertices that still exists is a neighbour's boundary
    // face now, and keeps the label (remove_elements).
    if (Outcome<Done> removed = remove_elements(mesh, elements); !removed)
        return removed.refusal().prefixed("cut free: ");
    return Done{};
}

}  // namespace sxk::degeneracy::detail
