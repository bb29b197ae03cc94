// Mesh files: Medit .mesh, Gmsh .msh (2.2 and 4.1, ASCII and binary), TetGen .node/.ele(/.face),
// OFF, OBJ, VTK XML .vtu, legacy VTK .vtk, STL and PLY (ASCII and binary), all read and written
// (docs/formats.md). The format follows the file extension; WriteOptions::encoding chooses text
// or binary where the format has both.
//
// Readers never return a half-built mesh and never crash on bad input: every problem throws
// InputError naming the file, the 1-based line (0 for binary data, whose messages name the byte
// or the element instead) and the reason. What they check: truncated
// files, counts that do not match, indices out of range, NaN/inf coordinates, unknown keywords,
// binary garbage, and, through Mesh::assign_elements, duplicate and non-manifold elements.
// Inverted elements (negative exact orientation when topological == ambient dimension) are an
// error unless ReadOptions::reorient is set, which flips them and counts them. Flat elements
// (orientation exactly zero) are read as they are. A vertex whose elements do not connect
// through faces (two tetrahedra touching at a corner: a pinched vertex) cannot be held by the
// kernel; by default it is split, one vertex per face-connected piece of its star (thesis §7.3,
// the (v,{})-components of dissection), see ReadOptions::split_pinched.
//
// Dimensions. The topological dimension is that of the largest cells in the file (tetrahedra,
// else triangles; a file with neither is refused). The ambient dimension is what the file says
// where it says it (Medit "Dimension", the TetGen .node dimension); formats that always store
// x y z (Gmsh, OFF, OBJ, VTK, STL, PLY) make a planar mesh (ambient 2) exactly when the mesh is
// made of triangles and every z is 0 (-0 included; planar meshes store z = +0).
//
// Labels. Element labels: Medit element refs, Gmsh physical tags (2.2: the element's first tag;
// 4.1: the first physical tag of its entity; a group named `label N` is label N, other names are
// Mesh::label_names), the first TetGen region attribute, VTK cell data `label`; OFF, OBJ, STL
// and PLY have none (0). Face labels (Mesh::face_labels(), keyed by the face's vertex set as
// Simplex(+1, ...) with sign +1, whichever way the file orients it): the cells one dimension
// below the mesh (Medit Triangles/Edges refs, Gmsh lower-dimensional elements' physical tags,
// VTK lower-dimensional cells' labels, TetGen .face markers, or .edge markers for triangle
// meshes as Triangle writes them). Every
// labelled face must be a face of the mesh. Writers write exactly these faces back (boundary
// faces outward), never invented ones; TetGen without face labels writes the plain boundary
// without markers.
//
// Medit lists a face more than once where its writer gives each side of a face its own line
// (CGAL's output_to_medit writes every boundary triangle twice, once per orientation, and an
// interface triangle with the subdomain of either side): the repeats are one labelled face. When
// the references differ, the first listed is kept and ReadReport::label_conflicts says so. Other
// formats refuse a repeated face.
//
// Error messages number elements as the file does (Gmsh element tags, TetGen element numbers),
// else 1, 2, ... in file order; vertices likewise (OFF from 0, Medit and OBJ from 1).
#pragma once

#include <cstddef>
#include <filesystem>
#include <iosfwd>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "sxk/config.hpp"
#include "sxk/mesh.hpp"
#include "sxk/predicates.hpp"

namespace sxk {

enum class Format { medit, gmsh, tetgen, off, obj, vtu, vtk, stl, ply };

SXK_API std::string_view to_string(Format format);
// By extension: .mesh .msh .node .ele .off .obj .vtu .vtk .stl .ply; nullopt otherwise.
SXK_API std::optional<Format> format_from_extension(const std::filesystem::path& path);
// The format called `name`: to_string's name ("medit", "gmsh", ...) or an extension with or
// without its dot ("mesh", ".msh"), in any case; nullopt otherwise.
SXK_API std::optional<Format> format_from_name(std::string_view name);
// Those extensions as one line, for messages and help texts: ".mesh .msh .node .ele ...".
SXK_API std::string_view known_mesh_extensions();

// A reader's complaint. what() is "FILE:LINE: reason" (LINE is 0 when the problem is not tied to
// a line, e.g. a missing file).
class SXK_API InputError : public std::runtime_error {
public:
    InputError(std::string file, std::size_t line, std::string reason);
    const std::string& file() const { return m_file; }
    std::size_t line() const { return m_line; }
    const std::string& reason() const { return m_reason; }

private:
    std::string m_file;
    std::size_t m_line;
    std::string m_reason;
};

// A writer's complaint (cannot open, disk full, format cannot hold the mesh).
class SXK_API OutputError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

struct ReadOptions {
    bool reorient = false;  // flip inverted elements instead of refusing the file
    // Build with Mesh::assign_elements_unchecked: duplicate, non-manifold and inconsistently
    // oriented elements are kept (and inverted ones are not refused) so that validate() can
    // name the broken invariant. `sxk validate` reads this way; nothing else should.
    bool lenient = false;
    // A pinched vertex (its star falls into several pieces that only touch at it) is split into
    // one vertex per face-connected piece: the piece holding the first element in file order
    // keeps the vertex, every other piece gets a new vertex appended after the file's own (for
    // each pinched vertex in file order, its pieces in order of their first element), with the
    // position of its original. Elements keep their order and labels; a labelled face around
    // the vertex goes to the copy its element got. false refuses the file as before ("vertex N
    // is non-manifold: ..."). A lenient read never splits (validate() names the vertex).
    bool split_pinched = true;
    // A labelled face (Medit Triangles, Gmsh lower-dimensional elements, TetGen .face) that is
    // no face of any element, as CGAL's Mesh_3 writes surface facets whose cells lie outside
    // the complex: dropped and counted in ReadReport::stray_faces. false refuses the file
    // ("triangle N is not a face of any tetrahedron"). A lenient read keeps the label, so that
    // validate() names it.
    bool drop_stray_faces = true;
};

struct ReadReport {
    std::size_t reoriented = 0;  // elements flipped because of ReadOptions::reorient
    // ReadOptions::split_pinched: how many of the file's vertices were split, and each new
    // vertex with the vertex it copies, (original, copy) in order of creation (copies are
    // numbered from the file's vertex count on; originals are 0-based ids in file order).
    std::size_t pinched_vertices = 0;
    std::vector<std::pair<VertexId, VertexId>> vertex_copies;
    // Medit faces listed again with a different reference (the first one is kept), and the
    // first of them as "FILE:LINE: triangle 2 repeats triangle 1 with reference 2, not 1".
    std::size_t label_conflicts = 0;
    std::string first_label_conflict;
    // ReadOptions::drop_stray_faces: labelled faces dropped because no element has them, and
    // the first as "FILE:LINE: triangle 9 is not a face of any tetrahedron".
    std::size_t stray_faces = 0;
    std::string first_stray_face;
    // STL triangles two of whose corners are at one position (zero area: nothing of the
    // surface, and no element), dropped, and the first as "FILE:LINE: triangle 7 has two
    // corners at one position" (line 0 in binary files).
    std::size_t dropped_triangles = 0;
    std::string first_dropped_triangle;
};

// Reads a mesh file; for TetGen give either X.node or X.ele (the other, and X.face if present,
// are found beside it). Throws InputError.
SXK_API Mesh read_mesh(const std::filesystem::path& path, const ReadOptions& options = {},
                       ReadReport* report = nullptr);

// Reads from a stream (fuzzers, tests); `name` is used in error messages. TetGen needs two
// streams and has its own entry point.
SXK_API Mesh read_mesh(std::istream& in, Format format, const std::string& name,
                       const ReadOptions& options = {}, ReadReport* report = nullptr);
SXK_API Mesh read_tetgen(std::istream& node, const std::string& node_name, std::istream& ele,
                         const std::string& ele_name, const ReadOptions& options = {},
                         ReadReport* report = nullptr);

// The most bytes read from one input (mesh files and side inputs alike): 1 GiB, a hundred times
// the femur's ~10 MB of text. A FIFO or a stream has no size to check beforehand; without a
// bound an endless pipe would be read until memory ran out.
inline constexpr std::size_t max_input_bytes = std::size_t{1} << 30;

// Reads a text file as the mesh readers read theirs, for the side inputs of commands (the face
// list of `sxk dissect --faces`, .bpt patch files): a regular file or a FIFO, at most `limit`
// bytes; a directory, a device (/dev/zero), a socket or an unreadable file is refused; a byte
// that cannot be text is refused ("binary data (byte 0x00)" on its line); a UTF-8 byte order
// mark is dropped. An empty file gives an empty text. Throws InputError (docs/formats.md
// "Reading files").
SXK_API std::string read_text_file(const std::filesystem::path& path,
                                   std::size_t limit = max_input_bytes);
// The same from a stream; `name` stands for the file in the messages.
SXK_API std::string read_text_stream(std::istream& in, const std::string& name,
                                     std::size_t limit = max_input_bytes);

// How a writer encodes its numbers, for the formats that have a choice.
enum class Encoding {
    standard,  // each format's usual: .vtu binary, appended and zlib-compressed; .msh and legacy
               // .vtk ASCII; .stl and .ply binary
    ascii,     // text (.vtu: every array inline as ASCII)
    binary,    // .msh binary (file type 1); .vtu appended raw, uncompressed; legacy .vtk
               // binary (big-endian); .stl and .ply binary (little-endian)
};
SXK_API std::string_view to_string(Encoding encoding);
// "standard", "ascii", "binary"; nullopt otherwise.
SXK_API std::optional<Encoding> encoding_from_string(std::string_view name);

struct WriteOptions {
    int gmsh_version = 41;                      // 22 or 41
    Encoding encoding = Encoding::standard;
    Positions positions = Positions::deformed;  // which coordinates go into the file
    bool quality_cell_data = true;              // .vtu: aspect ratio etc. per element
    // Refuse (OutputError, nothing written) a mesh that does not pass Mesh::validate with the
    // orientation check: inverted elements, broken connectivity. The sxk commands set it, so
    // that a command's result is a file every command accepts, or no file.
    bool refuse_invalid = false;
    // Leave out the vertices that are in no element (Mesh::compact_vertices on a copy): the file
    // then numbers the others consecutively. `sxk degeneracies` sets it.
    bool drop_unused_vertices = false;
};

// Writes by extension (for TetGen give X.node or X.ele: writes X.node, X.ele and X.face, or
// X.edge for a triangle mesh). Positions are written in the shortest form that reads back to
// the same double, so write -> read is exact. Every file is written atomically
// (sxk/atomic_write.hpp): a failed write leaves no partial file and an existing target as it
// was, and a TetGen set is written whole or not at all. A mesh without elements is refused
// ("the mesh has no elements"): no reader accepts such a file.
// OFF, OBJ, STL and PLY hold triangles: a tetrahedral mesh is written as its boundary surface.
// Throws OutputError.
SXK_API void write_mesh(const Mesh& mesh, const std::filesystem::path& path,
                        const WriteOptions& options = {});
// The same to a stream (standard output) in `format`, `name` standing for the file in messages;
// TetGen, a set of files, is refused. Nothing is written when a check refuses the mesh.
SXK_API void write_mesh(const Mesh& mesh, std::ostream& out, Format format, const std::string& name,
                        const WriteOptions& options = {});

}  // namespace sxk
