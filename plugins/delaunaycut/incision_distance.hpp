// How closely a planar cut follows the scalpel's path (thesis §5.4: "the subdivision cut follows
// the scalpel path more closely"): the distance of the incision's nodes from the path.
#pragma once

#include <cstddef>
#include <span>

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

}  // namespace sxk::delaunaycut
