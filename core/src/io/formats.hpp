// The per-format readers and writers behind read_mesh/write_mesh (io.cpp dispatches).
//
// Readers of text formats (Medit, OFF, OBJ, TetGen) get the whole file as text that already
// passed check_text and is not blank. Readers of formats that may hold binary data (Gmsh, VTU,
// legacy VTK, STL, PLY) get the file's bytes as they are, not blank, a UTF-8 byte order mark
// already dropped: they check their text parts themselves (check_text) and bound every binary
// read by the bytes there are. All throw InputError. Writers return the file's content (the
// caller writes it in one go; binary content is bytes in the string) and throw OutputError when
// the format cannot hold the mesh.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "raw_mesh.hpp"
#include "sxk/io.hpp"
#include "sxk/mesh.hpp"

namespace sxk::io {

Mesh read_medit(std::string_view text, const std::string& name, const ReadOptions& options,
                ReadReport* report);
Mesh read_gmsh(std::string_view text, const std::string& name, const ReadOptions& options,
               ReadReport* report);
Mesh read_off(std::string_view text, const std::string& name, const ReadOptions& options,
              ReadReport* report);
Mesh read_obj(std::string_view text, const std::string& name, const ReadOptions& options,
              ReadReport* report);
Mesh read_vtu(std::string_view bytes, const std::string& name, const ReadOptions& options,
              ReadReport* report);
Mesh read_vtk(std::string_view bytes, const std::string& name, const ReadOptions& options,
              ReadReport* report);
Mesh read_stl(std::string_view bytes, const std::string& name, const ReadOptions& options,
              ReadReport* report);
Mesh read_ply(std::string_view bytes, const std::string& name, const ReadOptions& options,
              ReadReport* report);
// read_obj's parsing alone: the vertices and triangles as listed, none of build_mesh's checks.
struct RawMesh;
RawMesh parse_obj(std::string_view text, const std::string& name);

// TetGen: .node and .ele, and optionally the labelled faces (.face for tetrahedra, .edge for
// triangles; face_text == nullptr when there is no such file).
struct TetgenText {
    std::string_view node;
    std::string node_name;
    std::string_view ele;
    std::string ele_name;
    const std::string_view* face = nullptr;
    std::string face_name;
};
// Parses the three texts; the caller builds the mesh (build_mesh) once it has let go of them,
// so that a large mesh's text and its build do not take memory at the same time (the femur-1226k:
// 75 MB of text, a quarter of the read's peak).
RawMesh parse_tetgen_text(const TetgenText& text);
// Whether a .ele text's header announces tetrahedra (its second field, 4 by default; 3 or 6
// mean triangles): decides between the .face and the .edge file before the .ele file is read.
// When that field is malformed, reading the .ele file fails with its own message.
bool tetgen_announces_tetrahedra(std::string_view ele, const std::string& ele_name);

std::string write_medit(const Mesh& mesh, const WriteOptions& options);
std::string write_gmsh(const Mesh& mesh, const WriteOptions& options);
std::string write_off(const Mesh& mesh, const WriteOptions& options);
std::string write_obj(const Mesh& mesh, const WriteOptions& options);
std::string write_vtu(const Mesh& mesh, const WriteOptions& options);
std::string write_vtk(const Mesh& mesh, const WriteOptions& options);
std::string write_stl(const Mesh& mesh, const WriteOptions& options);
std::string write_ply(const Mesh& mesh, const WriteOptions& options);
struct TetgenFiles {
    std::string node, ele, face;  // face: .face for tetrahedra, .edge for triangles
};
TetgenFiles write_tetgen(const Mesh& mesh, const WriteOptions& options);

}  // namespace sxk::io
