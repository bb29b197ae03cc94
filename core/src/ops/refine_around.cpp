// refine-around(x, h) of thesis §6.5 (Fig. 6.8), planned on an overlay, then replayed.
#include "sxk/ops/refine_around.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <string>

#include "ops/bisect_2d_helpers.hpp"
#include "ops/index_check.hpp"
#include "ops/point_text.hpp"
#include "sxk/predicates.hpp"
#include "sxk/traversal.hpp"

namespace sxk {
namespace {

// The checks every entry point makes before locating x; nothing when they pass.
std::optional<Refusal> refuse_planar_arguments(const Mesh& mesh, double h) {
    if (mesh.topological_dimension() == 3)
        return Refusal{RefusalCode::wrong_dimension,
                       "refine_around: tetrahedral meshes use refine_around_tetrahedra"};
    if (mesh.ambient_dimension() != 2)
        return Refusal{RefusalCode::wrong_dimension,
                       "refine_around: needs a planar triangle mesh (ambient dimension 2)"};
    if (!(h > 0))
        return Refusal{RefusalCode::bad_argument,
                       "refine_around: size h = " + number_text(h) + " is not a positive number"};
    return std::nullopt;
}

// refine-around from the triangle `start` that contains x.
Outcome<RefineAroundResult> refine_from(Mesh& mesh, ElementId start, const Point& x, double h) {
    if (start == invalid_id)
        return Refusal{RefusalCode::not_found, "refine_around: point " + point_text(x, 2) + " is not in the mesh"};
    // refine-around's tail recursion as a loop, on the plan: after a bisection the triangle
    // that contained x has been split, and x is followed into the child that contains it
    detail::BisectionPlan plan(mesh);
    int current = plan.node_of(start);
    for (;;) {
        current = plan.leaf_containing(current, x);
        const detail::Edge hypotenuse = plan.hypotenuse(current);
        if (!(plan.length(hypotenuse) > h))
            break;
        if (auto refused = plan.bisect(hypotenuse, "refine_around"))
            return *refused;
    }
    auto applied = plan.apply(mesh, "refine_around");
    if (!applied)
        return applied.refusal();
    RefineAroundResult result;
    result.bisections = applied->size();
    // the planned leaf is an element now: find it by its simplex around one of its vertices
    // (locating x again could pick a coarser neighbour when x lies on an edge)
    const Simplex& leaf = plan.node(current).simplex;
    for (ElementId t : star(mesh, leaf.vertex(0)))
        if (mesh.simplex(t) == leaf)
            result.element = t;
    return result;
}

}  // namespace

Outcome<RefineAroundResult> refine_around(Mesh& mesh, const Point& x, double h, ElementId hint) {
    if (auto refused = refuse_planar_arguments(mesh, h))
        return *refused;
    return refine_from(mesh, locate_triangle(mesh, x, hint), x, h);
}

Outcome<RefineAroundResult> refine_around(Mesh& mesh, const Point& x, double h, const SpatialIndex& index,
                                          ElementId hint) {
    if (auto refused = refuse_planar_arguments(mesh, h))
        return *refused;
    if (auto refused = detail::refuse_index(mesh, index, "refine_around"))
        return *refused;
    return refine_from(mesh, index.locate(x, hint).element, x, h);
}

}  // namespace sxk
