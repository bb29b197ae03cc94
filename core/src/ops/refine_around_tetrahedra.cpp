// refine_around_tetrahedra: thesis §6.5 refine-around(x, h) in 3D, on bisect_tetrahedron.
#include "sxk/ops/refine_around_tetrahedra.hpp"

#include <cmath>
#include <optional>
#include <sstream>
#include <string>

#include "ops/index_check.hpp"
#include "ops/point_text.hpp"
#include "ops/tet_bisection_amp.hpp"
#include "ops/tet_bisection_plan.hpp"
#include "sxk/ops/split_edge.hpp"
#include "sxk/predicates.hpp"

namespace sxk {

namespace {

// The checks every entry point makes before locating x; nothing when they pass.
std::optional<Refusal> refuse_tetrahedral_arguments(const Mesh& mesh, double h) {
    if (mesh.topological_dimension() != 3)
        return Refusal{RefusalCode::wrong_dimension,
                       "refine_around_tetrahedra: the mesh has triangles, not tetrahedra"};
    if (!(h > 0)) {  // negated so that NaN is refused too
        std::ostringstream out;
        out << "refine_around_tetrahedra: h = " << h << " is not positive";
        return Refusal{RefusalCode::bad_argument, out.str()};
    }
    return std::nullopt;
}

std::optional<Refusal> refuse_stale(const TetBisection& state) {
    if (!state.is_stale())
        return std::nullopt;
    return Refusal{RefusalCode::stale,
                   "refine_around_tetrahedra: the bisection state is stale: " + state.stale_reason()};
}

Refusal not_in_mesh(const Point& x) {
    return Refusal{RefusalCode::not_found,
                   "refine_around_tetrahedra: point " + point_text(x, 3) + " is not in the mesh"};
}

// With a bisection state, from the tetrahedron t containing x.
Outcome<std::size_t> refine_with_state(TetBisection& state, ElementId t, const Point& x, double h) {
    Mesh& mesh = state.mesh();
    if (t == invalid_id) return not_in_mesh(x);
    if (state.rule() == BisectionRule::arnold_mukherjee_pouly) {
        // AMP: bisect the leaf containing x and close to conformity, until its refinement edge
        // is short enough; one transaction as well (tet_bisection_amp.hpp)
        auto refined = detail::amp_refine_around(state, t, x, h);
        if (!refined.ok())
            return refined.refusal().prefixed("refine_around_tetrahedra: bisect_tetrahedron: ");
        return refined;
    }
    // One transaction: every bisection of the call is planned on the overlay, then replayed.
    detail::TetBisectionPlan plan(mesh, state.rule(),
                                  [&state](ElementId u) { return state.marking(u); });
    bool did_not_end = false;
    auto planned = detail::plan_refine_around(plan, t, x, h, did_not_end);
    // a marking whose chains cycle will cycle again: the state says so from now on
    if (did_not_end) detail::TetBisectionAccess::make_stale(state, planned.reason());
    if (!planned.ok())
        return planned.refusal().prefixed("refine_around_tetrahedra: bisect_tetrahedron: ");
    if (auto replayed =
            detail::TetBisectionAccess::replay(state, plan.splits(), "refine_around_tetrahedra");
        !replayed.ok())
        return replayed.refusal();
    return planned;
}

// Without a state (longest-edge), from the tetrahedron t containing x.
Outcome<std::size_t> refine_stateless(Mesh& mesh, ElementId t, const Point& x, double h) {
    if (t == invalid_id) return not_in_mesh(x);
    // The longest-edge rule needs no stored marks: the refinement edge of an element is a
    // function of its vertices' reference positions, computed when asked (the plan computes the
    // original elements' on first use and its children's from their planned positions). So
    // this costs what it refines (no pass over the mesh), and calls in a row are one
    // longest-edge session.
    detail::TetBisectionPlan plan(mesh, BisectionRule::longest_edge,
                                  [&mesh](ElementId u) { return longest_edge_marking(mesh, u); });
    bool did_not_end = false;
    auto planned = detail::plan_refine_around(plan, t, x, h, did_not_end);
    if (!planned.ok()) return planned.refusal().prefixed("refine_around_tetrahedra: ");
    if (auto refused = detail::refuse_pinched_edges(mesh, plan.splits(), "refine_around_tetrahedra"))
        return *refused;
    for (const auto& e : plan.splits())
        if (auto split = split_edge(mesh, e[0], e[1], 0.5); !split.ok())
            return Refusal{RefusalCode::internal_error,
                           "refine_around_tetrahedra: internal error, a planned bisection was "
                           "refused: " +
                           split.reason()};
    return planned;
}

}  // namespace

Outcome<std::size_t> refine_around_tetrahedra(TetBisection& state, const Point& x, double h) {
    if (auto refused = refuse_tetrahedral_arguments(state.mesh(), h)) return *refused;
    if (auto refused = refuse_stale(state)) return *refused;
    return refine_with_state(state, locate_tetrahedron(state.mesh(), x, state.last_child()), x, h);
}

Outcome<std::size_t> refine_around_tetrahedra(TetBisection& state, const Point& x, double h,
                                              const SpatialIndex& index) {
    if (auto refused = refuse_tetrahedral_arguments(state.mesh(), h)) return *refused;
    if (auto refused = refuse_stale(state)) return *refused;
    if (auto refused = detail::refuse_index(state.mesh(), index, "refine_around_tetrahedra")) return *refused;
    return refine_with_state(state, index.locate(x, state.last_child()).element, x, h);
}

Outcome<std::size_t> refine_around_tetrahedra(Mesh& mesh, const Point& x, double h) {
    if (auto refused = refuse_tetrahedral_arguments(mesh, h)) return *refused;
    return refine_stateless(mesh, locate_tetrahedron(mesh, x, invalid_id), x, h);
}

Outcome<std::size_t> refine_around_tetrahedra(Mesh& mesh, const Point& x, double h, const SpatialIndex& index) {
    if (auto refused = refuse_tetrahedral_arguments(mesh, h)) return *refused;
    if (auto refused = detail::refuse_index(mesh, index, "refine_around_tetrahedra")) return *refused;
    return refine_stateless(mesh, index.locate(x).element, x, h);
}

}  // namespace sxk
