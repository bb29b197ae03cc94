// Meshes made from nothing: the test cube of the thesis for the tests, the benchmarks, the
// fuzzers and applications that want a conforming tetrahedral mesh without a mesher.
#pragma once

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

}  // namespace sxk
