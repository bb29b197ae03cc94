// flip_32 (thesis §5.2.2, edge removal, the inverse of the face flip; §7.3 replace-elements).
#include "sxk/ops/flip_32.hpp"

#include "ops/label_constraints.hpp"
#include "ops/tet_flip_checks.hpp"

namespace sxk {

Outcome<std::array<ElementId, 2>> flip_32(Mesh& mesh, FaceId entry, int j,
                                          const TetFlipOptions& options) {
    if (auto refused = detail::refuse_bad_edge_arguments(mesh, entry, j, "flip_32"))
        return *refused;
    const Simplex edge = mesh.face_simplex(entry).subn(j);
    const VertexId a = edge.vertex(0);
    const VertexId b = edge.vertex(1);
    auto found = detail::interior_edge_ring(mesh, entry, j, 3, "flip_32");
    if (!found) return found.refusal();
    const std::span<const ElementId> ring = found->span();
    if (auto refused = detail::refuse_material_interface(mesh, ring, "flip_32"))
        return *refused;

    // tau = <ab, c, d> for two ring vertices c, d; e is the ring vertex not in tau.
    const Simplex tau = mesh.simplex(ring[0]);
    VertexId c = invalid_id, d = invalid_id;
    for (const VertexId v : tau.vertices())
        if (v != a && v != b) (c == invalid_id ? c : d) = v;
    const VertexId e = detail::fourth_vertex(mesh.simplex(ring[1]).contains(c) ? mesh.simplex(ring[1])
                                                                              : mesh.simplex(ring[2]),
                                             a, b, c);
    // Thesis Fig. 5.9: if cde is already a triangle of the mesh (outside the ring, necessarily),
    // the flip would represent it three times.
    if (!detail::embedding_proves_absence(options) &&
        detail::star_has(mesh, c, [&](const Simplex& s) { return s.contains(d) && s.contains(e); }))
        return Refusal{RefusalCode::not_manifold,
                       "flip_32: triangle " + to_text(Simplex(+1, {c, d, e})) + " already exists"};
    // Replacing b (resp. a) by e in <ab,c,d> gives the tetrahedron <cde,a> (resp. <cde,b>) with
    // the orientation the ring induces: exactly the inverse of flip_23's substitutions.
    const std::array<Simplex, 2> created{tau.substituted(b, e), tau.substituted(a, e)};
    if (auto refused = detail::refuse_non_positive(mesh, created, options, "flip_32"))
        return *refused;

    const int label = mesh.label(mesh.face_element(entry));
    const std::array<int, 2> labels{label, label};
    if (auto refused = detail::refuse_vanishing_label(mesh, ring, created, "flip_32"))
        return *refused;
    // Both new elements and the one new face pair contain the triangle cde, which is not in the
    // mesh (checked above), and the hull faces are reused: the star checks of
    // replace_elements are proven (mesh_checks.hpp, ProvenEdit).
    auto result = ProvenEdit::replace(mesh, ring, created, labels);
    if (!result.ok()) return result.refusal().prefixed("flip_32: ");
    const std::vector<ElementId>& ids = *result;
    return std::array<ElementId, 2>{ids[0], ids[1]};
}

}  // namespace sxk
