// refine_around_tetrahedra: thesis §6.5 refine-around(x, h) in 3D, on bisect_tetrahedron.
#include "sxk/ops/refine_around_tetrahedra.hpp"

#include <cmath>
#include <sstream>
#include <string>

#include "ops/tet_bisection_amp.hpp"
#include "ops/tet_bisection_plan.hpp"
#include "sxk/ops/split_edge.hpp"
#include "sxk/predicates.hpp"

namespace sxk {

namespace {

// True when x lies strictly beyond face i of element simplex s (the face opposite vertex i):
// replacing vertex i by x turns the positive element negative.
bool beyond_face(const Mesh& mesh, const Simplex& s, int i, const Point& x) {
    std::array<const Point*, 4> p{};
    for (int j = 0; j < 4; ++j)
        p[static_cast<std::size_t>(j)] = j == i ? &x : &mesh.reference(s.vertex(j));
    const Sign raw = orient3d(*p[0], *p[1], *p[2], *p[3]);
    return static_cast<int>(raw) * s.sign() < 0;
}

bool contains_point(const Mesh& mesh, ElementId t, const Point& x) {
    const Simplex& s = mesh.simplex(t);
    for (int i = 0; i < 4; ++i)
        if (beyond_face(mesh, s, i, x)) return false;
    return true;
}

std::string point_text(const Point& x) {
    std::ostringstream out;
    out << '(' << x[0] << ", " << x[1] << ", " << x[2] << ')';
    return out.str();
}

}  // namespace

ElementId locate_tetrahedron(const Mesh& mesh, const Point& x, ElementId start) {
    if (mesh.topological_dimension() != 3) return invalid_id;
    for (double c : x)
        if (!std::isfinite(c)) return invalid_id;
    ElementId t = start;
    if (!mesh.is_element(t)) {
        const auto first = elements(mesh).begin();
        if (first == elements(mesh).end()) return invalid_id;
        t = *first;
    }
    // Visibility walk: step through a face that has x strictly beyond it. The face tried first
    // rotates from step to step, which keeps the walk from circling in non-Delaunay meshes; the
    // step bound is a guard only (walks in a mesh of n elements take about n^(1/3) steps).
    constexpr std::size_t max_steps = std::size_t{1} << 16;
    for (std::size_t step = 0; step < max_steps; ++step) {
        const Simplex& s = mesh.simplex(t);
        ElementId next = t;
        for (int k = 0; k < 4; ++k) {
            const int i = static_cast<int>((static_cast<std::size_t>(k) + step) % 4);
            if (beyond_face(mesh, s, i, x)) {
                next = mesh.neighbor(t, i);
                break;
            }
        }
        if (next == t) return t;
        if (next == invalid_id) break;  // the walk left the mesh: x is outside, or behind a bay
        t = next;
    }
    // x outside, or a non-convex domain blocked the walk: test every element (linear, but only
    // reached for points that are not where the walk can see them).
    for (ElementId u : elements(mesh))
        if (contains_point(mesh, u, x)) return u;
    return invalid_id;
}

Outcome<std::size_t> refine_around_tetrahedra(TetBisection& state, const Point& x, double h) {
    Mesh& mesh = state.mesh();
    if (mesh.topological_dimension() != 3)
        return Refusal{RefusalCode::wrong_dimension,
                       "refine_around_tetrahedra: the mesh has triangles, not tetrahedra"};
    if (!(h > 0)) {  // negated so that NaN is refused too
        std::ostringstream out;
        out << "refine_around_tetrahedra: h = " << h << " is not positive";
        return Refusal{RefusalCode::bad_argument, out.str()};
    }
    if (state.is_stale())
        return Refusal{RefusalCode::stale,
                       "refine_around_tetrahedra: the bisection state is stale: " +
                       state.stale_reason()};
    const ElementId t = locate_tetrahedron(mesh, x, state.last_child());
    if (t == invalid_id)
        return Refusal{RefusalCode::not_found,
                       "refine_around_tetrahedra: point " + point_text(x) + " is not in the mesh"};

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

Outcome<std::size_t> refine_around_tetrahedra(Mesh& mesh, const Point& x, double h) {
    if (mesh.topological_dimension() != 3)
        return Refusal{RefusalCode::wrong_dimension,
                       "refine_around_tetrahedra: the mesh has triangles, not tetrahedra"};
    if (!(h > 0)) {
        std::ostringstream out;
        out << "refine_around_tetrahedra: h = " << h << " is not positive";
        return Refusal{RefusalCode::bad_argument, out.str()};
    }
    const ElementId t = locate_tetrahedron(mesh, x, invalid_id);
    if (t == invalid_id)
        return Refusal{RefusalCode::not_found,
                       "refine_around_tetrahedra: point " + point_text(x) + " is not in the mesh"};
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
    for (const auto& e : plan.splits())
        if (auto split = split_edge(mesh, e[0], e[1], 0.5); !split.ok())
            return Refusal{RefusalCode::internal_error,
                           "refine_around_tetrahedra: internal error, a planned bisection was "
                           "refused: " +
                           split.reason()};
    return planned;
}

}  // namespace sxk
