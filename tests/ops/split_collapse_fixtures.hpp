// Helpers shared by the split_edge / split_face / split_element / collapse_edge tests.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "core/fixtures.hpp"
#include "sxk/mesh.hpp"
#include "sxk/ops/remove_elements.hpp"
#include "sxk/predicates.hpp"
#include "sxk/traversal.hpp"

namespace sxk::test {

// Sorted oriented simplexes of all elements: what a split followed by the collapse of the new
// vertex must restore (element ids may differ).
inline std::vector<Simplex> sorted_simplexes(const Mesh& mesh) {
    std::vector<Simplex> all;
    for (ElementId t : elements(mesh)) all.push_back(mesh.simplex(t));
    std::sort(all.begin(), all.end());
    return all;
}

inline std::string text(const Simplex& sigma) {
    std::ostringstream out;
    out << sigma;
    return out.str();
}

// Every element strictly positive by exact orientation in both position sets.
inline bool all_strictly_positive(const Mesh& mesh) {
    for (ElementId t : elements(mesh))
        if (element_orientation(mesh, t, Positions::reference) != Sign::positive ||
            element_orientation(mesh, t, Positions::deformed) != Sign::positive)
            return false;
    return true;
}

// An edge whose tetrahedra are two fans joined only at the edge: a valid mesh (every vertex
// star face-connected through other tetrahedra) made from the 3 x 3 x 3 Kuhn cube by removing
// two tetrahedra of an edge's cycle that are not next to each other (found by search: the
// first pair whose removal remove_elements accepts).
struct TwoFanEdge {
    Mesh mesh;
    VertexId a = invalid_id, b = invalid_id;
};
inline std::optional<TwoFanEdge> two_fan_edge() {
    const Mesh cube = kuhn_cube(3);
    for (const ElementId t : elements(cube))
        for (int i = 0; i < 4; ++i)
            for (int j = i + 1; j < 4; ++j) {
                const VertexId a = cube.simplex(t).vertex(i), b = cube.simplex(t).vertex(j);
                std::vector<ElementId> around;
                for (const ElementId u : star(cube, a))
                    if (cube.simplex(u).contains(b)) around.push_back(u);
                if (around.size() < 5) continue;
                for (const ElementId u : around) {
                    if (u == t) continue;
                    bool adjacent = false;  // t and u share a face containing the edge
                    for (int k = 0; k < 4; ++k) adjacent = adjacent || cube.neighbor(t, k) == u;
                    if (adjacent) continue;
                    Mesh mesh = cube;
                    const std::array<ElementId, 2> doomed{t, u};
                    if (!remove_elements(mesh, doomed)) continue;
                    if (!mesh.validate()) continue;
                    return TwoFanEdge{std::move(mesh), a, b};
                }
            }
    return std::nullopt;
}

}  // namespace sxk::test
