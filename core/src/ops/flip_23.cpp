// flip_23 (thesis §5.2.2, face flip; connectivity edit by §7.3 replace-elements).
#include "sxk/ops/flip_23.hpp"

#include "ops/label_constraints.hpp"
#include "ops/tet_flip_checks.hpp"

namespace sxk {

Outcome<std::array<ElementId, 3>> flip_23(Mesh& mesh, FaceId face, const TetFlipOptions& options) {
    if (mesh.topological_dimension() != 3)
        return Refusal{RefusalCode::wrong_dimension, "flip_23: needs a tetrahedral mesh"};
    if (!mesh.is_face(face))
        return Refusal{RefusalCode::not_found,
                       "flip_23: " + std::to_string(face) + " is not a face"};
    const FaceId other = mesh.mate(face);
    if (other == invalid_id)
        return Refusal{RefusalCode::not_applicable, "flip_23: face " + std::to_string(face) + " " +
                                                        to_text(mesh.face_simplex(face)) +
                                                        " is on the boundary"};
    const ElementId t0 = mesh.face_element(face);
    const ElementId t1 = mesh.face_element(other);
    const std::array<ElementId, 2> pair{t0, t1};
    if (auto refused = detail::refuse_material_interface(mesh, pair, "flip_23"))
        return *refused;
    const VertexId p = mesh.opposite_vertex(t0, face);
    const VertexId q = mesh.opposite_vertex(t1, other);
    // Thesis Fig. 5.9: if p and q are already joined elsewhere, the flip would represent the
    // edge pq twice and the result would not be a manifold complex.
    if (!detail::embedding_proves_absence(options) && detail::edge_exists(mesh, p, q))
        return Refusal{RefusalCode::not_manifold,
                       "flip_23: edge " + to_text(Simplex(+1, {p, q})) + " already exists"};

    // simplex(t0) = sigma.sup(p) with sigma = face_simplex(face); substituting q for one vertex
    // of sigma keeps the orientation consistent (kernel.md: substituted re-sorts with its sign),
    // and the three results are exactly the tetrahedra around pq that fill t0 and t1.
    const Simplex tau = mesh.simplex(t0);
    const Simplex sigma = mesh.face_simplex(face);
    const std::array<Simplex, 3> created{tau.substituted(sigma.vertex(0), q),
                                         tau.substituted(sigma.vertex(1), q),
                                         tau.substituted(sigma.vertex(2), q)};
    // All three strictly positive <=> pq crosses the open triangle abc (the convexity
    // condition of the flip), in each set of positions.
    if (auto refused = detail::refuse_non_positive(mesh, created, options, "flip_23"))
        return *refused;

    const std::array<ElementId, 2> old{t0, t1};
    const std::array<int, 3> labels{mesh.label(t0), mesh.label(t0), mesh.label(t0)};
    if (auto refused = detail::refuse_vanishing_label(mesh, old, created, "flip_23"))
        return *refused;
    // Every new element and every new face that is not a hull face contains the new edge,
    // which is not in the mesh (checked above), and the hull faces are reused: the star
    // checks of replace_elements are proven (mesh_checks.hpp, ProvenEdit).
    auto result = ProvenEdit::replace(mesh, old, created, labels);
    if (!result.ok()) return result.refusal().prefixed("flip_23: ");
    const std::vector<ElementId>& ids = *result;
    return std::array<ElementId, 3>{ids[0], ids[1], ids[2]};
}

}  // namespace sxk
