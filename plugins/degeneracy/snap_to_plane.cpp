// Snapping vertices onto a plane (snap_to_plane.hpp): the snapped test meshes of degeneracy
// removal (thesis §3.2.2 node snapping, §3.3 results).
#include "snap_to_plane.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "sxk/predicates.hpp"
#include "sxk/quality.hpp"
#include "sxk/traversal.hpp"
#include "sxk/point_math.hpp"

namespace sxk::degeneracy {
namespace {

// p projected orthogonally onto the plane; `unit` is the plane's unit normal.
Point projected(const Point& p, const Point& on_plane, const Point& unit) {
    const double height = dot(minus(p, on_plane), unit);
    return {p[0] - height * unit[0], p[1] - height * unit[1], p[2] - height * unit[2]};
}

// Exact orientation of element t with vertex v at `at` (the other vertices where the mesh has
// them), in one position set: the sign element_orientation would give after the move. A triangle
// in space has only flatness (collinear vertices), as in element_orientation.
Sign orientation_with(const Mesh& mesh, ElementId t, VertexId v, const Point& at,
                      Positions positions) {
    const Simplex& s = mesh.simplex(t);
    auto point = [&](int j) -> const Point& {
        const VertexId w = s.vertex(j);
        if (w == v)
            return at;
        return positions == Positions::reference ? mesh.reference(w) : mesh.deformed(w);
    };
    Sign raw;
    if (mesh.topological_dimension() == 3) {
        raw = orient3d(point(0), point(1), point(2), point(3));
    } else if (mesh.ambient_dimension() == 2) {
        raw = orient2d(point(0), point(1), point(2));
    } else {
        return collinear(point(0), point(1), point(2)) ? Sign::zero : Sign::positive;
    }
    if (raw == Sign::zero)
        return raw;
    return static_cast<int>(raw) * s.sign() > 0 ? Sign::positive : Sign::negative;
}

// True when moving v to (reference, deformed) leaves every element of its star at least as well
// oriented as before in both position sets: a positive element stays positive (never flat or
// inverted: thesis §3.4 suggests "forbidding node relocations in those cases"), and one that is
// flat or inverted already may not get worse.
bool move_keeps_orientation(const Mesh& mesh, VertexId v, std::span<const ElementId> around,
                            const Point& reference, const Point& deformed) {
    for (const ElementId t : around)
        for (const Positions positions : {Positions::reference, Positions::deformed}) {
            const bool in_reference = positions == Positions::reference;
            const Sign before = orientation_with(
                mesh, t, v, in_reference ? mesh.reference(v) : mesh.deformed(v), positions);
            const Sign after =
                orientation_with(mesh, t, v, in_reference ? reference : deformed, positions);
            if (static_cast<int>(after) < static_cast<int>(before))
                return false;
        }
    return true;
}

std::string text(double x) {
    std::ostringstream out;
    out << x;
    return out.str();
}

}  // namespace

Plane plane_through_centre(const Mesh& mesh, const Point& normal) {
    if (mesh.vertex_count() == 0) return {{0, 0, 0}, normal};
    Point low = mesh.reference(0), high = low;
    for (VertexId v = 0; v < mesh.vertex_count(); ++v)
        for (std::size_t k = 0; k < 3; ++k) {
            low[k] = std::min(low[k], mesh.reference(v)[k]);
            high[k] = std::max(high[k], mesh.reference(v)[k]);
        }
    return {{(low[0] + high[0]) / 2, (low[1] + high[1]) / 2, (low[2] + high[2]) / 2}, normal};
}

SnapReport snap_to_plane(Mesh& mesh, const Plane& plane, double max_distance) {
    const double length = std::sqrt(dot(plane.normal, plane.normal));
    if (!(length > 0) || !std::isfinite(length))
        throw std::invalid_argument(
            "snap_to_plane: the plane's normal must be finite and not zero");
    if (!(max_distance >= 0) || !std::isfinite(max_distance))
        throw std::invalid_argument("snap_to_plane: max_distance must be finite and >= 0, not " +
                                    text(max_distance));
    const Point unit{plane.normal[0] / length, plane.normal[1] / length, plane.normal[2] / length};

    SnapReport report;
    report.mean_edge_length = sxk::mean_edge_length(mesh);
    std::vector<ElementId> around;
    for (VertexId v = 0; v < mesh.vertex_count(); ++v) {
        if (mesh.vertex_element(v) == invalid_id)
            continue;  // in no element: not part of the mesh
        if (!(std::abs(dot(minus(mesh.reference(v), plane.point), unit)) <= max_distance))
            continue;
        const Point reference = projected(mesh.reference(v), plane.point, unit);
        const Point deformed = projected(mesh.deformed(v), plane.point, unit);
        if (reference == mesh.reference(v) && deformed == mesh.deformed(v))
            continue;  // on it already
        around.clear();
        collect_star(mesh, v, mesh.vertex_element(v), around);
        if (!move_keeps_orientation(mesh, v, around, reference, deformed)) {
            ++report.refused;
            continue;
        }
        mesh.set_reference(v, reference);
        mesh.set_deformed(v, deformed);
        report.moved.push_back(v);
    }
    return report;
}

std::vector<ElementId> elements_around(const Mesh& mesh, const std::vector<VertexId>& vertices) {
    return stars_of(mesh, vertices);
}

}  // namespace sxk::degeneracy
