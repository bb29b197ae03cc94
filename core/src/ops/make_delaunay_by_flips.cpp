// Lawson's edge-flip algorithm (thesis §5.2.1, after Lawson; the incremental flip algorithm the
// thesis cites as [40] builds on the same local step).
#include "sxk/ops/make_delaunay_by_flips.hpp"

#include <string>
#include <vector>

#include "sxk/ops/flip_edge.hpp"

namespace sxk {
namespace {

bool is_planar_triangle_mesh(const Mesh& mesh) {
    return mesh.topological_dimension() == 2 && mesh.ambient_dimension() == 2;
}

}  // namespace

bool is_locally_delaunay(const Mesh& mesh, FaceId edge, Positions positions) {
    if (mesh.topological_dimension() != 2 || !mesh.is_face(edge)) return true;
    const FaceId mate = mesh.mate(edge);
    if (mate == invalid_id) return true;
    const Simplex edge_simplex = mesh.face_simplex(edge);
    // <a,b> as the edge's element <a,b,c> sees it, so that a, b, c is its vertex order
    const VertexId a = edge_simplex.sign() > 0 ? edge_simplex.vertex(0) : edge_simplex.vertex(1);
    const VertexId b = edge_simplex.sign() > 0 ? edge_simplex.vertex(1) : edge_simplex.vertex(0);
    const VertexId c = mesh.opposite_vertex(mesh.face_element(edge), edge);
    const VertexId d = mesh.opposite_vertex(mesh.face_element(mate), mate);
    const Point& pa = position(mesh, a, positions);
    const Point& pb = position(mesh, b, positions);
    const Point& pc = position(mesh, c, positions);
    // a surface in space: the two triangles unfolded about the edge (thesis §5.3.1)
    if (mesh.ambient_dimension() == 3)
        return unfolded_incircle(pa, pb, pc, position(mesh, d, positions)) != Sign::positive;
    // incircle needs a counter-clockwise circle; anything else is outside this contract
    if (orient2d(pa, pb, pc) != Sign::positive) return true;
    return incircle(pa, pb, pc, position(mesh, d, positions)) != Sign::positive;
}

Outcome<std::size_t> make_delaunay_by_flips(Mesh& mesh, Positions positions) {
    if (!is_planar_triangle_mesh(mesh))
        return Refusal{RefusalCode::wrong_dimension,
                       "make_delaunay_by_flips: needs a planar triangle mesh (topological and "
                       "ambient dimension 2)"};
    // Lawson's argument (every illegal edge has a convex quadrilateral) needs a proper
    // triangulation: check every triangle before touching anything, so refusals are clean
    for (ElementId t : elements(mesh))
        if (element_orientation(mesh, t, positions) != Sign::positive)
            return Refusal{RefusalCode::not_applicable,
                           "make_delaunay_by_flips: element " + std::to_string(t) +
                               " is not counter-clockwise in the " +
                               (positions == Positions::reference ? "reference" : "deformed") + " positions",
                           t};

    // A stack of candidate edges. FaceIds of hull edges survive a flip; the old diagonal's ids
    // are freed and may be reused by a later edit, so stale entries are re-validated (is_face)
    // and at worst cost one extra incircle test.
    std::vector<FaceId> stack;
    for (ElementId t : elements(mesh))
        for (FaceId f : mesh.faces(t))
            if (mesh.mate(f) != invalid_id && f < mesh.mate(f)) stack.push_back(f);

    // incircle > 0 on two counter-clockwise triangles implies a strictly convex quadrilateral
    // (§5.2.1), so the geometric checks of flip_edge are already decided for `positions`. The
    // other set decides nothing about Delaunay-ness, but a flip must not invert or flatten a
    // triangle there: such an edge stays, like a constraint (see the header).
    const FlipOptions options{.topology_only = true};
    const Positions other = positions == Positions::reference ? Positions::deformed : Positions::reference;
    auto keeps_other_set_positive = [&](FaceId edge) {
        const Simplex edge_simplex = mesh.face_simplex(edge);
        const VertexId a = edge_simplex.sign() > 0 ? edge_simplex.vertex(0) : edge_simplex.vertex(1);
        const VertexId b = edge_simplex.sign() > 0 ? edge_simplex.vertex(1) : edge_simplex.vertex(0);
        const VertexId c = mesh.opposite_vertex(mesh.face_element(edge), edge);
        const VertexId d = mesh.opposite_vertex(mesh.face_element(mesh.mate(edge)), mesh.mate(edge));
        // the quadrilateral a, d, b, c is counter-clockwise; the flip makes <a,d,c> and <d,b,c>
        const Point &pa = position(mesh, a, other), &pb = position(mesh, b, other);
        const Point &pc = position(mesh, c, other), &pd = position(mesh, d, other);
        return orient2d(pa, pd, pc) == Sign::positive && orient2d(pd, pb, pc) == Sign::positive;
    };
    std::size_t flips = 0;
    while (!stack.empty()) {
        const FaceId edge = stack.back();
        stack.pop_back();
        if (!mesh.is_face(edge) || is_locally_delaunay(mesh, edge, positions) || !keeps_other_set_positive(edge))
            continue;
        // In a valid planar triangulation a convex quadrilateral's other diagonal cannot exist
        // (it would cross a-b), so the flip is refused only at a constraint: an interface
        // between labels or a labelled edge stays (the result is then constrained Delaunay).
        auto flipped = flip_edge(mesh, edge, options);
        if (!flipped) continue;
        ++flips;
        for (ElementId t : flipped.value())
            for (FaceId f : mesh.faces(t)) {
                const FaceId m = mesh.mate(f);
                // the new diagonal is locally Delaunay by construction; push only hull edges
                if (m == invalid_id) continue;
                const ElementId other = mesh.face_element(m);
                if (other == flipped.value()[0] || other == flipped.value()[1]) continue;
                stack.push_back(f);
            }
    }
    return flips;
}

}  // namespace sxk
