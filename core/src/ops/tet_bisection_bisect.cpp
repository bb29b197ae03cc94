// bisect_tetrahedron: thesis §6.5 bisect(e) in 3D, with Maubach / longest-edge marks
// (tet_bisection.hpp). Planned on an overlay first, then replayed (tet_bisection_plan.hpp); the
// AMP rule refines to conformity instead (tet_bisection_amp.hpp).
#include <string>

#include "ops/tet_bisection_amp.hpp"
#include "ops/tet_bisection_plan.hpp"
#include "sxk/ops/tet_bisection.hpp"

namespace sxk {

Outcome<std::size_t> bisect_tetrahedron(TetBisection& state, ElementId t) {
    Mesh& mesh = *state.m_mesh;
    if (!mesh.is_element(t))
        return Refusal{RefusalCode::not_found,
                       "bisect_tetrahedron: " + std::to_string(t) + " is not an element"};
    if (state.is_stale())
        return Refusal{RefusalCode::stale,
                       "bisect_tetrahedron: the bisection state is stale: " + state.stale_reason()};

    if (state.rule() == BisectionRule::arnold_mukherjee_pouly) {
        auto bisected = detail::amp_bisect(state, t);
        if (!bisected.ok()) return bisected.refusal().prefixed("bisect_tetrahedron: ");
        return bisected;
    }
    detail::TetBisectionPlan plan(mesh, state.rule(),
                                  [&state](ElementId u) { return state.marking(u); });
    bool did_not_end = false;
    auto planned = plan.bisect(plan.node_of(t), did_not_end);
    // a marking whose chains cycle will cycle again: the state says so from now on
    if (did_not_end) state.m_stale_reason = planned.reason();
    if (!planned.ok()) return planned.refusal().prefixed("bisect_tetrahedron: ");
    if (auto replayed = detail::TetBisectionAccess::replay(state, plan.splits(), "bisect_tetrahedron");
        !replayed.ok())
        return replayed.refusal();
    return planned;
}

}  // namespace sxk
