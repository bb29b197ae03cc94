// Traversal of the connectivity (thesis §7.2).
#pragma once

#include <span>
#include <vector>

#include "sxk/config.hpp"
#include "sxk/mesh.hpp"

namespace sxk {

// Thesis cycle-around: the elements containing sigma = face_simplex(entry).subn(j), a
// (d-2)-simplex (the vertex triangles turn around in 2D, the edge tetrahedra turn around in 3D).
// j in 0..d-1. The thesis walks one way and stops at the boundary; here, when the walk meets
// the boundary it walks the other way from entry's mate too, so the result is the whole ring
// for interior and boundary sigma alike. Elements are listed in ring order.
SXK_API std::vector<ElementId> cycle_around(const Mesh& mesh, FaceId entry, int j);

// star(v) = the elements containing v, found by walking face neighbours from
// mesh.vertex_element(v) (valid meshes have face-connected stars, §7.3). Empty for a vertex in
// no element.
SXK_API std::vector<ElementId> star(const Mesh& mesh, VertexId v);

// The same walk starting from a given element that contains v; appends to `out` (which may hold
// other elements: only the walk's own are listed once each).
SXK_API void collect_star(const Mesh& mesh, VertexId v, ElementId start,
                          std::vector<ElementId>& out);

// star(v) of a triangle mesh (planar or a surface in space) in order around v: triangles[i] is
// <v, ring[i], ring[i+1]> in its positive vertex order (counter-clockwise in the plane). Around an
// interior vertex the ring closes (as many ring vertices as triangles; next(n-1) is ring[0]);
// around a boundary vertex it runs from the boundary edge v-ring[0] to the boundary edge
// ring[n]-v and has n+1 vertices. Empty for a vertex in no element or a mesh of tetrahedra.
// O(d^2) in the degree d (stars of triangle meshes are small).
struct VertexFan {
    std::vector<ElementId> triangles;
    std::vector<VertexId> ring;
    bool closed = false;
    VertexId next(std::size_t i) const { return ring[(i + 1) % ring.size()]; }
};
SXK_API VertexFan fan_around(const Mesh& mesh, VertexId v);

// The elements of the stars of `vertices` (vertices in no element or out of range skipped),
// sorted, each once: what an edit that moved or split those vertices touched.
SXK_API std::vector<ElementId> stars_of(const Mesh& mesh, std::span<const VertexId> vertices);

}  // namespace sxk
