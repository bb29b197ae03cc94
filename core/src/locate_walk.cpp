// The visibility walks of sxk/locate.hpp (they were refine_around's and
// refine_around_tetrahedra's own), and the index-less point locations built on them.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>

#include "locate_trees.hpp"
#include "sxk/locate.hpp"
#include "sxk/predicates.hpp"

namespace sxk {
namespace {

bool finite_query(const Mesh& mesh, const Point& x) {
    for (int k = 0; k < mesh.ambient_dimension(); ++k)
        if (!std::isfinite(x[static_cast<std::size_t>(k)])) return false;
    return true;
}

Sign orientation(const std::array<const Point*, 4>& p, int dimension) {
    return dimension == 2 ? orient2d(*p[0], *p[1], *p[2]) : orient3d(*p[0], *p[1], *p[2], *p[3]);
}

// -1: x is inside the closed element t. Otherwise a face i of t (opposite its vertex i) with x
// strictly on its far side, trying the faces from `first` on; -2 for a flat element. The signs
// are compared with t's own orientation, so inverted elements (deformed positions) are closed
// simplexes too.
int outside_face(const Mesh& mesh, ElementId t, const Point& x, std::uint32_t first, Positions positions) {
    const int d = mesh.topological_dimension();
    const detail::ElementPoints e = detail::element_points(mesh, t, positions);
    const int whole = static_cast<int>(orientation(e.p, d));
    if (whole == 0) return -2;
    const auto count = static_cast<std::uint32_t>(d + 1);
    for (std::uint32_t k = 0; k < count; ++k) {
        const std::size_t i = (first + k) % count;
        std::array<const Point*, 4> q = e.p;
        q[i] = &x;
        if (static_cast<int>(orientation(q, d)) * whole < 0) return static_cast<int>(i);
    }
    return -1;
}

// Planar meshes: the stochastic walk, the face tried first picked by a small local xorshift so
// that the walk cannot cycle on meshes that are not Delaunay.
ElementId walk_triangles(const Mesh& mesh, const Point& x, ElementId t, Positions positions, std::size_t max_steps) {
    std::uint32_t state = 0x9e3779b9u;
    for (std::size_t step = 0; step <= max_steps; ++step) {
        state ^= state << 13;
        state ^= state >> 17;
        state ^= state << 5;
        const int face = outside_face(mesh, t, x, state % 3, positions);
        if (face == -1) return t;
        if (face == -2) return invalid_id;
        const ElementId next = mesh.neighbor(t, face);
        if (next == invalid_id) return invalid_id;  // x outside, or a bay of the domain in the way
        t = next;
    }
    return invalid_id;
}

// Tetrahedral meshes: the face tried first rotates from step to step, which keeps the walk from
// circling in non-Delaunay meshes (walks in a mesh of n elements take about n^(1/3) steps).
ElementId walk_tetrahedra(const Mesh& mesh, const Point& x, ElementId t, Positions positions, std::size_t max_steps) {
    for (std::size_t step = 0; step < max_steps; ++step) {
        // the next element is one of these: its record is on its way while this one's positions
        // arrive (a walk on a mesh larger than the cache misses twice per step otherwise:
        // docs/performance.md "locate")
        for (int i = 0; i < 4; ++i)
            if (const ElementId u = mesh.neighbor(t, i); u != invalid_id) __builtin_prefetch(&mesh.simplex(u));
        const int face = outside_face(mesh, t, x, static_cast<std::uint32_t>(step % 4), positions);
        if (face == -1) return t;
        if (face == -2) return invalid_id;
        const ElementId next = mesh.neighbor(t, face);
        if (next == invalid_id) return invalid_id;
        t = next;
    }
    return invalid_id;
}

double surface_distance_squared(const Mesh& mesh, ElementId t, const Point& x, Positions positions,
                                std::array<double, 3>& weights) {
    const detail::ElementPoints e = detail::element_points(mesh, t, positions);
    weights = nearest_on_triangle(*e.p[0], *e.p[1], *e.p[2], x);
    Point q{};
    for (std::size_t k = 0; k < 3; ++k)
        q[k] = weights[0] * (*e.p[0])[k] + weights[1] * (*e.p[1])[k] + weights[2] * (*e.p[2])[k];
    return detail::distance_squared(q, x);
}

// Triangle surfaces in space: descend to a triangle nearest x. The nearest point of t lies on the
// edges whose opposite weight is 0; step across such an edge while the neighbour is nearer.
ElementId walk_surface(const Mesh& mesh, const Point& x, ElementId t, Positions positions, std::size_t max_steps) {
    std::array<double, 3> w{};
    double best = surface_distance_squared(mesh, t, x, positions, w);
    for (std::size_t step = 0; step < max_steps && best > 0; ++step) {
        ElementId next = invalid_id;
        double next_distance = best;
        const std::array<double, 3> here = w;
        for (int i = 0; i < 3; ++i) {
            if (here[static_cast<std::size_t>(i)] != 0) continue;
            const ElementId u = mesh.neighbor(t, i);
            if (u == invalid_id) continue;
            std::array<double, 3> wu{};
            if (const double du = surface_distance_squared(mesh, u, x, positions, wu); du < next_distance) {
                next = u;
                next_distance = du;
                w = wu;
            }
        }
        if (next == invalid_id) break;
        t = next;
        best = next_distance;
    }
    return t;
}

// Without a hint: jump-and-walk (Mücke, Saias and Zhu). Of about cbrt(n) elements spread evenly
// over the id range, start from the one whose first vertex is nearest x, so the walk is short
// instead of O(sqrt n) triangles from the first element (which dominated a call on a 1M-element
// mesh, docs/performance.md "refine_latency"). Deterministic: the same mesh and point give the
// same start.
ElementId jump_start(const Mesh& mesh, const Point& x) {
    const std::size_t capacity = mesh.element_capacity();
    const auto samples = std::max<std::size_t>(
        1, static_cast<std::size_t>(std::cbrt(static_cast<double>(mesh.element_count()))));
    ElementId best = invalid_id;
    double best_distance = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < samples; ++i) {
        const auto t = static_cast<ElementId>(i * capacity / samples);
        if (!mesh.is_element(t)) continue;
        const Point& p = mesh.reference(mesh.simplex(t).vertex(0));
        const double distance = (p[0] - x[0]) * (p[0] - x[0]) + (p[1] - x[1]) * (p[1] - x[1]);
        if (distance < best_distance) {
            best_distance = distance;
            best = t;
        }
    }
    return best != invalid_id ? best : *elements(mesh).begin();
}

// The walk failed: every element is tested (O(n), only for points the walk cannot see).
ElementId scan(const Mesh& mesh, const Point& x) {
    for (const ElementId u : elements(mesh))
        if (locate_in_element(mesh, u, x, Positions::reference).found()) return u;
    return invalid_id;
}

}  // namespace

ElementId walk_to_point(const Mesh& mesh, const Point& x, ElementId start, Positions positions,
                        std::size_t max_steps) {
    if (!mesh.is_element(start) || !finite_query(mesh, x)) return invalid_id;
    if (mesh.topological_dimension() < mesh.ambient_dimension())
        return walk_surface(mesh, x, start, positions, max_steps);
    if (mesh.topological_dimension() == 2) return walk_triangles(mesh, x, start, positions, max_steps);
    return walk_tetrahedra(mesh, x, start, positions, max_steps);
}

ElementId locate_triangle(const Mesh& mesh, const Point& x, ElementId hint) {
    if (mesh.topological_dimension() != 2 || mesh.ambient_dimension() != 2) return invalid_id;
    if (!finite_query(mesh, x) || mesh.element_count() == 0) return invalid_id;
    const ElementId start = mesh.is_element(hint) ? hint : jump_start(mesh, x);
    if (const ElementId found = walk_to_point(mesh, x, start, Positions::reference, mesh.element_count());
        found != invalid_id)
        return found;
    return scan(mesh, x);
}

ElementId locate_tetrahedron(const Mesh& mesh, const Point& x, ElementId start) {
    if (mesh.topological_dimension() != 3 || !finite_query(mesh, x)) return invalid_id;
    ElementId t = start;
    if (!mesh.is_element(t)) {
        const auto first = elements(mesh).begin();
        if (first == elements(mesh).end()) return invalid_id;
        t = *first;
    }
    // the step bound is a guard only
    constexpr std::size_t max_steps = std::size_t{1} << 16;
    if (const ElementId found = walk_to_point(mesh, x, t, Positions::reference, max_steps); found != invalid_id)
        return found;
    return scan(mesh, x);
}

}  // namespace sxk
