// VTK XML UnstructuredGrid (.vtu) reader.
//
// What it reads: DataArrays in ASCII, inline binary (format="binary": base64 of the header, then
// the data, compressed or not), appended raw and appended base64 (<AppendedData
// encoding="raw"|"base64">, arrays at their offset after the '_' marker); compression by
// vtkZLibDataCompressor (the other compressors are refused); header_type UInt32 and UInt64;
// byte_order LittleEndian and BigEndian; array types Int8 ... UInt64, Float32, Float64. One
// Piece: a file of several pieces (a parallel writer's partition, whose points repeat where the
// pieces meet) is refused rather than merged into a mesh with seams.
//
// Cells: VTK_TETRA, VTK_TRIANGLE, VTK_LINE; VTK_VERTEX is ignored, any other type refused. The
// largest cells present are the elements, cells one dimension lower are labelled faces (as the
// Gmsh reader does it: build_mesh, raw_mesh.hpp). Labels: cell data `label`, else
// `gmsh:physical`, else `medit:ref`, else `CellEntityIds` (meshio's names for Gmsh and Medit
// files, and VTK's), else 0. Point data (`displacement` included) is not read: the mesh's
// positions are the points. Cells and points are numbered from 0 in messages, as ParaView
// numbers them. Lines in messages are those of the XML element concerned.
//
// The XML goes through pugixml. Appended raw data is not XML, so only the text before
// <AppendedData is parsed (its unclosed elements are what pugixml then reports, and accepted),
// and the appended block is read by offsets, bounded by the bytes there are.
#include <pugixml.hpp>

#include <algorithm>
#include <charconv>
#include <cstring>
#include <limits>

#include "formats.hpp"
#include "text.hpp"
#include "vtk_arrays.hpp"

namespace sxk::io {

namespace {

class VtuReader {
public:
    VtuReader(std::string_view bytes, const std::string& name) : m_bytes(bytes), m_name(name) {}

    RawMesh read() {
        parse_xml();
        const pugi::xml_node root = m_document.child("VTKFile");
        if (!root)
            fail(0, "no VTKFile element");
        const std::size_t root_line = line_of(root);
        const std::string type = root.attribute("type").value();
        if (type != "UnstructuredGrid")
            fail(root_line, "VTKFile type " + quote(type) + " is not read; only UnstructuredGrid");
        const std::string order = root.attribute("byte_order").as_string("LittleEndian");
        if (order != "LittleEndian" && order != "BigEndian")
            fail(root_line, "unknown byte_order " + quote(order));
        m_big_endian = order == "BigEndian";
        const std::string header = root.attribute("header_type").as_string("UInt32");
        if (header != "UInt32" && header != "UInt64")
            fail(root_line, "unknown header_type " + quote(header) + " (UInt32 or UInt64)");
        m_header_bytes = header == "UInt64" ? 8 : 4;
        const std::string compressor = root.attribute("compressor").value();
        if (!compressor.empty() && compressor != "vtkZLibDataCompressor")
            fail(root_line, "compressor " + quote(compressor) +
                                " is not supported (only vtkZLibDataCompressor)");
        m_compressed = !compressor.empty();

        const pugi::xml_node grid = root.child("UnstructuredGrid");
        if (!grid)
            fail(root_line, "no UnstructuredGrid element");
        std::size_t pieces = 0;
        for (pugi::xml_node piece = grid.child("Piece"); piece; piece = piece.next_sibling("Piece"))
            ++pieces;
        if (pieces == 0)
            fail(line_of(grid), "no Piece element");
        if (pieces > 1)
            fail(line_of(grid), "the file holds " + std::to_string(pieces) +
                                    " pieces; only files of one piece are read");
        return read_piece(grid.child("Piece"));
    }

private:
    [[noreturn]] void fail(std::size_t line, const std::string& reason) const {
        throw InputError(m_name, line, reason);
    }

    std::size_t line_of(std::ptrdiff_t offset) const {
        const std::size_t end = std::min(static_cast<std::size_t>(std::max<std::ptrdiff_t>(offset, 0)),
                                         m_xml.size());
        return 1 + static_cast<std::size_t>(std::count(m_xml.begin(), m_xml.begin() +
                                                           static_cast<std::ptrdiff_t>(end), '\n'));
    }
    std::size_t line_of(const pugi::xml_node& node) const { return line_of(node.offset_debug()); }

    void parse_xml() {
        const std::size_t appended = m_bytes.find("<AppendedData");
        m_xml = check_text(m_bytes.substr(0, appended), m_name);
        const pugi::xml_parse_result result =
            m_document.load_buffer(m_xml.data(), m_xml.size(), pugi::parse_default,
                                   pugi::encoding_utf8);
        // before <AppendedData the elements around it are still open: pugixml reports that at the
        // last character of the text and keeps everything it read
        const std::size_t last = static_cast<std::size_t>(std::max<std::ptrdiff_t>(result.offset, 0));
        const bool open_at_end =
            appended != std::string_view::npos &&
            result.status == pugi::status_end_element_mismatch &&
            std::all_of(m_xml.begin() + static_cast<std::ptrdiff_t>(std::min(last + 1, m_xml.size())),
                        m_xml.end(), [](char c) {
                            return c == ' ' || c == '\t' || c == '\n' || c == '\r';
                        });
        if (!result && !open_at_end)
            fail(line_of(result.offset), std::string("XML error: ") + result.description());
        if (appended == std::string_view::npos)
            return;

        const std::size_t line = line_of(static_cast<std::ptrdiff_t>(m_xml.size()));
        const std::size_t close = m_bytes.find('>', appended);
        if (close == std::string_view::npos)
            fail(line, "truncated <AppendedData> element");
        std::string tag(m_bytes.substr(appended, close - appended));
        check_text(tag, m_name);
        if (!tag.empty() && tag.back() == '/')
            tag.pop_back();
        tag += "/>";
        pugi::xml_document element;
        if (!element.load_buffer(tag.data(), tag.size(), pugi::parse_default, pugi::encoding_utf8))
            fail(line, "malformed <AppendedData> element");
        const std::string encoding =
            element.child("AppendedData").attribute("encoding").as_string("raw");
        if (encoding != "raw" && encoding != "base64")
            fail(line, "unknown AppendedData encoding " + quote(encoding) + " (raw or base64)");
        m_appended_base64 = encoding == "base64";
        std::size_t at = close + 1;
        while (at < m_bytes.size() &&
               (m_bytes[at] == ' ' || m_bytes[at] == '\t' || m_bytes[at] == '\n' || m_bytes[at] == '\r'))
            ++at;
        if (at == m_bytes.size() || m_bytes[at] != '_')
            fail(line, "AppendedData does not start with '_'");
        m_appended = m_bytes.substr(at + 1);
        m_have_appended = true;
        if (m_appended_base64)  // base64 is text: it ends where the element does
            m_appended = m_appended.substr(0, m_appended.find("</AppendedData"));
    }

    std::size_t count_attribute(const pugi::xml_node& node, const char* attribute,
                                std::size_t default_value, std::size_t maximum) const {
        const pugi::xml_attribute a = node.attribute(attribute);
        if (!a)
            return default_value;
        const std::string_view text = a.value();
        std::size_t value = 0;
        const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
        if (error != std::errc() || end != text.data() + text.size() || value > maximum)
            fail(line_of(node), std::string(node.name()) + " " + attribute + " " + quote(text) +
                                    " is not a count (0.." + std::to_string(maximum) + ")");
        return value;
    }

    // An array's values as bytes in the file's order (binary formats) or its text (ascii).
    struct Array {
        Scalar type;
        bool ascii;
        std::string_view text;
        std::vector<unsigned char> bytes;
        std::size_t line;
        std::string what;
    };

    // `role` names an array without a Name (VTK's Points array need not have one).
    Array load(const pugi::xml_node& node, std::size_t count, int components, const char* role) {
        Array array;
        array.line = line_of(node);
        const std::string_view name = node.attribute("Name").value();
        array.what = "DataArray " + quote(name.empty() ? std::string_view(role) : name);
        const vtk::Where where{m_name, array.line};
        const std::string type = node.attribute("type").value();
        const std::optional<Scalar> scalar = vtk::xml_scalar(type);
        if (!scalar)
            where.fail(array.what + " has unknown type " + quote(type));
        array.type = *scalar;
        // an array without NumberOfComponents has what its place needs (Points: three)
        const std::size_t found = count_attribute(node, "NumberOfComponents",
                                                  static_cast<std::size_t>(components), 64);
        if (found != static_cast<std::size_t>(components))
            where.fail(array.what + " has " + std::to_string(found) + " components, " +
                       std::to_string(components) + " expected");
        const std::string format = node.attribute("format").value();
        const std::size_t size = size_of(array.type);
        if (count > std::numeric_limits<std::uint64_t>::max() / size)
            where.fail(array.what + " is too large");
        const std::uint64_t expected = count * size;
        if (format == "ascii") {
            array.ascii = true;
            array.text = node.text().get();
            return array;
        }
        array.ascii = false;
        if (format == "binary") {
            vtk::Base64Source source(node.text().get(), where, array.what);
            array.bytes = vtk::read_block(source, m_header_bytes, m_big_endian, m_compressed,
                                          expected, where, array.what);
            return array;
        }
        if (format != "appended")
            where.fail(array.what + " has unknown format " + quote(format) +
                       " (ascii, binary or appended)");
        if (!m_have_appended)
            where.fail(array.what + " is appended but the file has no AppendedData");
        const std::size_t offset =
            count_attribute(node, "offset", 0, std::numeric_limits<std::size_t>::max());
        if (offset >= m_appended.size())
            where.fail(array.what + " offset " + std::to_string(offset) + " is beyond the " +
                       std::to_string(m_appended.size()) + " bytes of appended data");
        if (m_appended_base64) {
            vtk::Base64Source source(m_appended.substr(offset), where, array.what);
            array.bytes = vtk::read_block(source, m_header_bytes, m_big_endian, m_compressed,
                                          expected, where, array.what);
        } else {
            vtk::RawSource source(m_appended.substr(offset), where, array.what);
            array.bytes = vtk::read_block(source, m_header_bytes, m_big_endian, m_compressed,
                                          expected, where, array.what);
        }
        return array;
    }

    std::vector<std::int64_t> integers(const pugi::xml_node& node, std::size_t count) {
        const Array array = load(node, count, 1, "");
        const vtk::Where where{m_name, array.line};
        if (array.ascii)
            return vtk::ascii_integers(array.text, count, array.type, where, array.what);
        return vtk::to_integers(array.bytes, array.type, m_big_endian, where, array.what);
    }

    pugi::xml_node named_array(const pugi::xml_node& parent, std::string_view name) const {
        for (pugi::xml_node node = parent.child("DataArray"); node;
             node = node.next_sibling("DataArray"))
            if (name == node.attribute("Name").value())
                return node;
        return {};
    }

    RawMesh read_piece(const pugi::xml_node& piece) {
        const std::size_t piece_line = line_of(piece);
        // vertex ids are 32 bits (sxk/ids.hpp); counts beyond are refused before anything is read
        const std::size_t points =
            count_attribute(piece, "NumberOfPoints", 0, std::size_t{invalid_id} - 1);
        const std::size_t cells = count_attribute(piece, "NumberOfCells", 0,
                                                  std::numeric_limits<std::uint32_t>::max() - 1);
        RawMesh raw;
        raw.vertex_file = raw.edges.file = raw.triangles.file = raw.tetrahedra.file = m_name;
        raw.vertex_base = 0;
        raw.ambient_from_z = true;

        const pugi::xml_node point_array = piece.child("Points").child("DataArray");
        if (!point_array)
            fail(piece_line, "Piece has no Points");
        {
            const Array array = load(point_array, 3 * points, 3, "Points");
            const vtk::Where where{m_name, array.line};
            const std::vector<double> xyz =
                array.ascii ? vtk::ascii_coordinates(array.text, 3 * points, array.type, where,
                                                     array.what)
                            : vtk::to_doubles(array.bytes, array.type, m_big_endian);
            if (!array.ascii)
                vtk::check_coordinates(xyz, where, array.what);
            raw.reserve_points(points);
            for (std::size_t v = 0; v < points; ++v) {
                raw.points.push_back({xyz[3 * v], xyz[3 * v + 1], xyz[3 * v + 2]});
                raw.point_lines.push_back(array.line);
            }
        }

        const pugi::xml_node cell_arrays = piece.child("Cells");
        const auto cell_array = [&](const char* name) {
            const pugi::xml_node node = named_array(cell_arrays, name);
            if (!node)
                fail(cell_arrays ? line_of(cell_arrays) : piece_line,
                     std::string("Cells has no ") + quote(name) + " DataArray");
            return node;
        };
        const pugi::xml_node offsets_node = cell_array("offsets");
        const pugi::xml_node types_node = cell_array("types");
        const pugi::xml_node connectivity_node = cell_array("connectivity");
        const std::vector<std::int64_t> offsets = integers(offsets_node, cells);
        const std::vector<std::int64_t> types = integers(types_node, cells);
        const std::int64_t entries = offsets.empty() ? 0 : offsets.back();
        if (entries < 0)
            fail(line_of(offsets_node), "DataArray 'offsets' ends at " + std::to_string(entries));
        const std::vector<std::int64_t> connectivity =
            integers(connectivity_node, static_cast<std::size_t>(entries));

        std::vector<std::int64_t> labels;
        std::size_t labels_line = piece_line;
        const pugi::xml_node cell_data = piece.child("CellData");
        for (std::string_view name : vtk::label_names)
            if (const pugi::xml_node node = named_array(cell_data, name)) {
                labels = integers(node, cells);
                labels_line = line_of(node);
                break;
            }

        vtk::Cells list;
        list.connectivity = connectivity;
        list.offsets = offsets;
        list.types = types;
        list.labels = labels;
        list.connectivity_line = line_of(connectivity_node);
        list.types_line = line_of(types_node);
        vtk::add_cells(raw, list, points, vtk::Where{m_name, labels_line});
        return raw;
    }

    std::string_view m_bytes;
    const std::string& m_name;
    std::string_view m_xml;  // the text before <AppendedData (the whole file without one)
    pugi::xml_document m_document;
    bool m_have_appended = false, m_appended_base64 = false;
    std::string_view m_appended;  // after the '_' marker
    bool m_big_endian = false, m_compressed = false;
    std::size_t m_header_bytes = 4;
};

}  // namespace

Mesh read_vtu(std::string_view bytes, const std::string& name, const ReadOptions& options,
              ReadReport* report) {
    RawMesh raw = VtuReader(bytes, name).read();
    return build_mesh(raw, name, options, report);
}

}  // namespace sxk::io
