// What the VTK formats share (.vtu in vtu.cpp and vtu_read.cpp, legacy .vtk in vtk_legacy.cpp):
// the scalar types of data arrays, byte order, base64, zlib blocks as vtkZLibDataCompressor
// writes them, the cells and cell data the writers put in a file, and the step from VTK cells to
// a RawMesh that both readers take.
//
// Hostile input: nothing here allocates more than the bytes a file still holds can fill, except
// inflating, which allocates the size the zlib header declares only after checking it against
// what the file's counts need and against deflate's largest ratio (1032:1, zlib's own bound in
// its documentation of compressBound's inverse: a 258-byte match costs at least 2 bits).
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "binary_numbers.hpp"
#include "raw_mesh.hpp"
#include "sxk/io.hpp"
#include "sxk/mesh.hpp"

namespace sxk::io::vtk {

// Where a problem is reported: the file and the line of the XML element or legacy keyword.
struct Where {
    const std::string& file;
    std::size_t line;
    [[noreturn]] void fail(const std::string& reason) const;
};

// ---- scalar types -----------------------------------------------------------------------------
// XML names: Int8 ... UInt64, Float32, Float64 (and "Char"/"UInt8"-style aliases VTK accepts).
std::optional<Scalar> xml_scalar(std::string_view name);
std::string_view xml_name(Scalar type);
// Legacy names: unsigned_char, char, short, ..., long (8 bytes, as VTK writes it on 64-bit
// Linux), float, double, vtkIdType (64 bits, VTK's default build), vtktypeint8 ... vtktypefloat64.
std::optional<Scalar> legacy_scalar(std::string_view name);

// `count` values of `type` stored in `bytes` (count * size_of(type) bytes), in big-endian order
// when `big_endian`. Float32 values become the double of the float, as VTK reads them.
std::vector<double> to_doubles(std::span<const unsigned char> bytes, Scalar type, bool big_endian);
// Integers; a float value that is not a whole number within int64, or a UInt64 above int64's
// range, fails with "WHAT value V of item I is not an integer" / "... is too large".
std::vector<std::int64_t> to_integers(std::span<const unsigned char> bytes, Scalar type,
                                      bool big_endian, const Where& where, const std::string& what);

// ASCII numbers separated by whitespace: exactly `count` of them (fewer: "WHAT holds N values, M
// expected"; more: "WHAT holds more than the M values expected").
// Coordinates follow the text readers' rules (text.hpp Cursor::to_double): finite, overflow
// refused, underflow to zero; messages "WHAT: coordinate is not finite".
std::vector<double> ascii_coordinates(std::string_view text, std::size_t count, Scalar type,
                                      const Where& where, const std::string& what);
// One ASCII value: a coordinate (as ascii_coordinates), an integer (a float type's value must be
// a whole number; `item` numbers it in the message).
double parse_coordinate(std::string_view token, Scalar type, const Where& where,
                        const std::string& what);
std::int64_t parse_integer(std::string_view token, Scalar type, std::size_t item,
                           const Where& where, const std::string& what);
// Binary coordinates: "WHAT: coordinate is not finite" for NaN and infinity.
void check_coordinates(std::span<const double> values, const Where& where,
                       const std::string& what);
std::vector<std::int64_t> ascii_integers(std::string_view text, std::size_t count, Scalar type,
                                         const Where& where, const std::string& what);

// ---- binary blocks ----------------------------------------------------------------------------
// Bytes to read a data block from: raw bytes, or base64 text decoded as it is read.
class Source {
public:
    virtual ~Source() = default;
    // An upper bound of the bytes left (for base64, of what the characters left can decode to).
    virtual std::size_t most_left() const = 0;
    // Appends exactly n bytes to out or fails ("WHAT: truncated ...", "invalid base64 ...").
    virtual void read(std::size_t n, std::vector<unsigned char>& out) = 0;
};

class RawSource final : public Source {
public:
    RawSource(std::string_view bytes, const Where& where, const std::string& what)
        : m_bytes(bytes), m_where(where), m_what(what) {}
    std::size_t most_left() const override { return m_bytes.size() - m_at; }
    void read(std::size_t n, std::vector<unsigned char>& out) override;

private:
    std::string_view m_bytes;
    std::size_t m_at = 0;
    const Where& m_where;
    const std::string& m_what;
};

// Base64 as VTK writes it: the header and the data encoded separately (so '=' padding may end a
// chunk in the middle of the text) or together; whitespace is skipped.
class Base64Source final : public Source {
public:
    Base64Source(std::string_view text, const Where& where, const std::string& what)
        : m_text(text), m_where(where), m_what(what) {}
    std::size_t most_left() const override;
    void read(std::size_t n, std::vector<unsigned char>& out) override;

private:
    bool decode_group();  // refills m_group from the next four characters; false at the end
    std::string_view m_text;
    std::size_t m_at = 0;
    unsigned char m_group[3]{};
    int m_group_size = 0, m_group_used = 0;
    const Where& m_where;
    const std::string& m_what;
};

// The block VTK writes for one array: a header of UInt32 or UInt64 words (header_bytes 4 or 8),
// then the data; with zlib, the header is (number of blocks, block size, size of the last block,
// compressed size of each block) and the blocks follow. Returns exactly `expected_bytes` bytes
// (the array's values as the file stores them) or fails naming `what`.
std::vector<unsigned char> read_block(Source& source, std::size_t header_bytes, bool header_big_endian,
                                      bool compressed, std::uint64_t expected_bytes,
                                      const Where& where, const std::string& what);

// ---- writing ----------------------------------------------------------------------------------
void append_base64(std::string& out, std::span<const unsigned char> bytes);
// `data` as vtkZLibDataCompressor writes it with a UInt64 little-endian header, blocks of
// 32768 bytes (vtkXMLWriter's default block size) each compressed on its own.
void append_zlib_blocks(std::string& out, std::span<const unsigned char> data);

// The cells and data that both writers write (docs: the cut shows in ParaView because the
// labelled faces are cells too).
struct Grid {
    std::span<const Point> points;
    int element_type = 0, face_type = 0;  // VTK_TETRA 10 / VTK_TRIANGLE 5, VTK_TRIANGLE / VTK_LINE 3
    std::size_t element_count = 0;        // the first cells; the labelled faces follow
    std::vector<std::int64_t> connectivity;
    std::vector<std::int64_t> offsets;  // end of each cell in connectivity
    std::vector<std::uint8_t> types;
    std::vector<std::int32_t> label, piece;
    bool quality = false;
    std::vector<double> aspect_ratio, radius_ratio, min_angle_deg;  // NaN for faces
    std::vector<double> displacement;  // 3 per point; empty when no vertex moved
    std::string active_scalars;        // the cell array a viewer colours by at first
    std::size_t cell_count() const { return types.size(); }
};
Grid grid_of(const Mesh& mesh, const WriteOptions& options);

// ---- reading ----------------------------------------------------------------------------------
// The cell data names that carry labels, in the order they are looked for: ours, meshio's Gmsh
// and Medit names, then what VTK's own readers of other formats (Exodus, ...) call them.
inline constexpr std::string_view label_names[] = {"label", "gmsh:physical", "medit:ref",
                                                   "CellEntityIds"};

// VTK cells into the RawMesh: tetrahedra, triangles and lines go to their lists (numbered as VTK
// numbers cells, from 0), vertices are ignored, any other type is refused. `offsets` holds each
// cell's end in `connectivity`; labels is empty (all 0) or one per cell.
struct Cells {
    std::span<const std::int64_t> connectivity, offsets, types, labels;
    std::size_t connectivity_line = 0, types_line = 0;
};
void add_cells(RawMesh& raw, const Cells& cells, std::size_t point_count, const Where& where);
// The name of a VTK cell type for messages ("hexahedron"), empty when unknown.
std::string_view cell_type_name(std::int64_t type);

}  // namespace sxk::io::vtk
