// Meshes made from nothing: the test cube of the thesis for the tests, the benchmarks, the
// fuzzers and applications that want a conforming tetrahedral mesh without a mesher.
#pragma once

#include <array>
#include <span>
#include <vector>

#include "sxk/config.hpp"
#include "sxk/mesh.hpp"
#include "sxk/outcome.hpp"

namespace sxk {

// The cube [0, n*spacing]^3 cut into n^3 cubes and each cube into its 6 Kuhn tetrahedra: the
// monotone paths of unit steps from the cube's corner (0,0,0) to (1,1,1), one per order of the
// axes. Every cube is cut the same way, so the mesh is conforming, and Maubach's bisection
// applies (TetBisection::for_kuhn_mesh).
//
//        z                 path x->y->z: (0,0,0) (1,0,0) (1,1,0) (1,1,1)
//        |   (1,1,1)       path y->x->z: (0,0,0) (0,1,0) (1,1,0) (1,1,1)
//        |  /              ...six paths share the diagonal (0,0,0)-(1,1,1)
//        | /
//        +------- y
//       /
//      x
//
// Numbering: vertex (i,j,k) is (k*(n+1) + j)*(n+1) + i, at (i,j,k)*spacing in both position
// sets; element 6c + o is path o of cube c (cubes numbered like vertices, x fastest), paths in
// the order of the axis orders xyz, xzy, yxz, yzx, zxy, zyx; every element positive; labels 0.
// The thesis' 729-node, 3072-tetrahedron cube (§3.3) is make_kuhn_cube(8).
//
// Refuses n < 1, n > 1000 ("make_kuhn_cube: ...") and a spacing that is not positive and finite.
SXK_API Outcome<Mesh> make_kuhn_cube(int n, double spacing = 1.0);

// The box [0, cells[0]*spacing[0]] x [0, cells[1]*spacing[1]] x [0, cells[2]*spacing[2]] cut
// the same way: cells[0] x cells[1] x cells[2] boxes of spacing[0] x spacing[1] x spacing[2],
// each into its 6 Kuhn tetrahedra, numbered as make_kuhn_cube (vertex (i,j,k) is
// (k*(cells[1]+1) + j)*(cells[0]+1) + i; x fastest). The thesis' cantilever beams (Table 3.1,
// l x h x d = 1.2 x 0.2 x 0.3 m in 16 x 4 x 4 ... 48 x 12 x 12 cells) are such boxes.
// Refuses a count not in 1..1000 and a spacing that is not positive and finite ("make_kuhn_box:
// ...").
SXK_API Outcome<Mesh> make_kuhn_box(std::array<int, 3> cells, std::array<double, 3> spacing);

// The planar rectangle [0, cells[0]*spacing[0]] x [0, cells[1]*spacing[1]] (ambient dimension
// 2) cut into cells[0] x cells[1] rectangles, each into two counter-clockwise triangles along the
// diagonal from its lower left to its upper right corner: vertex (i,j) is j*(cells[0]+1) + i;
// triangles 2c and 2c+1 of cell c (x fastest) are (i,j) (i+1,j) (i+1,j+1) and (i,j) (i+1,j+1)
// (i,j+1); labels 0. The thesis' 2D cuts (§5.4) run in such meshes: 5 x 5 cells give Fig. 5.16's
// 50 triangles, 19 x 19 Fig. 5.8's 722. Refuses a count not in 1..5000 and a spacing that is not
// positive and finite ("make_triangle_grid: ...").
SXK_API Outcome<Mesh> make_triangle_grid(std::array<int, 2> cells, std::array<double, 2> spacing = {1.0, 1.0});

// The grid of make_triangle_grid lifted into space as a Gaussian bell: vertex (x, y) of the grid
// goes to (x, y, height * exp(-r^2 / (2 width^2))), r its distance from the grid's centre, the same
// triangles (ambient dimension 3, labels 0). The surface of the thesis' 3D cuts (Fig. 5.19: 14 x 14
// cells, 392 triangles). Refuses what make_triangle_grid refuses, a height that is not finite and a
// width that is not positive and finite ("make_gaussian_bell: ...").
SXK_API Outcome<Mesh> make_gaussian_bell(std::array<int, 2> cells, std::array<double, 2> spacing, double height,
                                         double width);

// The Delaunay tetrahedralisation of `points` (CGAL's Delaunay_triangulation_3, exact predicates):
// vertex i is points[i] in both position sets (a point given twice is one vertex: the repeat is
// in no element), every element positive, labels 0. Refuses fewer than 4 points, a coordinate
// that is not finite, and points that span no tetrahedron ("make_delaunay: the points are
// coplanar"). O(n log n) expected.
SXK_API Outcome<Mesh> make_delaunay(std::span<const Point> points);

// A cylindrical point cloud (the thesis' test objects of §3.3 and §4.4 are Delaunay
// tetrahedralisations of such clouds): `layers` + 1 discs along z, `spacing` apart; each disc the
// axis point and `rings` concentric rings of radius k * spacing holding round(2 pi k) points,
// every other disc turned by half a point so that the cloud is not a lattice. With rings 4 and
// layers 13: 896 points (the thesis' cylinder: 891 vertices, 4020 tetrahedra).
SXK_API std::vector<Point> cylinder_cloud(int rings, int layers, double spacing = 1.0);

}  // namespace sxk
