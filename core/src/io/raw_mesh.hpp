// What a reader collected, and the one place where it becomes a Mesh.
//
// Readers only parse: they turn file indices into 0-based vertex ids (checking the range, since
// only they know the file's numbering) and remember on which line each vertex and cell stood.
// build_mesh then does every check that is the same for all formats, in this order, before the
// caller ever sees a Mesh (readers never return a half-built mesh):
//
//   1. topological dimension = that of the largest cells present (tetrahedra, else triangles);
//      cells one dimension lower are labelled faces; lower ones are ignored
//   2. ambient dimension: what the file said, or (formats that always store x y z) 2 when the
//      mesh is made of triangles and every z is exactly 0
//   3. repeated vertices within a cell
//   4. orientation, when topological == ambient dimension: exact orient2d/orient3d of the
//      vertices in file order; negative is "element N is inverted" unless ReadOptions::reorient
//      (zero, a flat element, is accepted: repairing those is the degeneracy plug-in's job)
//   5. Mesh::assign_elements: duplicates, faces shared by three or more elements, neighbours
//      with inconsistent orientation; its refusal names an element index, mapped back to the
//      element's number and line
//   6. vertex stars connected through faces (the kernel's invariant: two tetrahedra touching
//      only at a vertex). When assign_elements refuses a pinched vertex and
//      ReadOptions::split_pinched is set, split_pinched_vertices (a step of its own, run only on
//      that path) splits every pinched vertex and the elements are assigned again
//   7. labelled faces: no repeated vertex, listed once (CellList::repeats_are_one_face: a
//      repeat is the same face, the first label kept), and a face of some element
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "sxk/detail/large_array.hpp"
#include "sxk/io.hpp"
#include "sxk/mesh.hpp"

namespace sxk::io {

// Cells with `size` vertices each (2: edges, 3: triangles, 4: tetrahedra), as listed in a file.
struct CellList {
    explicit CellList(int size) : size(size) {}
    int size;
    // the arrays: huge pages when large (sxk/detail/large_array.hpp)
    detail::LargeVector<VertexId> vertices;  // size per cell, file order, 0-based
    detail::LargeVector<int> labels;         // one per cell
    detail::LargeVector<std::size_t> lines;  // one per cell
    detail::LargeVector<std::int64_t>
        numbers;       // the file's numbers (Gmsh tags, TetGen ids); empty: 1, 2, ...
    std::string file;  // where the cells were read
    // Labelled faces only: a face listed again is the same face (Medit writers list each side
    // of a face); otherwise it is refused as a repeat.
    bool repeats_are_one_face = false;

    std::size_t count() const { return lines.size(); }
    // Room for `n` cells (and their file numbers when `numbered`), the memory backed in parallel
    // first (core/src/fresh_array.hpp).
    void reserve(std::size_t n, bool numbered = false);
    std::int64_t number(std::size_t i) const {
        return numbers.empty() ? static_cast<std::int64_t>(i) + 1 : numbers[i];
    }
};

struct RawMesh {
    detail::LargeVector<Point> points;
    detail::LargeVector<std::size_t> point_lines;     // one per point
    detail::LargeVector<std::int64_t> point_numbers;  // the file's numbers; empty: vertex_base + id
    std::int64_t vertex_base = 1;
    std::string vertex_file;

    int ambient = 3;              // as the file says
    bool ambient_from_z = false;  // the file always stores x y z: decide by the z rule

    CellList edges{2};
    CellList triangles{3};
    CellList tetrahedra{4};

    // Room for `n` points and their lines (and file numbers when `numbered`), as CellList::reserve.
    void reserve_points(std::size_t n, bool numbered = false);
    std::int64_t vertex_number(VertexId v) const {
        return point_numbers.empty() ? vertex_base + static_cast<std::int64_t>(v)
                                     : point_numbers[v];
    }
};

// Checks everything listed at the top and builds the mesh; throws InputError.
// `fallback_file` names the file for problems tied to no list (e.g. "no triangles or tetrahedra").
Mesh build_mesh(RawMesh& raw, const std::string& fallback_file, const ReadOptions& options,
                ReadReport* report);

// Room for `wanted` records, but never more than the text left could hold (a header claiming a
// billion vertices must not allocate gigabytes before the file runs out).
std::size_t plausible_count(std::int64_t wanted, std::size_t bytes_left,
                            std::size_t bytes_per_record);

}  // namespace sxk::io
