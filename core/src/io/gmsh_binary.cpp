// Gmsh .msh binary files (file type 1), versions 2.2 and 4.1: what Gmsh writes with
// Mesh.Binary = 1, and what ParaView's and meshio's Gmsh writers write when asked for binary.
//
// The layout is the ASCII one with the numbers as bytes: keywords stay text lines, $PhysicalNames
// stays text, and 2.2 keeps its two count lines as text. After "VERSION 1 8" comes the int 1 in
// the writer's byte order, which tells the reader whether to swap. Sizes: Gmsh's `int` is 4
// bytes; its `size_t` (4.1's counts and tags) and its doubles are the header's data size, which
// must be 8. Per section:
//
//   2.2 $Nodes     count line; per node: int tag, 3 doubles
//   2.2 $Elements  count line; blocks of "int type, int n, int ntags" then n times
//                  "int tag, ntags ints (physical first), nodes as ints"
//   4.1 $Entities  4 size_t counts; per entity: int tag, 3 (points) or 6 doubles, size_t
//                  count + int physical tags, and for curves and up size_t count + int bounding
//   4.1 $Nodes     size_t blocks, count, smallest, largest; per block "int dim, int entity,
//                  int parametric, size_t n", n size_t tags, n times 3 (+dim) doubles
//   4.1 $Elements  size_t blocks, count, smallest, largest; per block "int dim, int entity,
//                  int type, size_t n", n times size_t tag and size_t nodes
//
// A binary section ends with a newline before its $End keyword. Errors name no line (binary
// data have none): "FILE:0: $Nodes: ..., at byte N". Every count is checked against the bytes
// left before anything is reserved.
#include <algorithm>
#include <array>
#include <charconv>
#include <climits>
#include <cmath>
#include <cstring>
#include <unordered_map>

#include "binary_numbers.hpp"
#include "formats.hpp"
#include "gmsh_common.hpp"
#include "raw_mesh.hpp"
#include "text.hpp"

namespace sxk::io::gmsh {

namespace {

bool is_space(char c) {
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f';
}

class BinaryReader {
public:
    BinaryReader(std::string_view bytes, const std::string& name) : m_bytes(bytes), m_name(name) {
        m_raw.vertex_file = m_raw.edges.file = m_raw.triangles.file = m_raw.tetrahedra.file = name;
        m_raw.ambient_from_z = true;
    }

    RawMesh& read() {
        read_header();
        for (std::string_view section = next_line(); !section.empty(); section = next_line()) {
            m_section = section;
            if (section == "$Nodes") {
                if (m_have_nodes)
                    fail("section $Nodes appears twice");
                m_have_nodes = true;
                m_version == 2 ? read_nodes_2() : read_nodes_4();
                end_section("$EndNodes");
            } else if (section == "$Elements") {
                if (!m_have_nodes)
                    fail("$Elements before $Nodes");
                if (m_have_elements)
                    fail("section $Elements appears twice");
                m_have_elements = true;
                m_version == 2 ? read_elements_2() : read_elements_4();
                end_section("$EndElements");
            } else if (section == "$Entities" && m_version == 4) {
                if (m_have_entities)
                    fail("section $Entities appears twice");
                m_have_entities = true;
                read_entities();
                end_section("$EndEntities");
            } else if (section == "$PhysicalNames") {
                read_physical_names_text();
            } else if (std::find(gmsh::skipped_sections.begin(), gmsh::skipped_sections.end(),
                                 section) != gmsh::skipped_sections.end()) {
                // binary data of no interest: up to the section's end keyword at a line start
                const std::string end = "\n$End" + std::string(section.substr(1));
                const std::size_t at = m_bytes.find(end, m_at - 1);
                if (at == std::string_view::npos)
                    fail("section " + std::string(section) + " has no " + end.substr(1));
                m_at = at + end.size();
            } else if (section[0] == '$') {
                fail("unknown section " + quote(section));
            } else {
                fail("expected a section such as $Nodes, found " + quote(section));
            }
        }
        m_section = "";
        if (!m_have_nodes)
            fail("missing $Nodes section");
        if (!m_have_elements)
            fail("missing $Elements section");
        labels_from_groups(m_raw, m_names);
        return m_raw;
    }

    const std::vector<PhysicalName>& names() const { return m_names; }

private:
    [[noreturn]] void fail(const std::string& reason) const {
        const std::string where = m_section.empty() ? "" : std::string(m_section) + ": ";
        throw InputError(m_name, 0, where + reason + ", at byte " + std::to_string(m_at));
    }

    std::size_t left() const { return m_bytes.size() - m_at; }

    // A line of text (a keyword, a count), blanks and empty lines before it skipped; empty at
    // the end of the file.
    std::string_view next_line() {
        while (m_at < m_bytes.size() && is_space(m_bytes[m_at]))
            ++m_at;
        if (m_at == m_bytes.size())
            return {};
        const std::size_t end = std::min(m_bytes.find('\n', m_at), m_bytes.size());
        std::string_view line = m_bytes.substr(m_at, end - m_at);
        while (!line.empty() && is_space(line.back()))
            line.remove_suffix(1);
        m_at = std::min(end + 1, m_bytes.size());
        return line;
    }

    void expect_line(std::string_view keyword) {
        const std::size_t at = m_at;
        const std::string_view line = next_line();
        if (line != keyword) {
            m_at = at;
            fail("expected " + std::string(keyword) + ", found " +
                 (line.empty() ? std::string("the end of the file") : quote(line)));
        }
    }

    void end_section(std::string_view keyword) {
        const std::size_t at = m_at;
        const std::string_view line = next_line();
        if (line == keyword)
            return;
        m_at = at;
        fail("expected " + std::string(keyword) +
             " after the section's data (the counts do not match the data)");
    }

    // A count on a text line (2.2's node and element counts).
    std::int64_t count_line(const char* what, std::int64_t maximum) {
        const std::string_view line = next_line();
        std::int64_t value = 0;
        const auto [end, error] = std::from_chars(line.data(), line.data() + line.size(), value);
        if (line.empty() || error != std::errc() || end != line.data() + line.size())
            fail(std::string("expected ") + what + ", found " +
                 (line.empty() ? std::string("the end of the file") : quote(line)));
        if (value < 0 || value > maximum)
            fail(std::string(what) + " out of range: " + quote(line));
        return value;
    }

    template <class T>
    T take(const char* what) {
        if (left() < sizeof(T))
            fail(std::string("truncated file: expected ") + what);
        const T value = load_number<T>(m_bytes.data() + m_at, m_big_endian);
        m_at += sizeof(T);
        return value;
    }
    std::int64_t int32(const char* what, std::int64_t low = INT32_MIN,
                       std::int64_t high = INT32_MAX) {
        const std::int64_t value = take<std::int32_t>(what);
        if (value < low || value > high)
            fail(std::string(what) + " out of range: " + std::to_string(value));
        return value;
    }
    std::int64_t size(const char* what, std::int64_t high = INT64_MAX) {
        const std::uint64_t value = take<std::uint64_t>(what);
        if (value > static_cast<std::uint64_t>(high))
            fail(std::string(what) + " out of range: " + std::to_string(value));
        return static_cast<std::int64_t>(value);
    }
    double real(const char* what) {
        const double value = take<double>(what);
        if (!std::isfinite(value))
            fail(std::string(what) + " is not finite");
        return value;
    }
    // Room for `count` records of at least `bytes` each, or the message that the file is too
    // short for what it declares (before anything is reserved for them).
    void need_room(std::int64_t count, std::size_t bytes, const char* things) {
        if (static_cast<std::uint64_t>(count) > left() / bytes)
            fail("truncated file: " + std::to_string(count) + " " + things +
                 " declared, room for " + std::to_string(left() / bytes));
    }

    void read_header() {
        expect_line("$MeshFormat");
        const std::string_view header = next_line();  // "VERSION 1 DATASIZE"
        const std::size_t blank = header.find(' ');
        const std::string_view version = header.substr(0, blank);
        if (version == "2" || version == "2.0" || version == "2.1" || version == "2.2")
            m_version = 2;
        else if (version == "4.1")
            m_version = 4;
        else
            fail("unsupported Gmsh version " + quote(version) + " (2.2 and 4.1 are supported)");
        const std::string_view rest =
            blank == std::string_view::npos ? "" : header.substr(blank + 1);
        if (rest != "1 8")
            fail("expected file type 1 and data size 8 after the version, found " + quote(rest));
        // the int 1 in the writer's byte order; a message names the byte where it starts
        if (left() < 4)
            fail("truncated file: expected the int 1 after the header");
        const auto little = load_number<std::int32_t>(m_bytes.data() + m_at, false);
        const auto big = load_number<std::int32_t>(m_bytes.data() + m_at, true);
        if (little != 1 && big != 1)
            fail("expected the int 1 after the header, found " + std::to_string(little));
        m_big_endian = little != 1;
        m_at += 4;
        expect_line("$EndMeshFormat");
    }

    // $PhysicalNames is text in binary files too: read with the ASCII reader's cursor over the
    // section's text, its lines counted from the file's start (the section comes before any
    // binary data in Gmsh's files).
    void read_physical_names_text() {
        const std::size_t end = m_bytes.find("$EndPhysicalNames", m_at);
        if (end == std::string_view::npos)
            fail("section $PhysicalNames has no $EndPhysicalNames");
        const std::size_t stop = end + std::string_view("$EndPhysicalNames").size();
        const std::string_view text = m_bytes.substr(m_at, stop - m_at);
        const std::size_t line_before = static_cast<std::size_t>(
            std::count(m_bytes.begin(), m_bytes.begin() + static_cast<std::ptrdiff_t>(m_at), '\n'));
        try {
            Cursor in(check_text(text, m_name), m_name, '\0');
            const std::vector<PhysicalName> names = read_physical_names(in);
            m_names.insert(m_names.end(), names.begin(), names.end());
        } catch (const InputError& error) {
            throw InputError(m_name, line_before + error.line(), error.reason());
        }
        m_at = stop;
    }

    void add_point(std::int64_t tag) {
        Point p{0, 0, 0};
        static constexpr const char* axes[] = {"x coordinate", "y coordinate", "z coordinate"};
        for (std::size_t c = 0; c < 3; ++c)
            p[c] = real(axes[c]);
        m_raw.points.push_back(p);
        m_raw.point_lines.push_back(0);
        m_raw.point_numbers.push_back(tag);
    }

    void build_node_map() {
        if (const auto repeated = m_nodes.build(m_raw.point_numbers))
            fail("node " + std::to_string(m_raw.point_numbers[*repeated]) + " is defined twice");
    }

    CellList* cells_of(int size) {
        return size == 2   ? &m_raw.edges
               : size == 3 ? &m_raw.triangles
               : size == 4 ? &m_raw.tetrahedra
                           : nullptr;
    }

    void add_node_of(CellList* cells, std::int64_t node) {
        const VertexId v = m_nodes.find(node);
        if (v == invalid_id)
            fail("undefined node " + std::to_string(node));
        if (cells)
            cells->vertices.push_back(v);
    }

    void file_element(CellList* cells, std::int64_t tag, int label) {
        if (!cells)
            return;
        cells->labels.push_back(label);
        cells->numbers.push_back(tag);
        cells->lines.push_back(0);
    }

    void read_nodes_2() {
        const std::int64_t count = count_line("number of nodes", invalid_id - 1);
        need_room(count, 4 + 3 * 8, "nodes");
        m_raw.reserve_points(static_cast<std::size_t>(count), true);
        for (std::int64_t i = 0; i < count; ++i)
            add_point(int32("node tag", 1));
        build_node_map();
    }

    void read_elements_2() {
        const std::int64_t count = count_line("number of elements", invalid_id - 1);
        std::int64_t seen = 0;
        while (seen < count) {
            const std::int64_t type = int32("element type");
            const int vertices = type_size(type);
            if (vertices == 0)
                fail(unsupported_type(type));
            const std::int64_t n = int32("number of elements in the block", 1, count - seen);
            const std::int64_t tags = int32("number of tags", 0);
            need_room(n, 4 * static_cast<std::size_t>(1 + tags + vertices), "elements");
            CellList* cells = cells_of(vertices);
            for (std::int64_t i = 0; i < n; ++i) {
                const std::int64_t tag = int32("element tag", 1);
                int label = 0;
                for (std::int64_t t = 0; t < tags; ++t) {
                    const std::int64_t value = int32("tag");
                    if (t == 0)
                        label = static_cast<int>(value);
                }
                for (int j = 0; j < vertices; ++j)
                    add_node_of(cells, int32("node tag"));
                file_element(cells, tag, label);
            }
            seen += n;
        }
    }

    void read_entities() {
        std::array<std::int64_t, 4> counts{};
        for (std::int64_t& c : counts)
            c = size("number of entities");
        for (std::size_t dim = 0; dim < 4; ++dim) {
            need_room(counts[dim], 4 + (dim == 0 ? 3 : 6) * 8 + 8, "entities");
            for (std::int64_t e = 0; e < counts[dim]; ++e) {
                const std::int64_t tag = int32("entity tag");
                for (int c = 0; c < (dim == 0 ? 3 : 6); ++c)
                    real("bounding box coordinate");
                const std::int64_t physicals = size("number of physical tags");
                need_room(physicals, 4, "physical tags");
                int label = 0;
                for (std::int64_t p = 0; p < physicals; ++p) {
                    const std::int64_t value = int32("physical tag");
                    if (p == 0)
                        label = static_cast<int>(value);
                }
                if (dim > 0) {
                    const std::int64_t bounding = size("number of bounding entities");
                    need_room(bounding, 4, "bounding entities");
                    m_at += static_cast<std::size_t>(bounding) * 4;
                }
                m_entities[{static_cast<int>(dim), tag}] = label;
            }
        }
    }

    void read_nodes_4() {
        const std::int64_t blocks = size("number of node blocks");
        const std::int64_t count = size("number of nodes", invalid_id - 1);
        size("smallest node tag");
        size("largest node tag");
        need_room(count, 8 + 3 * 8, "nodes");
        m_raw.reserve_points(static_cast<std::size_t>(count), true);
        for (std::int64_t b = 0; b < blocks; ++b) {
            const std::int64_t dim = int32("entity dimension", 0, 3);
            int32("entity tag");
            const std::int64_t parametric = int32("parametric flag", 0, 1);
            const std::int64_t n = size("number of nodes in the block", invalid_id - 1);
            if (static_cast<std::int64_t>(m_raw.points.size()) + n > count)
                fail("node blocks hold more than the " + std::to_string(count) +
                     " nodes the section declares");
            need_room(n, 8 + static_cast<std::size_t>(3 + parametric * dim) * 8, "nodes");
            std::vector<std::int64_t> tags(static_cast<std::size_t>(n));
            for (std::int64_t& tag : tags)
                tag = size("node tag");
            for (std::size_t i = 0; i < tags.size(); ++i) {
                if (tags[i] < 1)
                    fail("node tag out of range: 0");
                add_point(tags[i]);
                for (std::int64_t u = 0; parametric == 1 && u < dim; ++u)
                    real("parametric coordinate");
            }
        }
        if (static_cast<std::int64_t>(m_raw.points.size()) != count)
            fail("section $Nodes declares " + std::to_string(count) +
                 " nodes but its blocks hold " + std::to_string(m_raw.points.size()));
        build_node_map();
    }

    void read_elements_4() {
        const std::int64_t blocks = size("number of element blocks");
        const std::int64_t count = size("number of elements", invalid_id - 1);
        size("smallest element tag");
        size("largest element tag");
        std::int64_t seen = 0;
        for (std::int64_t b = 0; b < blocks; ++b) {
            const std::int64_t dim = int32("entity dimension", 0, 3);
            const std::int64_t entity = int32("entity tag");
            const std::int64_t type = int32("element type");
            const std::int64_t n = size("number of elements in the block", invalid_id - 1);
            const int vertices = type_size(type);
            if (vertices == 0)
                fail(unsupported_type(type));
            if (vertices - 1 != dim)
                fail("element type " + std::to_string(type) + " in a block of dimension " +
                     std::to_string(dim));
            int label = 0;
            if (m_have_entities) {
                const auto at = m_entities.find({static_cast<int>(dim), entity});
                if (at == m_entities.end())
                    fail("unknown entity (dimension " + std::to_string(dim) + ", tag " +
                         std::to_string(entity) + ")");
                label = at->second;
            }
            seen += n;
            if (seen > count)
                fail("element blocks hold more than the " + std::to_string(count) +
                     " elements the section declares");
            need_room(n, 8 * static_cast<std::size_t>(1 + vertices), "elements");
            CellList* cells = cells_of(vertices);
            for (std::int64_t i = 0; i < n; ++i) {
                const std::int64_t tag = size("element tag");
                if (tag < 1)
                    fail("element tag out of range: 0");
                for (int j = 0; j < vertices; ++j)
                    add_node_of(cells, size("node tag"));
                file_element(cells, tag, label);
            }
        }
        if (seen != count)
            fail("section $Elements declares " + std::to_string(count) +
                 " elements but its blocks hold " + std::to_string(seen));
    }

    std::string_view m_bytes;
    const std::string& m_name;
    std::size_t m_at = 0;
    bool m_big_endian = false;
    int m_version = 0;
    std::string_view m_section;
    bool m_have_nodes = false, m_have_elements = false, m_have_entities = false;
    RawMesh m_raw;
    NodeMap m_nodes;
    EntityLabels m_entities;
    std::vector<PhysicalName> m_names;
};

}  // namespace

bool announces_binary(std::string_view bytes) {
    // "$MeshFormat", then "VERSION FILETYPE ..." on the next line: file type 1 is binary
    std::size_t at = 0;
    auto word = [&] {
        while (at < bytes.size() && is_space(bytes[at]))
            ++at;
        const std::size_t begin = at;
        while (at < bytes.size() && !is_space(bytes[at]))
            ++at;
        return bytes.substr(begin, at - begin);
    };
    return word() == "$MeshFormat" && !word().empty() && word() == "1";
}

Mesh read_binary(std::string_view bytes, const std::string& name, const ReadOptions& options,
                 ReadReport* report) {
    BinaryReader reader(bytes, name);
    Mesh mesh = build_mesh(reader.read(), name, options, report);
    keep_label_names(mesh, reader.names());
    return mesh;
}

}  // namespace sxk::io::gmsh
