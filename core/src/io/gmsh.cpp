// Gmsh .msh, ASCII versions 2.2 and 4.1.
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
// of the element; 4.1: the first physical tag of its entity), 0 when it has none. Elements one
// dimension below the mesh (triangles of a tetrahedral mesh, lines of a triangle mesh) become
// labelled faces; points and lower elements are checked and dropped. Node tags may be any
// positive numbers, in any order. Gmsh always stores x y z: a triangle mesh whose z are all 0 is
// planar (ambient dimension 2).
//
// Sections that carry no connectivity ($Comments, $NodeData, ...) are skipped; an unknown section
// is an error, so a misspelt $Elemnts does not go unnoticed. $PhysicalNames is read for its count
// and entries (dimension 0..3, tag, quoted name), which are checked, and then dropped.
#include <algorithm>
#include <array>
#include <climits>
#include <span>
#include <unordered_map>

#include "../fresh_array.hpp"
#include "formats.hpp"
#include "raw_mesh.hpp"
#include "text.hpp"
#include "writing.hpp"

namespace sxk::io {

namespace {

constexpr std::array<std::string_view, 10> skipped_sections{
    "$Comments",         "$NodeData",           "$ElementData",
    "$ElementNodeData",  "$Periodic",           "$GhostElements",
    "$Parametrizations", "$InterpolationScheme", "$PartitionedEntities",
    "$NodeGroups"};

// Vertices per element for the types a simplicial mesh can hold; 0 for the others.
int type_size(std::int64_t type) {
    switch (type) {
        case 15:
            return 1;  // point
        case 1:
            return 2;  // line
        case 2:
            return 3;  // triangle
        case 4:
            return 4;  // tetrahedron
        default:
            return 0;
    }
}

[[noreturn]] void unsupported_type(const Cursor& in, std::int64_t type) {
    in.fail("element type " + std::to_string(type) +
            " is not supported (simplexes only: 15 point, 1 line, 2 triangle, 4 tetrahedron)");
}

// Node tags -> vertex ids. Tags are usually 1..N, so a vector does; sparse tags go to a map.
class NodeMap {
public:
    void build(std::span<const std::int64_t> tags, std::span<const std::size_t> lines,
               const Cursor& in) {
        std::int64_t largest = 0;
        for (std::int64_t tag : tags)
            largest = std::max(largest, tag);
        m_dense = largest <= 2 * static_cast<std::int64_t>(tags.size()) + 1024;
        if (m_dense)
            m_vector.assign(static_cast<std::size_t>(largest) + 1, invalid_id);
        else
            m_map.reserve(tags.size());
        for (std::size_t i = 0; i < tags.size(); ++i) {
            bool fresh = true;
            if (m_dense) {
                VertexId& slot = m_vector[static_cast<std::size_t>(tags[i])];
                fresh = slot == invalid_id;
                slot = static_cast<VertexId>(i);
            } else {
                fresh = m_map.emplace(tags[i], static_cast<VertexId>(i)).second;
            }
            if (!fresh)
                in.fail_at(lines[i], "node " + std::to_string(tags[i]) + " is defined twice");
        }
    }
    VertexId find(std::int64_t tag) const {
        if (m_dense)
            return tag > 0 && tag < static_cast<std::int64_t>(m_vector.size())
                       ? m_vector[static_cast<std::size_t>(tag)]
                       : invalid_id;
        const auto at = m_map.find(tag);
        return at == m_map.end() ? invalid_id : at->second;
    }

private:
    bool m_dense = true;
    std::vector<VertexId> m_vector;
    std::unordered_map<std::int64_t, VertexId> m_map;
};

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
        if (file_type == "1")
            m_in.fail("binary Gmsh files are not supported");
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
                read_physical_names();
            } else if (section == "$Entities" && m_version == 4) {
                if (m_have_entities)
                    m_in.fail("section $Entities appears twice");
                m_have_entities = true;
                read_entities();
            } else if (std::find(skipped_sections.begin(), skipped_sections.end(), section) !=
                       skipped_sections.end()) {
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
        return m_raw;
    }

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

    // "$PhysicalNames / count / dimension tag "name" (one per line) / $EndPhysicalNames". The
    // names label nothing the kernel keeps, but the count is checked like every other count
    // (docs/formats.md): one entry per line because a quoted name may hold blanks.
    void read_physical_names() {
        m_section = "$PhysicalNames";
        if (!m_in.next_line())
            m_in.fail("truncated file: expected number of physical names");
        const std::int64_t count =
            m_in.to_integer(m_in.need_in_line("number of physical names"), "number of physical names", 0,
                            INT64_MAX);
        if (!m_in.line_done())
            m_in.fail("unexpected " + quote(m_in.next_in_line()) + " after the number of physical names");
        for (std::int64_t i = 0; i < count; ++i) {
            if (!m_in.next_line())
                m_in.fail("truncated file: expected $EndPhysicalNames");
            const std::string_view first = m_in.need_in_line("physical dimension");
            if (first[0] == '$')
                m_in.fail("section $PhysicalNames declares " + std::to_string(count) + " names but has " +
                          std::to_string(i));
            m_in.to_integer(first, "physical dimension", 0, 3);
            m_in.to_integer(m_in.need_in_line("physical tag"), "physical tag", INT64_MIN, INT64_MAX);
            // "name", possibly several tokens: from a token starting with a quote to one ending with one
            std::string_view word = m_in.need_in_line("physical name");
            if (word[0] != '"')
                m_in.fail("expected a quoted physical name, found " + quote(word));
            word.remove_prefix(1);
            while (word.empty() || word.back() != '"') {
                word = m_in.next_in_line();
                if (word.empty())
                    m_in.fail("physical name without its closing '\"'");
            }
            if (!m_in.line_done())
                m_in.fail("unexpected " + quote(m_in.next_in_line()) + " after the physical name");
        }
        end_section("$EndPhysicalNames", "names", count);
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
        m_nodes.build(m_raw.point_numbers, m_raw.point_lines, m_in);
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
        m_nodes.build(m_raw.point_numbers, m_raw.point_lines, m_in);
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

    struct EntityHash {
        std::size_t operator()(const std::pair<int, std::int64_t>& key) const {
            // unsigned: entity tags may be anything, and signed overflow is undefined
            return std::hash<std::uint64_t>()(static_cast<std::uint64_t>(key.second) * 4 +
                                              static_cast<std::uint64_t>(key.first));
        }
    };

    Cursor m_in;
    std::string_view m_text;
    RawMesh m_raw;
    int m_version = 0;
    bool m_have_nodes = false, m_have_elements = false, m_have_entities = false;
    const char* m_section = "";
    NodeMap m_nodes;
    std::unordered_map<std::pair<int, std::int64_t>, int, EntityHash> m_entities;
};

}  // namespace

Mesh read_gmsh(std::string_view text, const std::string& name, const ReadOptions& options,
               ReadReport* report) {
    Reader reader(check_text(text, name), name);
    return build_mesh(reader.read(), name, options, report);
}

std::string write_gmsh(const Mesh& mesh, const WriteOptions& options) {
    if (options.gmsh_version != 22 && options.gmsh_version != 41)
        throw OutputError("Gmsh version must be 22 or 41, not " +
                          std::to_string(options.gmsh_version));
    const std::span<const Point> positions = chosen_positions(mesh, options);
    const int d = mesh.topological_dimension();
    const auto faces = sorted_face_labels(mesh);
    std::string out;
    out.reserve(mesh.vertex_count() * 64 + mesh.element_count() * 48);

    if (options.gmsh_version == 22) {
        out += "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n";
        append_number(out, mesh.vertex_count());
        out += '\n';
        for (std::size_t v = 0; v < positions.size(); ++v) {
            append_number(out, v + 1);
            out += ' ';
            append_xyz(out, positions[v]);
            out += '\n';
        }
        out += "$EndNodes\n$Elements\n";
        append_number(out, faces.size() + mesh.element_count());
        out += '\n';
        std::size_t tag = 0;
        // "tag type 2 physical elementary nodes": the label is both tags, so Gmsh shows it
        // whichever it colours by
        auto element = [&](const Simplex& s, int label) {
            append_number(out, ++tag);
            out += s.count() == 4 ? " 4 2 " : s.count() == 3 ? " 2 2 " : " 1 2 ";
            append_number(out, label);
            out += ' ';
            append_number(out, label);
            const auto v = oriented_vertices(s);
            for (int j = 0; j < s.count(); ++j) {
                out += ' ';
                append_number(out, v[static_cast<std::size_t>(j)] + 1);
            }
            out += '\n';
        };
        for (const auto& [face, label] : faces)
            element(face, label);
        for (ElementId t : elements(mesh))
            element(mesh.simplex(t), mesh.label(t));
        out += "$EndElements\n";
        return out;
    }

    // 4.1: entities carry the physical tags, so elements and faces are grouped by label, one
    // entity per distinct label (stable sorts keep the mesh's order within a group)
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
    // entity tags 1.. for the d-dimensional entities (at least one: the nodes live on it), and
    // 1.. for the (d-1)-dimensional ones
    const std::size_t entity_count = std::max<std::size_t>(volumes.size(), 1);
    out += "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Entities\n0 ";
    std::array<std::size_t, 4> counts{0, 0, 0, 0};
    counts[static_cast<std::size_t>(d)] = entity_count;
    counts[static_cast<std::size_t>(d - 1)] = surfaces.size();
    out += std::to_string(counts[1]) + ' ' + std::to_string(counts[2]) + ' ' +
           std::to_string(counts[3]) + '\n';
    auto entity = [&](std::size_t tag, int label) {
        append_number(out, tag);
        out += ' ';
        append_xyz(out, low);
        out += ' ';
        append_xyz(out, high);
        if (label != 0) {
            out += " 1 ";
            append_number(out, label);
        } else {
            out += " 0";
        }
        out += " 0\n";
    };
    // entities are listed by dimension: the faces' before the elements'
    for (std::size_t i = 0; i < surfaces.size(); ++i)
        entity(i + 1, faces_by_label[surfaces[i].first].second);
    for (std::size_t i = 0; i < entity_count; ++i)
        entity(i + 1, volumes.empty() ? 0 : by_label[volumes[i].first].first);
    out += "$EndEntities\n$Nodes\n1 ";
    append_number(out, mesh.vertex_count());
    out += mesh.vertex_count() ? " 1 " : " 0 ";
    append_number(out, mesh.vertex_count());
    out += '\n';
    append_number(out, d);
    out += " 1 0 ";
    append_number(out, mesh.vertex_count());
    out += '\n';
    for (std::size_t v = 0; v < positions.size(); ++v) {
        append_number(out, v + 1);
        out += '\n';
    }
    for (const Point& p : positions) {
        append_xyz(out, p);
        out += '\n';
    }
    out += "$EndNodes\n$Elements\n";
    const std::size_t total = faces.size() + mesh.element_count();
    append_number(out, surfaces.size() + volumes.size());
    out += ' ';
    append_number(out, total);
    out += total ? " 1 " : " 0 ";
    append_number(out, total);
    out += '\n';
    std::size_t tag = 0;
    auto block = [&](int dimension, std::size_t entity_tag, const char* type, std::size_t size) {
        append_number(out, dimension);
        out += ' ';
        append_number(out, entity_tag);
        out += type;
        append_number(out, size);
        out += '\n';
    };
    auto simplex_line = [&](const Simplex& s) {
        append_number(out, ++tag);
        const auto v = oriented_vertices(s);
        for (int j = 0; j < s.count(); ++j) {
            out += ' ';
            append_number(out, v[static_cast<std::size_t>(j)] + 1);
        }
        out += '\n';
    };
    for (std::size_t i = 0; i < surfaces.size(); ++i) {
        const auto [begin, end] = surfaces[i];
        block(d - 1, i + 1, d == 3 ? " 2 " : " 1 ", end - begin);
        for (std::size_t f = begin; f < end; ++f)
            simplex_line(faces_by_label[f].first);
    }
    for (std::size_t i = 0; i < volumes.size(); ++i) {
        const auto [begin, end] = volumes[i];
        block(d, i + 1, d == 3 ? " 4 " : " 2 ", end - begin);
        for (std::size_t e = begin; e < end; ++e)
            simplex_line(mesh.simplex(by_label[e].second));
    }
    out += "$EndElements\n";
    return out;
}

}  // namespace sxk::io
