// Gmsh .msh versions 2.2 and 4.1: the ASCII reader and the writer of both encodings (the binary
// reader is gmsh_binary.cpp, which this one hands a file whose header says file type 1).
//
//   $MeshFormat / 2.2 0 8 / $EndMeshFormat
//   $Nodes / N / "tag x y z" ... / $EndNodes
//   $Elements / M / "tag type ntags physical elementary ... nodes" ... / $EndElements
//
//   $MeshFormat / 4.1 0 8 / $EndMeshFormat
//   $Entities / #points #curves #surfaces #volumes / one line per entity with its physical
//       tags / $EndEntities
//   $Nodes / #blocks N min max / per block "dim entity parametric n", n tags, n "x y z" /
//   $EndNodes
//   $Elements / #blocks M min max / per block "dim entity type n", n "tag nodes..." /
//   $EndElements
//
// Labels are physical tags: an element's label is its first physical tag (2.2: the first tag
// of the element; 4.1: the first physical tag of its entity), 0 when it has none; a group named
// `label N` stands for label N, and other names are the mesh's label names (gmsh_common.hpp).
// Elements one dimension below the mesh (triangles of a tetrahedral mesh, lines of a triangle mesh)
// become labelled faces; points and lower elements are checked and dropped. Node tags may be any
// positive numbers, in any order. Gmsh always stores x y z: a triangle mesh whose z are all 0 is
// planar (ambient dimension 2).
//
// Sections that carry no connectivity ($Comments, $NodeData, ...) are skipped; an unknown section
// is an error, so a misspelt $Elemnts does not go unnoticed. $PhysicalNames is read for its count
// and entries (dimension 0..3, tag, quoted name), which are checked.
//
// The writer puts every element and labelled face in a physical group (gmsh_common.hpp says
// why and how labels become groups), and with WriteOptions::encoding == Encoding::binary writes
// Gmsh's binary layout (gmsh_binary.cpp describes it).
#include <algorithm>
#include <array>
#include <climits>
#include <cstring>
#include <span>
#include <unordered_map>

#include "../fresh_array.hpp"
#include "binary_numbers.hpp"
#include "formats.hpp"
#include "gmsh_common.hpp"
#include "raw_mesh.hpp"
#include "text.hpp"
#include "writing.hpp"

namespace sxk::io {

namespace {

using gmsh::EntityLabels;
using gmsh::NodeMap;
using gmsh::PhysicalName;
using gmsh::type_size;

[[noreturn]] void unsupported_type(const Cursor& in, std::int64_t type) {
    in.fail(gmsh::unsupported_type(type));
}

}  // namespace

// "$PhysicalNames / count / dimension tag "name" (one per line) / $EndPhysicalNames", one
// entry per line because a quoted name may hold blanks; counted like every other count
// (docs/formats.md). The names become labels or label names (gmsh_common.hpp).
std::vector<PhysicalName> gmsh::read_physical_names(Cursor& in) {
    std::vector<PhysicalName> names;
    if (!in.next_line())
        in.fail("truncated file: expected number of physical names");
    const std::int64_t count = in.to_integer(in.need_in_line("number of physical names"),
                                             "number of physical names", 0, INT64_MAX);
    if (!in.line_done())
        in.fail("unexpected " + quote(in.next_in_line()) + " after the number of physical names");
    for (std::int64_t i = 0; i < count; ++i) {
        if (!in.next_line())
            in.fail("truncated file: expected $EndPhysicalNames");
        const std::string_view first = in.need_in_line("physical dimension");
        if (first[0] == '$')
            in.fail("section $PhysicalNames declares " + std::to_string(count) + " names but has " +
                    std::to_string(i));
        PhysicalName group;
        group.dimension = static_cast<int>(in.to_integer(first, "physical dimension", 0, 3));
        group.tag =
            in.to_integer(in.need_in_line("physical tag"), "physical tag", INT64_MIN, INT64_MAX);
        // "name", possibly several tokens: from a token starting with a quote to one ending
        // with one; the name is the text between, blanks as they stand in the file
        std::string_view word = in.need_in_line("physical name");
        if (word[0] != '"')
            in.fail("expected a quoted physical name, found " + quote(word));
        const char* begin = word.data() + 1;
        word.remove_prefix(1);
        while (word.empty() || word.back() != '"') {
            word = in.next_in_line();
            if (word.empty())
                in.fail("physical name without its closing '\"'");
        }
        group.name.assign(begin, word.data() + word.size() - 1);
        names.push_back(std::move(group));
        if (!in.line_done())
            in.fail("unexpected " + quote(in.next_in_line()) + " after the physical name");
    }
    const std::string_view token = in.need("$EndPhysicalNames");
    if (token != "$EndPhysicalNames") {
        if (token[0] == '$')
            in.fail("expected $EndPhysicalNames, found " + quote(token));
        in.fail("section $PhysicalNames has more than the " + std::to_string(count) +
                " names it declares");
    }
    return names;
}

namespace {

class Reader {
public:
    Reader(std::string_view text, const std::string& name) : m_in(text, name, '\0'), m_text(text) {
        m_raw.vertex_file = m_raw.edges.file = m_raw.triangles.file = m_raw.tetrahedra.file = name;
        m_raw.ambient_from_z = true;
    }

    RawMesh& read() {
        const std::string_view first = m_in.need("$MeshFormat");
        if (first != "$MeshFormat")
            m_in.fail("expected $MeshFormat, found " + quote(first));
        const std::string_view version = m_in.need("format version");
        if (version == "2" || version == "2.0" || version == "2.1" || version == "2.2") {
            m_version = 2;
        } else if (version == "4.1") {
            m_version = 4;
        } else {
            m_in.fail("unsupported Gmsh version " + quote(version) +
                      " (2.2 and 4.1 are supported)");
        }
        const std::string_view file_type = m_in.need("file type");
        if (file_type != "0")
            m_in.fail("expected file type 0 (ASCII), found " + quote(file_type));
        m_in.to_integer(m_in.need("data size"), "data size", 1, 16);
        expect("$EndMeshFormat");

        for (std::string_view section = m_in.next(); !section.empty(); section = m_in.next()) {
            if (section == "$Nodes") {
                if (m_have_nodes)
                    m_in.fail("section $Nodes appears twice");
                m_have_nodes = true;
                m_version == 2 ? read_nodes_2() : read_nodes_4();
            } else if (section == "$Elements") {
                if (!m_have_nodes)
                    m_in.fail("$Elements before $Nodes");
                if (m_have_elements)
                    m_in.fail("section $Elements appears twice");
                m_have_elements = true;
                m_version == 2 ? read_elements_2() : read_elements_4();
            } else if (section == "$PhysicalNames") {
                const std::vector<PhysicalName> names = gmsh::read_physical_names(m_in);
                m_names.insert(m_names.end(), names.begin(), names.end());
            } else if (section == "$Entities" && m_version == 4) {
                if (m_have_entities)
                    m_in.fail("section $Entities appears twice");
                m_have_entities = true;
                read_entities();
            } else if (std::find(gmsh::skipped_sections.begin(), gmsh::skipped_sections.end(),
                                 section) != gmsh::skipped_sections.end()) {
                const std::string end = "$End" + std::string(section.substr(1));
                while (m_in.need(end.c_str()) != end) {
                }
            } else if (section[0] == '$') {
                m_in.fail("unknown section " + quote(section));
            } else {
                m_in.fail("expected a section such as $Nodes, found " + quote(section));
            }
        }
        if (!m_have_nodes)
            m_in.fail("missing $Nodes section");
        if (!m_have_elements)
            m_in.fail("missing $Elements section");
        gmsh::labels_from_groups(m_raw, m_names);
        return m_raw;
    }

    const std::vector<PhysicalName>& names() const { return m_names; }

private:
    void expect(const char* keyword) {
        const std::string_view token = m_in.need(keyword);
        if (token != keyword)
            m_in.fail(std::string("expected ") + keyword + ", found " + quote(token));
    }

    std::size_t bytes_left() {
        return static_cast<std::size_t>(m_text.data() + m_text.size() - m_in.peek().data());
    }

    // A token of the section's data: a '$' keyword here means the section stopped early.
    std::string_view data(const char* what) {
        const std::string_view token = m_in.need(what);
        if (token[0] == '$')
            m_in.fail("section " + std::string(m_section) + " ends early: expected " + what +
                      ", found " + quote(token));
        return token;
    }
    std::int64_t integer(const char* what, std::int64_t low, std::int64_t high) {
        return m_in.to_integer(data(what), what, low, high);
    }
    // The end of a section whose declared count has been read: anything else is extra data.
    void end_section(const char* end, const char* things, std::int64_t declared) {
        const std::string_view token = m_in.need(end);
        if (token == end)
            return;
        if (token[0] == '$')
            m_in.fail(std::string("expected ") + end + ", found " + quote(token));
        m_in.fail("section " + std::string(m_section) + " has more than the " +
                  std::to_string(declared) + " " + things + " it declares");
    }

    void add_node(std::int64_t tag) {
        Point p{0, 0, 0};
        static constexpr const char* axes[] = {"x coordinate", "y coordinate", "z coordinate"};
        for (std::size_t c = 0; c < 3; ++c) {
            p[c] = m_in.to_double(data(axes[c]), axes[c]);
            if (c == 0 && m_version == 2)
                m_raw.point_lines.push_back(m_in.line());
        }
        m_raw.points.push_back(p);
        if (m_version == 2)
            m_raw.point_numbers.push_back(tag);
    }

    void read_nodes_2() {
        m_section = "$Nodes";
        const std::int64_t count = integer("number of nodes", 0, invalid_id - 1);
        const std::size_t n = plausible_count(count, bytes_left(), 8);
        m_raw.reserve_points(n, true);
        for (std::int64_t i = 0; i < count; ++i) {
            const std::string_view token = m_in.need("node tag");
            if (token[0] == '$')
                m_in.fail("section $Nodes declares " + std::to_string(count) + " nodes but has " +
                          std::to_string(i));
            add_node(m_in.to_integer(token, "node tag", 1, INT64_MAX));
        }
        end_section("$EndNodes", "nodes", count);
        build_node_map();
    }

    void build_node_map() {
        if (const auto repeated = m_nodes.build(m_raw.point_numbers))
            m_in.fail_at(
                m_raw.point_lines[*repeated],
                "node " + std::to_string(m_raw.point_numbers[*repeated]) + " is defined twice");
    }

    void read_nodes_4() {
        m_section = "$Nodes";
        const std::int64_t blocks = integer("number of node blocks", 0, INT64_MAX);
        const std::int64_t count = integer("number of nodes", 0, invalid_id - 1);
        integer("smallest node tag", 0, INT64_MAX);
        integer("largest node tag", 0, INT64_MAX);
        const std::size_t n = plausible_count(count, bytes_left(), 8);
        m_raw.reserve_points(n, true);
        for (std::int64_t b = 0; b < blocks; ++b) {
            const std::int64_t dim = integer("entity dimension", 0, 3);
            integer("entity tag", INT64_MIN, INT64_MAX);
            const std::int64_t parametric = integer("parametric flag", 0, 1);
            const std::int64_t size = integer("number of nodes in the block", 0, invalid_id - 1);
            if (static_cast<std::int64_t>(m_raw.points.size()) + size > count)
                m_in.fail("node blocks hold more than the " + std::to_string(count) +
                          " nodes the section declares");
            const std::size_t first = m_raw.point_numbers.size();
            for (std::int64_t i = 0; i < size; ++i) {
                m_raw.point_numbers.push_back(integer("node tag", 1, INT64_MAX));
                m_raw.point_lines.push_back(m_in.line());
            }
            for (std::int64_t i = 0; i < size; ++i) {
                add_node(m_raw.point_numbers[first + static_cast<std::size_t>(i)]);
                // the node's line for messages: where its coordinates are
                m_raw.point_lines[first + static_cast<std::size_t>(i)] = m_in.line();
                for (std::int64_t u = 0; parametric == 1 && u < dim; ++u)
                    m_in.to_double(data("parametric coordinate"), "parametric coordinate");
            }
        }
        if (static_cast<std::int64_t>(m_raw.points.size()) != count)
            m_in.fail("section $Nodes declares " + std::to_string(count) +
                      " nodes but its blocks hold " + std::to_string(m_raw.points.size()));
        end_section("$EndNodes", "nodes", count);
        build_node_map();
    }

    // Reads `size` node tags of an element and files it by size.
    void add_element(std::int64_t tag, int size, int label) {
        CellList* cells = size == 2   ? &m_raw.edges
                          : size == 3 ? &m_raw.triangles
                          : size == 4 ? &m_raw.tetrahedra
                                      : nullptr;
        for (int j = 0; j < size; ++j) {
            const std::int64_t node = m_in.to_integer(data("node tag"), "node tag");
            const VertexId v = m_nodes.find(node);
            if (v == invalid_id)
                m_in.fail("undefined node " + std::to_string(node));
            if (!cells)
                continue;
            cells->vertices.push_back(v);
            if (j == 0)
                cells->lines.push_back(m_in.line());
        }
        if (!cells)
            return;
        cells->labels.push_back(label);
        cells->numbers.push_back(tag);
    }

    void read_elements_2() {
        m_section = "$Elements";
        const std::int64_t count = integer("number of elements", 0, invalid_id - 1);
        const std::size_t n = plausible_count(count, bytes_left(), 16);
        detail::reserve_fresh(m_raw.tetrahedra.vertices, 4 * n);
        for (std::int64_t i = 0; i < count; ++i) {
            const std::string_view token = m_in.need("element tag");
            if (token[0] == '$')
                m_in.fail("section $Elements declares " + std::to_string(count) +
                          " elements but has " + std::to_string(i));
            const std::int64_t tag = m_in.to_integer(token, "element tag", 1, INT64_MAX);
            const std::int64_t type = integer("element type", INT64_MIN, INT64_MAX);
            const int size = type_size(type);
            if (size == 0)
                unsupported_type(m_in, type);
            const std::int64_t tags = integer("number of tags", 0, INT_MAX);
            int label = 0;
            for (std::int64_t t = 0; t < tags; ++t) {
                const std::int64_t value = integer("tag", INT_MIN, INT_MAX);
                if (t == 0)
                    label = static_cast<int>(value);
            }
            add_element(tag, size, label);
        }
        end_section("$EndElements", "elements", count);
    }

    void read_entities() {
        m_section = "$Entities";
        std::array<std::int64_t, 4> counts{};
        for (std::int64_t& c : counts)
            c = integer("number of entities", 0, INT64_MAX);
        for (std::size_t dim = 0; dim < 4; ++dim) {
            for (std::int64_t e = 0; e < counts[dim]; ++e) {
                const std::int64_t tag = integer("entity tag", INT64_MIN, INT64_MAX);
                for (int c = 0; c < (dim == 0 ? 3 : 6); ++c)
                    m_in.to_double(data("bounding box coordinate"), "bounding box coordinate");
                const std::int64_t physicals = integer("number of physical tags", 0, INT64_MAX);
                int label = 0;
                for (std::int64_t p = 0; p < physicals; ++p) {
                    const std::int64_t value = integer("physical tag", INT_MIN, INT_MAX);
                    if (p == 0)
                        label = static_cast<int>(value);
                }
                if (dim > 0) {
                    const std::int64_t bounding =
                        integer("number of bounding entities", 0, INT64_MAX);
                    for (std::int64_t b = 0; b < bounding; ++b)
                        integer("bounding entity tag", INT64_MIN, INT64_MAX);
                }
                m_entities[{static_cast<int>(dim), tag}] = label;
            }
        }
        expect("$EndEntities");
    }

    void read_elements_4() {
        m_section = "$Elements";
        const std::int64_t blocks = integer("number of element blocks", 0, INT64_MAX);
        const std::int64_t count = integer("number of elements", 0, invalid_id - 1);
        integer("smallest element tag", 0, INT64_MAX);
        integer("largest element tag", 0, INT64_MAX);
        std::int64_t seen = 0;
        for (std::int64_t b = 0; b < blocks; ++b) {
            const std::int64_t dim = integer("entity dimension", 0, 3);
            const std::int64_t entity = integer("entity tag", INT64_MIN, INT64_MAX);
            const std::int64_t type = integer("element type", INT64_MIN, INT64_MAX);
            const std::int64_t size = integer("number of elements in the block", 0, invalid_id - 1);
            const int vertices = type_size(type);
            if (vertices == 0)
                unsupported_type(m_in, type);
            if (vertices - 1 != dim)
                m_in.fail("element type " + std::to_string(type) + " in a block of dimension " +
                          std::to_string(dim));
            int label = 0;
            if (m_have_entities) {
                const auto at = m_entities.find({static_cast<int>(dim), entity});
                if (at == m_entities.end())
                    m_in.fail("unknown entity (dimension " + std::to_string(dim) + ", tag " +
                              std::to_string(entity) + ")");
                label = at->second;
            }
            seen += size;
            if (seen > count)
                m_in.fail("element blocks hold more than the " + std::to_string(count) +
                          " elements the section declares");
            for (std::int64_t i = 0; i < size; ++i)
                add_element(integer("element tag", 1, INT64_MAX), vertices, label);
        }
        if (seen != count)
            m_in.fail("section $Elements declares " + std::to_string(count) +
                      " elements but its blocks hold " + std::to_string(seen));
        end_section("$EndElements", "elements", count);
    }

    Cursor m_in;
    std::string_view m_text;
    RawMesh m_raw;
    int m_version = 0;
    bool m_have_nodes = false, m_have_elements = false, m_have_entities = false;
    const char* m_section = "";
    NodeMap m_nodes;
    EntityLabels m_entities;
    std::vector<PhysicalName> m_names;
};

}  // namespace

Mesh read_gmsh(std::string_view text, const std::string& name, const ReadOptions& options,
               ReadReport* report) {
    if (gmsh::announces_binary(text))
        return gmsh::read_binary(text, name, options, report);
    Reader reader(check_text(text, name), name);
    Mesh mesh = build_mesh(reader.read(), name, options, report);
    gmsh::keep_label_names(mesh, reader.names());
    return mesh;
}

namespace {

// Where the writer's numbers go: text tokens separated by blanks, one record a line, or the
// binary layout of Gmsh's file type 1 (little-endian; the reader tells by the 1 after the
// header). Gmsh's binary sections keep their keywords and, in 2.2,
// their count lines as text: the writer switches with line().
class Sink {
public:
    Sink(std::string& out, bool binary) : m_out(out), m_binary(binary) {}
    bool binary() const { return m_binary; }
    // an int (Gmsh's `int`: 4 bytes in binary)
    void int32(std::int64_t value) {
        if (m_binary) {
            if (value < INT32_MIN || value > INT32_MAX)
                throw OutputError("a binary Gmsh file holds numbers up to 2147483647, not " +
                                  std::to_string(value));
            put(static_cast<std::int32_t>(value));
        } else {
            token();
            append_number(m_out, value);
        }
    }
    // a count or a 4.1 tag (Gmsh's `size_t`: 8 bytes in binary)
    void size(std::size_t value) {
        if (m_binary) {
            put(static_cast<std::uint64_t>(value));
        } else {
            token();
            append_number(m_out, value);
        }
    }
    void real(double value) {
        if (m_binary) {
            put(value);
        } else {
            token();
            append_number(m_out, value);
        }
    }
    void point(const Point& p) {
        real(p[0]);
        real(p[1]);
        real(p[2]);
    }
    // ends a record: a new line in text, nothing in binary
    void end() {
        if (!m_binary)
            m_out += '\n';
        m_fresh = true;
    }
    // a line of text in either encoding (keywords, 2.2's counts); binary data before it get the
    // newline Gmsh writes after them
    void line(std::string_view text) {
        if (m_binary && m_data)
            m_out += '\n';
        m_data = false;
        m_out += text;
        m_out += '\n';
        m_fresh = true;
    }
    // a count on a line of its own in both encodings (2.2 binary keeps them as text)
    void count_line(std::size_t value) {
        append_number(m_out, value);
        m_out += '\n';
        m_fresh = true;
    }

private:
    void token() {
        if (!m_fresh)
            m_out += ' ';
        m_fresh = false;
    }
    template <class T>
    void put(T value) {
        append_little_endian(m_out, value);
        m_data = true;
    }
    std::string& m_out;
    bool m_binary;
    bool m_fresh = true;  // no token on the current line yet
    bool m_data = false;  // binary data since the last line of text
};

void write_header(Sink& out, const char* version, const gmsh::PhysicalGroups& groups) {
    out.line("$MeshFormat");
    if (out.binary()) {
        // "VERSION 1 8", then the int 1 in the writer's byte order, then a newline
        out.line(std::string(version) + " 1 8");
        out.int32(1);
    } else {
        out.line(std::string(version) + " 0 8");
    }
    out.line("$EndMeshFormat");
    if (groups.names().empty())
        return;
    // text in both encodings
    out.line("$PhysicalNames");
    out.count_line(groups.names().size());
    for (const gmsh::PhysicalName& group : groups.names())
        out.line(std::to_string(group.dimension) + ' ' + std::to_string(group.tag) + " \"" +
                 group.name + '"');
    out.line("$EndPhysicalNames");
}

int gmsh_type(int vertices) {
    return vertices == 4 ? 4 : vertices == 3 ? 2 : 1;
}

std::string write_gmsh_22(const Mesh& mesh, std::span<const Point> positions, bool binary,
                          const gmsh::PhysicalGroups& groups,
                          const std::vector<std::pair<Simplex, int>>& faces) {
    std::string out;
    out.reserve(mesh.vertex_count() * (binary ? 32 : 64) +
                mesh.element_count() * (binary ? 28 : 48));
    Sink sink(out, binary);
    write_header(sink, "2.2", groups);
    sink.line("$Nodes");
    sink.count_line(mesh.vertex_count());
    for (std::size_t v = 0; v < positions.size(); ++v) {
        sink.int32(static_cast<std::int64_t>(v + 1));
        sink.point(positions[v]);
        sink.end();
    }
    sink.line("$EndNodes");
    sink.line("$Elements");
    sink.count_line(faces.size() + mesh.element_count());
    std::size_t tag = 0;
    // "tag type 2 physical elementary nodes": the group is both tags (an elementary tag of 0
    // is no entity to Gmsh), so Gmsh shows it whichever it colours by. Binary groups elements
    // of one type under a header "type count 2".
    auto element = [&](const Simplex& s, int group) {
        sink.int32(static_cast<std::int64_t>(++tag));
        if (!binary) {
            sink.int32(gmsh_type(s.count()));
            sink.int32(2);
        }
        sink.int32(group);
        sink.int32(group);
        const auto v = oriented_vertices(s);
        for (int j = 0; j < s.count(); ++j)
            sink.int32(static_cast<std::int64_t>(v[static_cast<std::size_t>(j)]) + 1);
        sink.end();
    };
    auto block_header = [&](int vertices, std::size_t count) {
        if (binary && count > 0) {
            sink.int32(gmsh_type(vertices));
            sink.int32(static_cast<std::int64_t>(count));
            sink.int32(2);
        }
    };
    const int k = mesh.element_vertex_count();
    block_header(k - 1, faces.size());
    for (const auto& [face, label] : faces)
        element(face, groups.face_tag(label));
    block_header(k, mesh.element_count());
    for (ElementId t : elements(mesh))
        element(mesh.simplex(t), groups.element_tag(mesh.label(t)));
    sink.line("$EndElements");
    return out;
}

std::string write_gmsh_41(const Mesh& mesh, std::span<const Point> positions, bool binary,
                          const gmsh::PhysicalGroups& groups,
                          const std::vector<std::pair<Simplex, int>>& faces) {
    const int d = mesh.topological_dimension();
    std::string out;
    out.reserve(mesh.vertex_count() * (binary ? 32 : 64) +
                mesh.element_count() * (binary ? 40 : 48));
    Sink sink(out, binary);
    write_header(sink, "4.1", groups);

    // entities carry the physical tags, so elements and faces are grouped by label, one entity
    // per distinct label (stable sorts keep the mesh's order within a group)
    std::vector<std::pair<int, ElementId>> by_label;
    by_label.reserve(mesh.element_count());
    for (ElementId t : elements(mesh))
        by_label.emplace_back(mesh.label(t), t);
    std::stable_sort(by_label.begin(), by_label.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
    std::vector<std::pair<Simplex, int>> faces_by_label = faces;
    std::stable_sort(faces_by_label.begin(), faces_by_label.end(),
                     [](const auto& a, const auto& b) { return a.second < b.second; });
    // [begin, end) runs of equal labels
    auto runs = [](const auto& items, auto label_of) {
        std::vector<std::pair<std::size_t, std::size_t>> result;
        for (std::size_t i = 0; i < items.size();) {
            std::size_t j = i + 1;
            while (j < items.size() && label_of(items[j]) == label_of(items[i]))
                ++j;
            result.emplace_back(i, j);
            i = j;
        }
        return result;
    };
    const auto volumes = runs(by_label, [](const auto& x) { return x.first; });
    const auto surfaces = runs(faces_by_label, [](const auto& x) { return x.second; });

    // one bounding box for every entity: Gmsh only uses it for display hints
    Point low{0, 0, 0}, high{0, 0, 0};
    for (std::size_t v = 0; v < positions.size(); ++v)
        for (std::size_t c = 0; c < 3; ++c) {
            low[c] = v == 0 ? positions[v][c] : std::min(low[c], positions[v][c]);
            high[c] = v == 0 ? positions[v][c] : std::max(high[c], positions[v][c]);
        }
    // entity tags 1.. for the d-dimensional entities (one per label; the nodes live on the
    // first), and 1.. for the (d-1)-dimensional ones
    sink.line("$Entities");
    std::array<std::size_t, 4> counts{0, 0, 0, 0};
    counts[static_cast<std::size_t>(d)] = volumes.size();
    counts[static_cast<std::size_t>(d - 1)] = surfaces.size();
    for (std::size_t count : counts)
        sink.size(count);
    sink.end();
    auto entity = [&](std::size_t tag, int group) {
        sink.int32(static_cast<std::int64_t>(tag));
        sink.point(low);
        sink.point(high);
        sink.size(1);  // one physical tag
        sink.int32(group);
        sink.size(0);  // no bounding entities
        sink.end();
    };
    // entities are listed by dimension: the faces' before the elements'
    for (std::size_t i = 0; i < surfaces.size(); ++i)
        entity(i + 1, groups.face_tag(faces_by_label[surfaces[i].first].second));
    for (std::size_t i = 0; i < volumes.size(); ++i)
        entity(i + 1, groups.element_tag(by_label[volumes[i].first].first));
    sink.line("$EndEntities");

    sink.line("$Nodes");
    const std::size_t n = mesh.vertex_count();
    sink.size(1);
    sink.size(n);
    sink.size(n ? 1 : 0);
    sink.size(n);
    sink.end();
    sink.int32(d);
    sink.int32(1);
    sink.int32(0);
    sink.size(n);
    sink.end();
    for (std::size_t v = 0; v < n; ++v) {
        sink.size(v + 1);
        sink.end();
    }
    for (const Point& p : positions) {
        sink.point(p);
        sink.end();
    }
    sink.line("$EndNodes");

    sink.line("$Elements");
    const std::size_t total = faces.size() + mesh.element_count();
    sink.size(surfaces.size() + volumes.size());
    sink.size(total);
    sink.size(total ? 1 : 0);
    sink.size(total);
    sink.end();
    std::size_t tag = 0;
    auto block = [&](int dimension, std::size_t entity_tag, int vertices, std::size_t size) {
        sink.int32(dimension);
        sink.int32(static_cast<std::int64_t>(entity_tag));
        sink.int32(gmsh_type(vertices));
        sink.size(size);
        sink.end();
    };
    auto simplex_line = [&](const Simplex& s) {
        sink.size(++tag);
        const auto v = oriented_vertices(s);
        for (int j = 0; j < s.count(); ++j)
            sink.size(static_cast<std::size_t>(v[static_cast<std::size_t>(j)]) + 1);
        sink.end();
    };
    for (std::size_t i = 0; i < surfaces.size(); ++i) {
        const auto [begin, end] = surfaces[i];
        block(d - 1, i + 1, d, end - begin);
        for (std::size_t f = begin; f < end; ++f)
            simplex_line(faces_by_label[f].first);
    }
    for (std::size_t i = 0; i < volumes.size(); ++i) {
        const auto [begin, end] = volumes[i];
        block(d, i + 1, d + 1, end - begin);
        for (std::size_t e = begin; e < end; ++e)
            simplex_line(mesh.simplex(by_label[e].second));
    }
    sink.line("$EndElements");
    return out;
}

}  // namespace

std::string write_gmsh(const Mesh& mesh, const WriteOptions& options) {
    if (options.gmsh_version != 22 && options.gmsh_version != 41)
        throw OutputError("Gmsh version must be 22 or 41, not " +
                          std::to_string(options.gmsh_version));
    const bool binary = options.encoding == Encoding::binary;
    const gmsh::PhysicalGroups groups(mesh);
    const auto faces = sorted_face_labels(mesh);
    const std::span<const Point> positions = chosen_positions(mesh, options);
    return options.gmsh_version == 22 ? write_gmsh_22(mesh, positions, binary, groups, faces)
                                      : write_gmsh_41(mesh, positions, binary, groups, faces);
}

}  // namespace sxk::io
