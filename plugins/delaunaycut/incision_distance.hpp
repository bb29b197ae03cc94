// How closely a cut follows the scalpel (thesis §5.4: "the subdivision cut follows the scalpel path
// more closely"): the distance of the incision's nodes from the point scalpel's path in the plane, or
// from the surface a line scalpel swept in space.
#pragma once

#include <cstddef>
#include <span>

#include "surface_cut.hpp"
#include "sxk/mesh.hpp"

namespace sxk::delaunaycut {

// The distance from p to the polyline `path` (x, y only); infinity for an empty path.
double distance_to_path(const Point& p, std::span<const Point> path);

// Over the nodes of the boundary edges labelled `cut_label` (deformed positions).
struct IncisionDistance {
    std::size_t nodes = 0;
    double farthest = 0, mean = 0;
};
IncisionDistance incision_distance(const Mesh& mesh, std::span<const Point> path, int cut_label);

// The distance from p to the surface the blade swept along `blades`: each movement's two triangles
// (h, t, t') and (h, t', h'), a bilinear patch's approximation; infinity for no blade.
double distance_to_sweep(const Point& p, std::span<const Blade> blades);
IncisionDistance incision_distance(const Mesh& mesh, std::span<const Blade> blades, int cut_label);

}  // namespace sxk::delaunaycut
