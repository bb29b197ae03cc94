// flip_44 (thesis §5.2.2; a 2-3 and a 3-2 flip fused into one §7.3 replace-elements).
#include "sxk/ops/flip_44.hpp"

#include "ops/label_constraints.hpp"
#include "ops/tet_flip_checks.hpp"

namespace sxk {

Outcome<std::array<ElementId, 4>> flip_44(Mesh& mesh, FaceId entry, int j, int diagonal,
                                          const TetFlipOptions& options) {
    if (auto refused = detail::refuse_bad_edge_arguments(mesh, entry, j, "flip_44"))
        return *refused;
    if (diagonal != 0 && diagonal != 1)
        return Refusal{RefusalCode::bad_argument,
                       "flip_44: diagonal " + std::to_string(diagonal) + " is not 0 or 1"};
    const Simplex edge = mesh.face_simplex(entry).subn(j);
    const VertexId a = edge.vertex(0);
    const VertexId b = edge.vertex(1);
    auto found = detail::interior_edge_ring(mesh, entry, j, 4, "flip_44");
    if (!found) return found.refusal();
    const std::span<const ElementId> ring = found->span();
    if (auto refused = detail::refuse_material_interface(mesh, ring, "flip_44"))
        return *refused;

    // v[k] = the vertex shared by ring[k] and ring[k+1] besides a and b (ring order).
    std::array<VertexId, 4> v{};
    for (std::size_t k = 0; k < 4; ++k) {
        const Simplex& s = mesh.simplex(ring[k]);
        const Simplex& next = mesh.simplex(ring[(k + 1) % 4]);
        for (const VertexId x : s.vertices())
            if (x != a && x != b && next.contains(x)) v[k] = x;
    }
    const std::size_t m = static_cast<std::size_t>(diagonal);
    const VertexId u = v[m], w = v[m + 2];
    if (!detail::embedding_proves_absence(options) && detail::edge_exists(mesh, u, w))
        return Refusal{RefusalCode::not_manifold,
                       "flip_44: edge " + to_text(Simplex(+1, {u, w})) + " already exists"};

    // As flip_23 on the face <a,b,v[m+1]> (apexes v[m], v[m+2]) then flip_32 on the edge ab
    // (ring v[m], v[m+2], v[m+3]); every tetrahedron is a vertex substitution of
    // R = ring[m+1] = <ab, v[m], v[m+1]>, so all are oriented as the ring induces.
    const Simplex r = mesh.simplex(ring[m + 1]);
    const VertexId x = v[m + 2];
    const VertexId y = v[(m + 3) % 4];
    const Simplex middle = r.substituted(v[m + 1], x);  // <ab, v[m], v[m+2]>, gone after 3-2
    const std::array<Simplex, 4> created{r.substituted(a, x), r.substituted(b, x),
                                         middle.substituted(b, y), middle.substituted(a, y)};
    if (auto refused = detail::refuse_non_positive(mesh, created, options, "flip_44"))
        return *refused;

    const int label = mesh.label(mesh.face_element(entry));
    const std::array<int, 4> labels{label, label, label, label};
    if (auto refused = detail::refuse_vanishing_label(mesh, ring, created, "flip_44"))
        return *refused;
    // Every new element and every new face that is not a hull face contains the new edge,
    // which is not in the mesh (checked above), and the hull faces are reused: the star
    // checks of replace_elements are proven (mesh_checks.hpp, ProvenEdit).
    auto result = ProvenEdit::replace(mesh, ring, created, labels);
    if (!result.ok()) return result.refusal().prefixed("flip_44: ");
    const std::vector<ElementId>& ids = *result;
    return std::array<ElementId, 4>{ids[0], ids[1], ids[2], ids[3]};
}

}  // namespace sxk
