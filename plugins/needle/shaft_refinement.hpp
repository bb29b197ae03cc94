// Refinement around the needle's tip as it moves (thesis §6.5 refine-around, §6.7 "refine mesh
// down to h_ref around the needle tip"): along the tip's whole path of a movement, so that a fast
// needle leaves no coarse stretch behind, and so the whole inserted shaft ends up refined.
#pragma once

#include <cstddef>
#include <span>

#include "sxk/locate.hpp"
#include "sxk/ops/tet_bisection.hpp"
#include "sxk/outcome.hpp"

namespace sxk::needle {

// Element sizes h are the thesis' h_k: the spacing of a uniform grid of that size, the legs of its
// right triangles (2D) or the cube edges of its Kuhn tetrahedra (3D). An element is of size h
// once its bisection edge (the hypotenuse; the longest edge) is at most sqrt(d) h long, d the
// dimension: a uniform grid of size h is then refined no further.
inline double bisection_edge_limit(const Mesh& mesh, double h) {
    return mesh.topological_dimension() == 2 ? h * 1.4142135623730951 : h * 1.7320508075688772;
}

// The reference position of a point located in the deformed positions (the same barycentric
// coordinates in the element's reference corners): where the tissue at a deformed point rests.
inline Point reference_of(const Mesh& mesh, const Location& at) {
    const Simplex element = mesh.simplex(at.element);
    const auto corners = element.vertices();
    return mesh.interpolated_positions(corners, std::span<const double>(at.barycentric.data(), corners.size())).first;
}

struct Refinement {
    std::size_t bisections = 0;          // new vertices
    ElementId tip_element = invalid_id;  // the element containing the tip afterwards (deformed)
};

// Points of the tip's path [from, to] (deformed positions) where it is inside the mesh (the stretch
// in the boxes of the elements it crosses), at most h / 2 apart, `to` last, each
// located in the deformed positions (walking from the previous one), taken into the reference
// positions through its element's barycentric coordinates (the tip moves through deformed
// material) and refined around there to size h: refine_around (triangles), or
// refine_around_tetrahedra with `bisection`'s rule (Maubach's newest-vertex bisection on Kuhn
// meshes, AMP's on others; without a state, longest-edge bisection), located through `reference`.
// Points outside the mesh are skipped, in the deformed positions or, by rounding at the boundary, in
// the reference ones. One call is not a transaction by itself: the session's step is.
// A needle with a radius (`tube`) refines its cross-section too: around each point of the path,
// rings of points up to the radius across the needle's axis, at most h / 2 apart (in the plane,
// the two points at each distance), so that the elements the needle's surface passes through are
// of size h (thesis Fig. 6.14's refinement around a 1 mm needle).
// Refuses (bad_argument) a path whose length is not a finite double, and one more than 500,000 h
// long inside the mesh.
struct Tube {
    double radius = 0;     // 0: a line, the path's points only
    Point axis{1, 0, 0};   // the needle's direction (unit), across which the rings lie
};
Outcome<Refinement> refine_along(Mesh& mesh, const SpatialIndex& reference, const SpatialIndex& deformed,
                                 const Point& from, const Point& to, double h, ElementId hint,
                                 TetBisection* bisection = nullptr, const Tube& tube = {});

}  // namespace sxk::needle
