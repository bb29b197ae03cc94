// refine-around(x, h) of thesis §6.5 (Fig. 6.8), planned on an overlay, then replayed.
#include "sxk/ops/refine_around.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <sstream>
#include <string>

#include "ops/bisect_2d_helpers.hpp"
#include "sxk/predicates.hpp"
#include "sxk/traversal.hpp"

namespace sxk {
namespace {

std::string number_text(double value) {
    if (std::isnan(value))
        return "nan";
    std::ostringstream out;
    out << value;
    return out.str();
}

// -1: x is inside the closed triangle t. Otherwise a face i of t (opposite its vertex i) with x
// strictly on its far side; `turn` picks which one when there are two (the stochastic walk).
// -2 for a flat triangle.
int outside_face(const Mesh& mesh, ElementId t, const Point& x, std::uint32_t turn) {
    const Simplex& s = mesh.simplex(t);
    std::array<Point, 3> p{mesh.reference(s.vertex(0)), mesh.reference(s.vertex(1)),
                           mesh.reference(s.vertex(2))};
    const int o = static_cast<int>(orient2d(p[0], p[1], p[2]));
    if (o == 0)
        return -2;
    for (std::uint32_t k = 0; k < 3; ++k) {
        const std::size_t i = (turn + k) % 3;
        std::array<Point, 3> q = p;
        q[i] = x;
        if (static_cast<int>(orient2d(q[0], q[1], q[2])) * o < 0)
            return static_cast<int>(i);
    }
    return -1;
}

// Without a hint: jump-and-walk (Mücke, Saias and Zhu). Of about cbrt(n) elements spread evenly
// over the id range, start from the one whose first vertex is nearest x, so the walk is short
// instead of O(sqrt n) triangles from the first element (which dominated a call on a 1M-element
// mesh). Deterministic: the same mesh and point give the same start.
ElementId jump_start(const Mesh& mesh, const Point& x) {
    const std::size_t capacity = mesh.element_capacity();
    const auto samples = std::max<std::size_t>(
        1, static_cast<std::size_t>(std::cbrt(static_cast<double>(mesh.element_count()))));
    ElementId best = invalid_id;
    double best_distance = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < samples; ++i) {
        const auto t = static_cast<ElementId>(i * capacity / samples);
        if (!mesh.is_element(t))
            continue;
        const Point& p = mesh.reference(mesh.simplex(t).vertex(0));
        const double distance = (p[0] - x[0]) * (p[0] - x[0]) + (p[1] - x[1]) * (p[1] - x[1]);
        if (distance < best_distance) {
            best_distance = distance;
            best = t;
        }
    }
    return best != invalid_id ? best : *elements(mesh).begin();
}

}  // namespace

ElementId locate_triangle(const Mesh& mesh, const Point& x, ElementId hint) {
    if (mesh.topological_dimension() != 2 || mesh.ambient_dimension() != 2)
        return invalid_id;
    if (!std::isfinite(x[0]) || !std::isfinite(x[1]))
        return invalid_id;
    if (mesh.element_count() == 0)
        return invalid_id;
    ElementId t = mesh.is_element(hint) ? hint : jump_start(mesh, x);
    if (!mesh.is_element(t))
        return invalid_id;  // no elements at all
    // Stochastic visibility walk: moving across a face that separates t from x, picked with a
    // small local xorshift so that the walk cannot cycle on non-Delaunay meshes.
    std::uint32_t state = 0x9e3779b9u;
    for (std::size_t step = 0; step <= mesh.element_count(); ++step) {
        state ^= state << 13;
        state ^= state >> 17;
        state ^= state << 5;
        const int face = outside_face(mesh, t, x, state % 3);
        if (face == -1)
            return t;
        if (face == -2)
            break;
        const ElementId next = mesh.neighbor(t, face);
        if (next == invalid_id)
            break;
        t = next;
    }
    for (ElementId u : elements(mesh))
        if (outside_face(mesh, u, x, 0) == -1)
            return u;
    return invalid_id;
}

Outcome<RefineAroundResult> refine_around(Mesh& mesh, const Point& x, double h, ElementId hint) {
    if (mesh.topological_dimension() == 3)
        return Refusal{RefusalCode::wrong_dimension,
                       "refine_around: tetrahedral meshes use refine_around_tetrahedra"};
    if (mesh.ambient_dimension() != 2)
        return Refusal{RefusalCode::wrong_dimension,
                       "refine_around: needs a planar triangle mesh (ambient dimension 2)"};
    if (!(h > 0))
        return Refusal{RefusalCode::bad_argument,
                       "refine_around: size h = " + number_text(h) + " is not a positive number"};
    const ElementId start = locate_triangle(mesh, x, hint);
    if (start == invalid_id)
        return Refusal{RefusalCode::not_found,
                       "refine_around: point (" + number_text(x[0]) + ", " + number_text(x[1]) +
                       ") is not in the mesh"};

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

}  // namespace sxk
