// Refinement along the tip's path (shaft_refinement.hpp).
#include "shaft_refinement.hpp"

#include <algorithm>
#include <cmath>

#include "needle_frame.hpp"
#include "sxk/ops/refine_around.hpp"
#include "sxk/ops/refine_around_tetrahedra.hpp"

namespace sxk::needle {

namespace {

// x (deformed) located with `hint`, in the reference positions; nullopt outside the mesh.
std::optional<Point> in_reference(const Mesh& mesh, const SpatialIndex& deformed, const Point& x,
                                  ElementId& hint) {
    const Location at = deformed.locate(x, hint);
    if (!at.found()) return std::nullopt;
    hint = at.element;
    Eigen::Vector3d reference = Eigen::Vector3d::Zero();
    const Simplex element = mesh.simplex(at.element);
    const auto vertices = element.vertices();
    for (std::size_t j = 0; j < vertices.size(); ++j) reference += at.barycentric[j] * vec(mesh.reference(vertices[j]));
    return point(reference);
}

}  // namespace

Outcome<Refinement> refine_along(Mesh& mesh, const SpatialIndex& reference, const SpatialIndex& deformed,
                                 const Point& from, const Point& to, double h, ElementId hint,
                                 TetBisection* bisection) {
    Refinement result;
    const double distance = (vec(to) - vec(from)).norm();
    const std::size_t pieces = std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil(distance / (0.5 * h))));
    const bool planar = mesh.topological_dimension() == 2;
    const double limit = bisection_edge_limit(mesh, h);
    for (std::size_t k = 1; k <= pieces; ++k) {
        const double t = static_cast<double>(k) / static_cast<double>(pieces);
        const Point x = k == pieces ? to : point(vec(from) + t * (vec(to) - vec(from)));
        const std::optional<Point> at = in_reference(mesh, deformed, x, hint);
        if (!at) continue;
        if (planar) {
            auto refined = refine_around(mesh, *at, limit, reference, hint);
            if (!refined) return refined.refusal();
            result.bisections += refined->bisections;
            hint = refined->element;
        } else {
            auto refined = bisection != nullptr ? refine_around_tetrahedra(*bisection, *at, limit, reference)
                                                : refine_around_tetrahedra(mesh, *at, limit, reference);
            if (!refined) return refined.refusal();
            result.bisections += *refined;
            hint = invalid_id;  // the tetrahedra around x changed; locate from the index
        }
    }
    const Location tip = deformed.locate(to, hint);
    result.tip_element = tip.element;
    return result;
}

}  // namespace sxk::needle
