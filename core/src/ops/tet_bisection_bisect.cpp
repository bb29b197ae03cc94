// bisect_tetrahedron: thesis §6.5 bisect(e) in 3D, with Maubach / longest-edge marks
// (tet_bisection.hpp).
#include <string>
#include <vector>

#include "ops/tet_bisection_recursion.hpp"
#include "sxk/ops/split_edge.hpp"
#include "sxk/ops/tet_bisection.hpp"

namespace sxk {

Outcome<std::size_t> bisect_tetrahedron(TetBisection& state, ElementId t) {
    Mesh& mesh = *state.m_mesh;
    if (!mesh.is_element(t))
        return Refusal{"bisect_tetrahedron: " + std::to_string(t) + " is not an element"};
    if (state.is_stale())
        return Refusal{"bisect_tetrahedron: the bisection state is stale: " + state.stale_reason()};

    std::vector<TetMarking> parents;
    auto split = [&](VertexId a, VertexId b, std::span<const ElementId> ring) -> Outcome<SplitResult> {
        parents.clear();
        for (ElementId u : ring) parents.push_back(state.marking(u));
        state.m_own_edit = true;
        auto result = split_edge(mesh, a, b, 0.5);
        state.m_own_edit = false;
        if (!result.ok()) return result;
        if (state.m_markings.size() < mesh.element_capacity())
            state.m_markings.resize(mesh.element_capacity());
        for (const ElementId child : result->elements) {
            // the parent is the one whose c and d the child has; the child keeps a or b
            const Simplex& simplex = mesh.simplex(child);
            for (const TetMarking& parent : parents) {
                if (!simplex.contains(parent.vertices[2]) || !simplex.contains(parent.vertices[3]))
                    continue;
                if (state.m_rule == BisectionRule::longest_edge) {
                    state.m_markings[child] = longest_edge_marking(mesh, child);
                    state.m_markings[child].generation = parent.generation + 1;
                } else {
                    const auto halves = bisected_markings(parent, result->vertex);
                    state.m_markings[child] =
                        simplex.contains(parent.vertices[0]) ? halves[0] : halves[1];
                }
                break;
            }
        }
        if (!result->elements.empty()) state.m_last_child = result->elements.back();
        return result;
    };
    bool did_not_end = false;
    auto bisected = detail::bisect_recursively(
        mesh, state.refinement_edge(t),
        [&](ElementId u) { return state.refinement_edge(u); }, split, did_not_end);
    if (did_not_end) state.m_stale_reason = bisected.reason();
    if (!bisected.ok()) return Refusal{"bisect_tetrahedron: " + bisected.reason()};
    return bisected;
}

}  // namespace sxk
