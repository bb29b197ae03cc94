// Element quality (thesis §3.2.3) and the classification of degenerate tetrahedra.
#pragma once

#include <array>
#include <cstddef>
#include <span>
#include <string_view>
#include <vector>

#include "sxk/config.hpp"
#include "sxk/mesh.hpp"
#include "sxk/predicates.hpp"

namespace sxk {

inline constexpr double pi = 3.14159265358979323846;

// Thesis aspect ratio: minimum over vertices p of the distance from p to the plane (line) of
// the opposite face, divided by the maximum edge length. sqrt(2/3) ~ 0.8165 for the regular
// tetrahedron, sqrt(3)/2 ~ 0.866 for the equilateral triangle, 0 for flat elements.
SXK_API double aspect_ratio(std::span<const Point> vertices);
// d * inradius / circumradius, normalised so the regular simplex has 1 (d = 2 or 3).
SXK_API double radius_ratio(std::span<const Point> vertices);
// The six dihedral angles of a tetrahedron in radians, ordered by edge
// (01, 02, 03, 12, 13, 23): the angle at edge (i,j) between the two faces containing it.
SXK_API std::array<double, 6> dihedral_angles(std::span<const Point> tetrahedron);
// The three angles of a triangle at vertices 0, 1, 2, in radians (any ambient dimension).
SXK_API std::array<double, 3> triangle_angles(std::span<const Point> triangle);

// Distance from p to the line (2 points) or plane (3 points) through `face`, divided by the
// face's longest edge; infinity when the face has no line or plane (coincident or collinear
// points). The boundary tolerance of collapses and of degeneracy removal is measured so.
SXK_API double relative_distance_to_hull(std::span<const Point> face, const Point& p);

// The mean length of the mesh's edges, each counted once, in the given positions: the mesh size
// h the thesis measures distances in (its snapped test meshes, the snap cut's incision). 0 for a
// mesh without elements. Linear in the elements (pairs bucketed by their lower vertex).
SXK_API double mean_edge_length(const Mesh& mesh, Positions positions = Positions::reference);

// On a triangle surface in space: the pairs of neighbouring triangles whose normals, in the
// orientation the mesh gives them, face against each other (negative dot product, exactly by
// normal_alignment): folds of the surface, a flipped triangle among its neighbours. 0 for other
// meshes. Linear in the elements.
SXK_API std::size_t folded_neighbours(const Mesh& mesh, Positions positions = Positions::deformed);

// The volume of a tetrahedron (4 points, unsigned), of a 3D mesh's element t, and the mean over a
// 3D mesh's elements (0 for a mesh without elements), in the given positions: the material a
// piece of the mesh holds, in elements' worth.
SXK_API double tetrahedron_volume(std::span<const Point> tetrahedron);
SXK_API double element_volume(const Mesh& mesh, ElementId t, Positions positions = Positions::reference);
SXK_API double mean_element_volume(const Mesh& mesh, Positions positions = Positions::reference);

// The positions of element t's vertices in canonical order.
SXK_API std::vector<Point> element_points(const Mesh& mesh, ElementId t,
                                          Positions positions = Positions::deformed);

// Degenerate tetrahedra by their number of large dihedral angles (§3.2.3, Fig. 3.8):
// none (aspect ratio at or above the threshold), needle (0 large angles), spindle (1),
// sliver (2), cap (3 or more).
enum class DegenerateClass { none, needle, spindle, sliver, cap };
SXK_API std::string_view to_string(DegenerateClass c);

struct DegeneracyThresholds {
    double aspect_ratio = 0.01;      // below: degenerate
    double large_angle = 0.99 * pi;  // above: a large dihedral angle
};
SXK_API DegenerateClass classify_tetrahedron(std::span<const Point> tetrahedron,
                                             const DegeneracyThresholds& thresholds = {});

// Whole-mesh summary used by `sxk quality` and the demo.
struct QualitySummary {
    std::size_t elements = 0;
    double min_aspect_ratio = 0, max_aspect_ratio = 0, mean_aspect_ratio = 0;
    double min_radius_ratio = 0, mean_radius_ratio = 0;
    double min_angle = 0, max_angle = 0;  // dihedral angles (tets) or angles (triangles), radians
    std::size_t inverted = 0;             // exact orientation negative (when defined)
    std::size_t flat = 0;                 // exact orientation zero
    // by DegenerateClass (index = enum value); for triangles only needle/cap-like counts
    // are not meaningful and only `degenerate` is filled
    std::array<std::size_t, 5> by_class{};
    std::size_t degenerate = 0;  // aspect ratio below the threshold
    // aspect ratio histogram over [0, 1] in 10 bins
    std::array<std::size_t, 10> aspect_histogram{};
};
SXK_API QualitySummary summarize_quality(const Mesh& mesh, const DegeneracyThresholds& thresholds = {},
                                         Positions positions = Positions::deformed);

}  // namespace sxk
