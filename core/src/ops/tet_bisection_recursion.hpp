// Private: the recursion of thesis §6.5 bisect(e) in 3D, shared by bisect_tetrahedron (marks kept
// in a TetBisection) and the state-less refine_around_tetrahedra (longest edges computed on the
// fly). Iterative with an explicit stack of edges. It runs on the plan's overlay
// (tet_bisection_plan.hpp), never on the mesh itself: the mesh is edited only by the replay.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "sxk/mesh.hpp"
#include "sxk/outcome.hpp"

namespace sxk::detail {

inline bool is_same_edge(const std::array<VertexId, 2>& e, VertexId u, VertexId v) {
    return (e[0] == u && e[1] == v) || (e[0] == v && e[1] == u);
}

// Bisects the edge `first` once every tetrahedron around it has it as refinement edge: the top
// edge of the stack is split when no tetrahedron around it is refined elsewhere, otherwise the
// refinement edge of the first one that is gets pushed. ring(a, b) gives the tetrahedra around
// ab (any handle type), refinement_edge(handle) their marks; split(a, b, ring) makes the edit
// (split_edge at 1/2) and records the children. Returns the number of splits. `did_not_end` is
// set when the stack outgrew its bound (64 + 4 * element_count: a marking whose chains cycle),
// which turns an endless loop into a refusal.
template <class Ring, class RefinementEdge, class Split>
Outcome<std::size_t> bisect_recursively(std::size_t element_count, std::array<VertexId, 2> first,
                                        Ring&& ring_of, RefinementEdge&& refinement_edge,
                                        Split&& split, bool& did_not_end) {
    did_not_end = false;
    std::vector<std::array<VertexId, 2>> stack{first};
    const std::size_t stack_limit = 64 + 4 * element_count;
    std::size_t splits = 0;
    while (!stack.empty()) {
        // plain variables, not a structured binding: the lambda below captures them (clang
        // before 16 cannot capture structured bindings)
        const VertexId a = stack.back()[0];
        const VertexId b = stack.back()[1];
        const auto ring = ring_of(a, b);
        if (ring.empty()) {  // split already, through another path of the recursion
            stack.pop_back();
            continue;
        }
        const auto blocker = std::find_if(ring.begin(), ring.end(), [&](const auto& u) {
            return !is_same_edge(refinement_edge(u), a, b);
        });
        if (blocker != ring.end()) {
            if (stack.size() >= stack_limit) {
                did_not_end = true;
                return Refusal{RefusalCode::bad_marking,
                               "the marking is not conforming: the recursion did not end"};
            }
            stack.push_back(refinement_edge(*blocker));
            continue;
        }
        auto result = split(a, b, ring);
        if (!result.ok()) return result.refusal();
        ++splits;
        stack.pop_back();
    }
    return splits;
}

}  // namespace sxk::detail
