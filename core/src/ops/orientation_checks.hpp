// The geometric checks of simplexes that are not (yet) elements: exact orientation with some
// vertices at positions not (yet) in the mesh (MovedVertex: the new vertex of a split, the
// surviving vertex of a collapse), and the splits' rule that a child keeps its parent's
// orientation in both position sets (refuse_bad_children). Used by the splits
// (split_parents.hpp), collapse_edge.cpp and the tetrahedron bisections.
#pragma once

#include <algorithm>
#include <optional>
#include <span>
#include <string>

#include "mesh_checks.hpp"
#include "ops/filtered_triangle_tests.hpp"
#include "sxk/mesh.hpp"
#include "sxk/outcome.hpp"
#include "sxk/predicates.hpp"

namespace sxk::detail {

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
        return collinear_filtered(point(0), point(1), point(2), triangle_normal(point(0), point(1), point(2)))
                   ? Sign::zero
                   : Sign::positive;
    if (raw == Sign::zero) return raw;
    return static_cast<int>(raw) * tau.sign() > 0 ? Sign::positive : Sign::negative;
}

// Splits share one rule: a child must keep its parent's orientation in both positions. In
// exact arithmetic a point strictly inside a simplex (or edge, or face) gives children of the
// parent's sign; the rounded new position can still make a child of a nearly flat parent flat,
// and that is refused rather than built. Nothing when all children are fine.
// Children of parents containing every vertex of `vanishing_with` (when not empty) are not
// checked (SplitOptions: the caller removes them in its next edit).
inline std::optional<Refusal> refuse_bad_children(const Mesh& mesh,
                                                  std::span<const Simplex> children,
                                                  std::span<const ElementId> parents_of_children,
                                                  const MovedVertex& moved, const char* operation,
                                                  std::span<const VertexId> vanishing_with = {}) {
    auto vanishing = [&](ElementId parent) {
        return !vanishing_with.empty() &&
               std::all_of(vanishing_with.begin(), vanishing_with.end(),
                           [&](VertexId v) { return mesh.simplex(parent).contains(v); });
    };
    for (const Positions positions : {Positions::reference, Positions::deformed}) {
        // children of one parent are consecutive: its orientation is computed once per run
        ElementId parent_id = invalid_id;
        Sign parent = Sign::zero;
        for (std::size_t i = 0; i < children.size(); ++i) {
            if (vanishing(parents_of_children[i])) continue;
            if (parents_of_children[i] != parent_id) {
                parent_id = parents_of_children[i];
                parent = simplex_orientation(mesh, mesh.simplex(parent_id), positions);
            }
            const Sign child = simplex_orientation(mesh, children[i], positions, moved);
            if (child == Sign::zero || child != parent)
                return Refusal{orientation_code(child),
                               std::string(operation) + ": new element " + to_text(children[i]) +
                                   (child == Sign::zero ? " would be flat" : " would be inverted") +
                                   " in the " + to_string(positions) + " positions",
                               i};
        }
    }
    return std::nullopt;
}

}  // namespace sxk::detail
