// VTK XML UnstructuredGrid (.vtu) writer: for looking at meshes in ParaView, and read back by
// vtu_read.cpp.
//
// Encodings (WriteOptions::encoding): standard writes every array into one appended block of raw
// bytes, zlib-compressed as vtkZLibDataCompressor does (header_type UInt64); binary the same
// uncompressed; ascii every array inline as text, numbers in shortest round-trip form. Byte order
// is little-endian on every machine.
//
// Points are written in 3D (z = 0 for planar meshes). Cells: the elements as VTK_TETRA (10) or
// VTK_TRIANGLE (5) in positive orientation (VTK's tetra convention is ours: the fourth point
// lies on the side the right-handed normal of the first three points points to,
// det[b-a, c-a, d-a] > 0), then every labelled face (Mesh::face_labels(): boundary faces
// outward, cut faces included) as VTK_TRIANGLE, or VTK_LINE (3) for a triangle mesh, so that
// the cut shows in ParaView. Cell data (vtk_arrays.hpp Grid):
//   label          element label, or the face's label
//   piece          face-connected component of the element (sxk/components.hpp); a face has
//                  that of an element it belongs to
//   aspect_ratio   thesis §3.2.3 aspect ratio (quality.hpp)      } with quality_cell_data;
//   radius_ratio   d * inradius / circumradius                   } NaN for faces
//   min_angle_deg  smallest dihedral angle (tetrahedra) or angle (triangles), in degrees
// Point data `displacement` (deformed - reference) when any vertex moved. The active scalars
// are those that show something (Grid::active_scalars).
#include <bit>
#include <cstring>
#include <vector>

#include "binary_numbers.hpp"
#include "formats.hpp"
#include "text.hpp"
#include "vtk_arrays.hpp"

namespace sxk::io {

namespace {

struct Writer {
    Encoding encoding;
    std::span<const std::int64_t> cell_ends;  // per_line == 0: one cell per line
    std::string out;
    // Appended arrays in document order: each one's encoded block, and where in `out` its offset
    // goes (filled in by finish()).
    std::vector<std::string> blocks;
    std::vector<std::size_t> offset_at;

    // Writes a DataArray element and its values (inline text, or into the appended block).
    template <typename T>
    void array(const char* indent, std::string_view type, std::string_view name,
               std::span<const T> values, int components, std::size_t per_line) {
        out += indent;
        out += "<DataArray type=\"";
        out += type;
        out += "\" Name=\"";
        out += name;
        out += '"';
        if (components != 1) {
            out += " NumberOfComponents=\"";
            append_number(out, components);
            out += '"';
        }
        if (encoding == Encoding::ascii) {
            out += " format=\"ascii\">\n";
            std::size_t cell = 0;
            const auto line_ends_at = [&](std::size_t i) {
                if (per_line != 0)
                    return i % per_line == per_line - 1;
                if (static_cast<std::int64_t>(i) + 1 != cell_ends[cell])
                    return false;
                ++cell;
                return true;
            };
            bool line_start = true;
            for (std::size_t i = 0; i < values.size(); ++i) {
                if (line_start) {
                    out += indent;
                    out += "  ";
                } else {
                    out += ' ';
                }
                if constexpr (std::is_floating_point_v<T>)
                    append_number(out, static_cast<double>(values[i]));
                else
                    append_number(out, static_cast<std::int64_t>(values[i]));
                line_start = line_ends_at(i) || i + 1 == values.size();
                if (line_start)
                    out += '\n';
            }
            out += indent;
            out += "</DataArray>\n";
            return;
        }
        out += " format=\"appended\" offset=\"";
        offset_at.push_back(out.size());
        out += "\"/>\n";
        std::string bytes;
        if constexpr (std::endian::native == std::endian::little) {
            bytes.assign(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T));
        } else {
            bytes.reserve(values.size() * sizeof(T));
            for (const T& value : values)
                append_number_bytes<T>(bytes, value, false);
        }
        const std::span<const unsigned char> data(
            reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size());
        std::string& block = blocks.emplace_back();
        if (encoding == Encoding::binary) {
            append_number_bytes<std::uint64_t>(block, bytes.size(), false);
            block += bytes;
        } else {
            vtk::append_zlib_blocks(block, data);
        }
    }

    // The offsets, and the appended block with the arrays in the reverse of the document's
    // order. meshio 5 reads raw appended data by rewriting each array's offset in turn (in
    // order of offset) and finding the next array as the first element in the document with
    // the next offset: when an offset already rewritten equals one still to come, it takes the
    // wrong array (the writer's first layout, in document order, gave it a 'radius_ratio' of 3
    // values for 6 cells). Reversed, the array meant always comes first in the document.
    void finish() {
        if (blocks.empty())
            return;
        std::vector<std::size_t> offsets(blocks.size());
        std::size_t at = 0;
        for (std::size_t i = blocks.size(); i-- > 0;) {
            offsets[i] = at;
            at += blocks[i].size();
        }
        std::string text;
        text.reserve(out.size() + 24 * blocks.size() + at + 64);
        std::size_t copied = 0;
        for (std::size_t i = 0; i < blocks.size(); ++i) {
            text.append(out, copied, offset_at[i] - copied);
            append_number(text, offsets[i]);
            copied = offset_at[i];
        }
        text.append(out, copied);
        out = std::move(text);
        out += "  <AppendedData encoding=\"raw\">\n   _";
        for (std::size_t i = blocks.size(); i-- > 0;) {
            out += blocks[i];
            std::string().swap(blocks[i]);  // the file's bytes are held once
        }
        out += "\n  </AppendedData>\n";
    }
};

}  // namespace

std::string write_vtu(const Mesh& mesh, const WriteOptions& options) {
    const vtk::Grid grid = vtk::grid_of(mesh, options);
    Writer w{options.encoding, grid.offsets, {}, {}, {}};
    std::string& out = w.out;
    out.reserve(options.encoding == Encoding::ascii
                    ? mesh.vertex_count() * 64 + grid.cell_count() * 96
                    : 4096);
    out +=
        "<?xml version=\"1.0\"?>\n"
        "<!-- written by simplexkit -->\n"
        "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
        "header_type=\"UInt64\"";
    if (options.encoding == Encoding::standard)
        out += " compressor=\"vtkZLibDataCompressor\"";
    out += ">\n  <UnstructuredGrid>\n    <Piece NumberOfPoints=\"";
    append_number(out, grid.points.size());
    out += "\" NumberOfCells=\"";
    append_number(out, grid.cell_count());
    out += "\">\n";
    const char* indent = "        ";
    if (!grid.displacement.empty()) {
        out += "      <PointData Vectors=\"displacement\">\n";
        w.array<double>(indent, "Float64", "displacement", grid.displacement, 3, 3);
        out += "      </PointData>\n";
    }
    out += "      <CellData Scalars=\"";
    out += grid.active_scalars;
    out += "\">\n";
    w.array<std::int32_t>(indent, "Int32", "label", grid.label, 1, 1);
    w.array<std::int32_t>(indent, "Int32", "piece", grid.piece, 1, 1);
    if (grid.quality) {
        // degenerate elements and faces give NaN; VTK's and meshio's ASCII parsers read "nan"
        w.array<double>(indent, "Float64", "aspect_ratio", grid.aspect_ratio, 1, 1);
        w.array<double>(indent, "Float64", "radius_ratio", grid.radius_ratio, 1, 1);
        w.array<double>(indent, "Float64", "min_angle_deg", grid.min_angle_deg, 1, 1);
    }
    out += "      </CellData>\n      <Points>\n";
    // a Point is three doubles without padding: the positions are one array of coordinates
    static_assert(sizeof(Point) == 3 * sizeof(double));
    const std::span<const double> coordinates(reinterpret_cast<const double*>(grid.points.data()),
                                              3 * grid.points.size());
    w.array<double>(indent, "Float64", "Points", coordinates, 3, 3);
    out += "      </Points>\n      <Cells>\n";
    w.array<std::int64_t>(indent, "Int64", "connectivity", grid.connectivity, 1, 0);
    w.array<std::int64_t>(indent, "Int64", "offsets", grid.offsets, 1, 1);
    w.array<std::uint8_t>(indent, "UInt8", "types", grid.types, 1, 1);
    out += "      </Cells>\n    </Piece>\n  </UnstructuredGrid>\n";
    w.finish();
    out += "</VTKFile>\n";
    return out;
}

}  // namespace sxk::io
