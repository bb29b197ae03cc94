// Helpers shared by the writers.
#pragma once

#include <array>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "sxk/io.hpp"
#include "sxk/mesh.hpp"

namespace sxk::io {

std::span<const Point> chosen_positions(const Mesh& mesh, const WriteOptions& options);

// The vertices of s in an order that a reader turns back into exactly s: the canonical order,
// with the first two swapped when s is negative (one swap flips the sign). Entries past
// s.count() are invalid_id.
std::array<VertexId, 4> oriented_vertices(const Simplex& s);

// The mesh's face labels sorted by face (deterministic files), each face oriented as the
// boundary face it is (outward for writers whose viewers care), else in canonical order.
std::vector<std::pair<Simplex, int>> sorted_face_labels(const Mesh& mesh);

// What OFF and OBJ hold: triangles. A triangle mesh gives all its vertices and triangles; a
// tetrahedral mesh gives its boundary surface, with the vertices on it renumbered compactly
// (in increasing order of their mesh ids).
struct Surface {
    std::vector<VertexId> vertices;                  // mesh vertex of each surface vertex
    std::vector<std::array<VertexId, 3>> triangles;  // surface vertex numbers, oriented
};
Surface triangle_surface(const Mesh& mesh);

// The surface as OFF and ASCII PLY write it after their headers: a line "x y z" per vertex,
// then a line "3 a b c" per triangle (0-based vertex numbers).
void append_surface_lines(std::string& out, const Surface& surface, std::span<const Point> positions);

}  // namespace sxk::io
