// Vertex renumbering for locality: reverse Cuthill-McKee on the vertex graph of element edges
// (two vertices are adjacent when some element contains both). A small bandwidth keeps the
// vertices of an element close in memory and the matrices of the solvers banded.
//
//   a planar grid shuffled at random           after cuthill_mckee_order + renumbered
//     17  3 11                                   0  1  3      neighbours get nearby ids:
//      8 20  0      bandwidth ~ n^2      --->    2  4  6      bandwidth ~ n (the grid's
//     14  5  9                                   5  7  8      natural row-by-row order)
//
// Contract.
//   cuthill_mckee_order(mesh): a permutation new_of_old of 0..vertex_count()-1 (new_of_old[v]
//   is the new id of v), computed by Boost.Graph's cuthill_mckee_ordering (the library's, not our own), one
//   pseudo-peripheral start per connected piece of the graph; vertices in no element come last.
//   renumbered(mesh, new_of_old): a new mesh with vertex new_of_old[v] carrying the positions of
//   v, every element simplex mapped (orientation kept: the permutation re-sorts with its sign),
//   element labels and face labels mapped, built with assign_elements. The elements are ordered
//   by their lowest new vertex id (ties in `mesh`'s id order): near in memory what is near in the
//   vertex order (a cut's step on the 1.2M femur: docs/performance.md "snapcut"); FaceIds are not
//   preserved. Watchers are not copied. new_of_old must be a permutation of size vertex_count()
//   (std::invalid_argument otherwise: a programming error, not an input refusal).
#pragma once

#include <span>
#include <vector>

#include "sxk/config.hpp"
#include "sxk/mesh.hpp"

namespace sxk {

SXK_API std::vector<VertexId> cuthill_mckee_order(const Mesh& mesh);

SXK_API Mesh renumbered(const Mesh& mesh, std::span<const VertexId> new_of_old);

// max |new(a) - new(b)| over the element edges, for tests and reports.
SXK_API std::size_t vertex_bandwidth(const Mesh& mesh);

}  // namespace sxk
