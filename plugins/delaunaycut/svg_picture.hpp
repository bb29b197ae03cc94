// Pictures of planar cuts (thesis Figs. 5.8, 5.16, 5.17): the mesh with the scalpel's path over it,
// as SVG, and histograms of the triangles' smallest and largest angles.
#pragma once

#include <array>
#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "sxk/mesh.hpp"

namespace sxk::delaunaycut {

// An SVG drawing (about 800 pixels across) of a planar mesh in its deformed positions: triangles
// in grey, boundary edges in black, boundary edges with `cut_label` (the incision) in red, and the
// scalpel's path as a dotted blue line, with `title` above.
std::string mesh_svg(const Mesh& mesh, std::span<const Point> path, int cut_label, const std::string& title);

// The smallest and the largest angle of every triangle, in degrees.
struct AngleCounts {
    std::vector<double> smallest, largest;
};
AngleCounts triangle_angle_degrees(const Mesh& mesh);

// An SVG histogram of angles (degrees, 5-degree bins from 0 to 180) of several series drawn side by
// side in each bin (Fig. 5.17 compares the subdivision and the Delaunay cut's).
struct AngleSeries {
    std::string name;
    std::vector<double> degrees;
};
std::string angle_histogram_svg(const std::string& title, std::span<const AngleSeries> series);

}  // namespace sxk::delaunaycut
