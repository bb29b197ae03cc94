// Refinement along the tip's path (shaft_refinement.hpp).
#include "shaft_refinement.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <Eigen/Geometry>

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
    return reference_of(mesh, at);
}

// The offsets from a point of the path to the points of its cross-section: rings at radii up to
// tube.radius, at most h / 2 apart, of points at most h / 2 apart (in the plane: two per radius).
std::vector<Eigen::Vector3d> cross_section(bool planar, const Tube& tube, double h) {
    std::vector<Eigen::Vector3d> out;
    if (!(tube.radius > 0)) return out;
    const Eigen::Vector3d axis = vec(tube.axis).normalized();
    const Eigen::Vector3d u = planar ? Eigen::Vector3d(-axis.y(), axis.x(), 0).normalized() : axis.unitOrthogonal();
    const Eigen::Vector3d w = axis.cross(u);
    const auto rings = static_cast<std::size_t>(std::ceil(tube.radius / (0.5 * h)));
    for (std::size_t ring = 1; ring <= rings; ++ring) {
        const double rho = tube.radius * static_cast<double>(ring) / static_cast<double>(rings);
        if (planar) {
            out.push_back(rho * u);
            out.push_back(-rho * u);
            continue;
        }
        const auto around = std::max<std::size_t>(6, static_cast<std::size_t>(std::ceil(2 * M_PI * rho / (0.5 * h))));
        for (std::size_t k = 0; k < around; ++k) {
            const double angle = 2 * M_PI * static_cast<double>(k) / static_cast<double>(around);
            out.push_back(rho * (std::cos(angle) * u + std::sin(angle) * w));
        }
    }
    return out;
}

}  // namespace

Outcome<Refinement> refine_along(Mesh& mesh, const SpatialIndex& reference, const SpatialIndex& deformed,
                                 const Point& from, const Point& to, double h, ElementId hint,
                                 TetBisection* bisection, const Tube& tube) {
    Refinement result;
    const Eigen::Vector3d a = vec(from), path = vec(to) - vec(from);
    const double distance = path.norm();
    if (!std::isfinite(distance))
        return Refusal{RefusalCode::bad_argument, "the tip moved farther than a double measures"};
    // only the stretch inside the mesh is sampled: the parameters where the path is in the boxes of
    // the elements it crosses (a needle that starts far away costs nothing for the way there)
    double first = 1, last = 0;
    for (const ElementId t : deformed.elements_crossed(from, to)) {
        double low = 0, high = 1;
        for (int k = 0; k < mesh.ambient_dimension(); ++k) {
            double box_low = std::numeric_limits<double>::infinity(), box_high = -box_low;
            for (const VertexId v : mesh.simplex(t).vertices()) {
                box_low = std::min(box_low, mesh.deformed(v)[k]);
                box_high = std::max(box_high, mesh.deformed(v)[k]);
            }
            if (path[k] == 0) continue;
            const double enter = (box_low - a[k]) / path[k], leave = (box_high - a[k]) / path[k];
            low = std::max(low, std::min(enter, leave));
            high = std::min(high, std::max(enter, leave));
        }
        first = std::min(first, low);
        last = std::max(last, high);
    }
    const double inside = std::max(last - first, 0.0) * distance;
    if (inside / (0.5 * h) > 1e6)
        return Refusal{RefusalCode::bad_argument, "the tip's path through the mesh is more than 500,000 h_ref long"};
    const std::size_t pieces = static_cast<std::size_t>(std::ceil(inside / (0.5 * h)));
    const bool planar = mesh.topological_dimension() == 2;
    const double limit = bisection_edge_limit(mesh, h);
    const std::vector<Eigen::Vector3d> across = cross_section(planar, tube, h);
    for (std::size_t k = 0; k <= pieces; ++k) {
        const double t =
            pieces == 0 ? 1.0 : first + (last - first) * static_cast<double>(k) / static_cast<double>(pieces);
        const Point centre = t >= 1 ? to : point(a + t * path);
        // the path's point, then its cross-section's
        for (std::size_t j = 0; j <= across.size(); ++j) {
            const Point x = j == 0 ? centre : point(vec(centre) + across[j - 1]);
            const std::optional<Point> at = in_reference(mesh, deformed, x, hint);
            if (!at) continue;
            // a point on the boundary in the deformed positions can map a rounding error outside the
            // reference mesh (a barycentric coordinate of -1e-17): nothing to refine there
            // (not_found), its neighbours are sampled
            if (planar) {
                auto refined = refine_around(mesh, *at, limit, reference, hint);
                if (!refined && refined.refusal().code == RefusalCode::not_found) continue;
                if (!refined) return refined.refusal();
                result.bisections += refined->bisections;
                hint = refined->element;
            } else {
                auto refined = bisection != nullptr ? refine_around_tetrahedra(*bisection, *at, limit, reference)
                                                    : refine_around_tetrahedra(mesh, *at, limit, reference);
                if (!refined && refined.refusal().code == RefusalCode::not_found) continue;
                if (!refined) return refined.refusal();
                result.bisections += *refined;
                hint = invalid_id;  // the tetrahedra around x changed; locate from the index
            }
        }
    }
    const Location tip = deformed.locate(to, hint);
    result.tip_element = tip.element;
    return result;
}

}  // namespace sxk::needle
