// Private helpers shared by flip_23.cpp, flip_32.cpp and flip_44.cpp: the checks every 3D flip
// makes before it hands its new simplexes to Mesh::replace_elements.
#pragma once

#include <algorithm>
#include <array>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "cycle_around.hpp"
#include "mesh_checks.hpp"
#include "sxk/mesh.hpp"
#include "sxk/ops/flip_options.hpp"
#include "sxk/outcome.hpp"
#include "sxk/predicates.hpp"
#include "sxk/traversal.hpp"

namespace sxk::detail {

// Exact orientation of an oriented tetrahedron that is not (yet) an element.
inline Sign tet_orientation(const Mesh& mesh, const Simplex& tau, Positions positions) {
    auto point = [&](int j) -> const Point& {
        return positions == Positions::reference ? mesh.reference(tau.vertex(j))
                                                 : mesh.deformed(tau.vertex(j));
    };
    const Sign raw = orient3d(point(0), point(1), point(2), point(3));
    if (raw == Sign::zero) return raw;
    return static_cast<int>(raw) * tau.sign() > 0 ? Sign::positive : Sign::negative;
}

// Nothing when every new tetrahedron is strictly positive in both positions (or the caller
// asked for topology only); otherwise a refusal naming the first offender and the positions.
inline std::optional<Refusal> refuse_non_positive(const Mesh& mesh,
                                                  std::span<const Simplex> created,
                                                  const TetFlipOptions& options,
                                                  const char* operation) {
    if (options.topology_only) return std::nullopt;
    for (const Positions positions : {Positions::reference, Positions::deformed})
        for (std::size_t i = 0; i < created.size(); ++i) {
            const Sign s = tet_orientation(mesh, created[i], positions);
            if (s != Sign::positive)
                return Refusal{orientation_code(s),
                               std::string(operation) + ": new tetrahedron " + to_text(created[i]) +
                                   (s == Sign::zero ? " would be flat" : " would be inverted") +
                                   " in the " +
                                   (positions == Positions::reference ? "reference" : "deformed") +
                                   " positions",
                               i};
        }
    return std::nullopt;
}

// edge_exists(mesh, v, w) (mesh_checks.hpp) walks star(v) (thesis §7.2) without allocating.

// True when some element of `ring` (the tetrahedra around edge a-b) has a boundary face
// containing a-b: then the edge lies on the boundary and its ring is not closed.
inline bool ring_touches_boundary(const Mesh& mesh, std::span<const ElementId> ring, VertexId a,
                                  VertexId b) {
    for (const ElementId t : ring) {
        const Simplex& tau = mesh.simplex(t);
        for (int i = 0; i < 4; ++i) {
            const VertexId v = tau.vertex(i);
            if (v != a && v != b && mesh.mate(mesh.face(t, i)) == invalid_id) return true;
        }
    }
    return false;
}

// The vertex of element t that is none of a, b, c (t must contain them).
inline VertexId fourth_vertex(const Simplex& tau, VertexId a, VertexId b, VertexId c) {
    for (const VertexId v : tau.vertices())
        if (v != a && v != b && v != c) return v;
    return invalid_id;
}

// Common argument checks for the edge flips: 3D mesh, entry a face, j in 0..2.
inline std::optional<Refusal> refuse_bad_edge_arguments(const Mesh& mesh, FaceId entry, int j,
                                                        const char* operation) {
    if (mesh.topological_dimension() != 3)
        return Refusal{RefusalCode::wrong_dimension,
                       std::string(operation) + ": needs a tetrahedral mesh"};
    if (!mesh.is_face(entry))
        return Refusal{RefusalCode::not_found,
                       std::string(operation) + ": " + std::to_string(entry) + " is not a face"};
    if (j < 0 || j > 2)
        return Refusal{RefusalCode::bad_argument, std::string(operation) + ": edge index " +
                                                      std::to_string(j) + " is not in 0..2"};
    return std::nullopt;
}

// The tetrahedra around an interior edge of degree 3 or 4, in ring order.
struct EdgeRing {
    std::array<ElementId, 4> elements{};
    std::size_t size = 0;
    std::span<const ElementId> span() const { return {elements.data(), size}; }
};

// The ring of tetrahedra around the interior edge face_simplex(entry).subn(j), which must have
// exactly `degree` of them (3 for flip_32, 4 for flip_44); a refusal otherwise.
inline Outcome<EdgeRing> interior_edge_ring(const Mesh& mesh, FaceId entry, int j,
                                            std::size_t degree, const char* operation) {
    const Simplex edge = mesh.face_simplex(entry).subn(j);
    const VertexId a = edge.vertex(0);
    const VertexId b = edge.vertex(1);
    SmallVector<ElementId, 64> ring;
    cycle_around_into(mesh, entry, j, ring);
    if (ring_touches_boundary(mesh, ring, a, b))
        return Refusal{RefusalCode::not_applicable, std::string(operation) + ": edge " +
                                                        to_text(Simplex(+1, {a, b})) +
                                                        " is on the boundary"};
    if (ring.size() != degree)
        return Refusal{RefusalCode::not_applicable,
                       std::string(operation) + ": edge " + to_text(Simplex(+1, {a, b})) +
                       " has degree " + std::to_string(ring.size()) + ", not " +
                       std::to_string(degree)};
    EdgeRing result;
    for (std::size_t i = 0; i < degree; ++i) result.elements[i] = ring[i];
    result.size = degree;
    return result;
}

}  // namespace sxk::detail
