// Medit .mesh (ASCII, as written by Medit, MMG, CGAL, TetGen -g, Gmsh): keyword sections
//
//   MeshVersionFormatted 2        (1..4; the ASCII text is the same for all)
//   Dimension 3                   (2: vertices have x y, and no tetrahedra)
//   Vertices  N   then N x "x y [z] ref"
//   Edges     N   then N x "a b ref"          1-based vertex indices
//   Triangles N   then N x "a b c ref"
//   Tetrahedra N  then N x "a b c d ref"
//   End
//
// The top-dimensional cells are the elements and their ref is the element label; the cells one
// dimension lower (Triangles of a tetrahedral mesh, Edges of a triangle mesh) are labelled faces
// (Mesh::face_labels); a face listed more than once is one labelled face, its first ref kept
// (ReadReport::label_conflicts counts repeats with another ref). Vertex refs are ignored, and so
// are sections that only annotate (Corners, Ridges, Normals, ...). Non-simplicial cells are
// refused.
#include <array>
#include <cctype>
#include <climits>
#include <cstring>

#include "formats.hpp"
#include "raw_mesh.hpp"
#include "text.hpp"
#include "writing.hpp"

namespace sxk::io {

namespace {

// Sections read and thrown away: name, numbers per record (or -1: the dimension).
struct Skipped {
    const char* name;
    int numbers;
};
constexpr std::array<Skipped, 13> skipped_sections{{
    {"Corners", 1},
    {"RequiredVertices", 1},
    {"Ridges", 1},
    {"RequiredEdges", 1},
    {"RequiredTriangles", 1},
    {"RequiredTetrahedra", 1},
    {"Normals", -1},
    {"Tangents", -1},
    {"NormalAtVertices", 2},
    {"NormalAtTriangleVertices", 3},
    {"NormalAtQuadrilateralVertices", 3},
    {"TangentAtVertices", 2},
    {"TangentAtEdgeVertices", 3},
}};

constexpr std::array<const char*, 14> unsupported_sections{
    "Quadrilaterals", "Hexahedra",    "Prisms",           "Pyramids",    "EdgesP2",
    "TrianglesP2",    "TetrahedraP2", "QuadrilateralsQ2", "HexahedraQ2", "TrianglesP3",
    "TetrahedraP3",   "Polygons",     "Polyhedra",        "Pentahedra"};

bool is_keyword(std::string_view token) {
    // every token of a section goes through here: numbers leave at the first character
    if (token.empty() || !std::isupper(static_cast<unsigned char>(token[0])))
        return false;
    if (token == "End" || token == "Vertices" || token == "Edges" || token == "Triangles" ||
        token == "Tetrahedra" || token == "Dimension" || token == "MeshVersionFormatted")
        return true;
    for (const Skipped& s : skipped_sections)
        if (token == s.name)
            return true;
    for (const char* s : unsupported_sections)
        if (token == s)
            return true;
    return false;
}

// Reads the records of one section, noticing when the section is shorter or longer than it
// says (the next keyword arrives early, or numbers go on after the last record).
class Section {
public:
    Section(Cursor& in, const char* name) : m_in(in), m_name(name) {
        m_declared = in.to_integer(in.need("number of entries"), "number of entries", 0,
                                   static_cast<std::int64_t>(invalid_id) - 1);
    }
    std::int64_t declared() const { return m_declared; }

    std::string_view need(std::int64_t entry, const char* what) {
        const std::string_view token = m_in.need(what);
        if (is_keyword(token))
            m_in.fail("section " + std::string(m_name) + " declares " + std::to_string(m_declared) +
                      " entries but has " + std::to_string(entry));
        return token;
    }
    // Numbers after the last record are surplus entries; a word is the next section's
    // business (perhaps an unknown keyword).
    void finish() {
        const std::string_view next = m_in.peek();
        if (!next.empty() && (std::isdigit(static_cast<unsigned char>(next[0])) || next[0] == '-' ||
                              next[0] == '+' || next[0] == '.')) {
            m_in.next();
            m_in.fail("section " + std::string(m_name) + " has more than the " +
                      std::to_string(m_declared) + " entries it declares");
        }
    }

private:
    Cursor& m_in;
    const char* m_name;
    std::int64_t m_declared = 0;
};

void read_cells(Cursor& in, const char* name, CellList& cells, std::size_t vertex_count,
                std::size_t bytes_left) {
    Section section(in, name);
    const std::size_t k = static_cast<std::size_t>(cells.size);
    const std::size_t n = plausible_count(section.declared(), bytes_left, 2 * (k + 1));
    cells.reserve(n);
    for (std::int64_t e = 0; e < section.declared(); ++e) {
        for (std::size_t j = 0; j < k; ++j) {
            const std::string_view token = section.need(e, "vertex index");
            const std::int64_t index = in.to_integer(token, "vertex index");
            if (index == 0)
                in.fail("vertex index 0: indices start at 1");
            if (index < 0 || index > static_cast<std::int64_t>(vertex_count))
                in.fail("vertex index " + std::to_string(index) + " out of range (1.." +
                        std::to_string(vertex_count) + ")");
            cells.vertices.push_back(static_cast<VertexId>(index - 1));
            if (j == 0)
                cells.lines.push_back(in.line());
        }
        cells.labels.push_back(static_cast<int>(
            in.to_integer(section.need(e, "reference"), "reference", INT_MIN, INT_MAX)));
    }
    section.finish();
}

}  // namespace

Mesh read_medit(std::string_view text, const std::string& name, const ReadOptions& options,
                ReadReport* report) {
    Cursor in(text, name, '#');
    RawMesh raw;
    raw.vertex_file = raw.edges.file = raw.triangles.file = raw.tetrahedra.file = name;
    raw.vertex_base = 1;
    // CGAL's output_to_medit lists every boundary triangle twice, once per orientation, each
    // with the subdomain on that side (the same one on the outer boundary): one labelled face
    raw.edges.repeats_are_one_face = raw.triangles.repeats_are_one_face = true;
    const char* const text_end = text.data() + text.size();
    auto bytes_left = [&] { return static_cast<std::size_t>(text_end - in.peek().data()); };

    const std::string_view first = in.need("MeshVersionFormatted");
    if (first != "MeshVersionFormatted")
        in.fail("expected MeshVersionFormatted, found " + quote(first));
    in.to_integer(in.need("format version"), "format version", 1, 4);

    int dimension = 0;
    bool have_vertices = false, have[5] = {false, false, false, false, false};
    for (;;) {
        const std::string_view keyword = in.need("End");
        if (keyword == "End")
            break;
        if (keyword == "Dimension") {
            if (dimension != 0)
                in.fail("Dimension appears twice");
            const std::string_view token = in.need("dimension");
            const std::int64_t value = in.to_integer(token, "dimension");
            if (value != 2 && value != 3)
                in.fail("Dimension must be 2 or 3, found " + quote(token));
            dimension = static_cast<int>(value);
            raw.ambient = dimension;
        } else if (keyword == "Vertices") {
            if (dimension == 0)
                in.fail("Vertices before Dimension");
            if (have_vertices)
                in.fail("section Vertices appears twice");
            have_vertices = true;
            Section section(in, "Vertices");
            const std::size_t n = plausible_count(section.declared(), bytes_left(), 2 * 4);
            raw.reserve_points(n);
            static constexpr const char* axes[] = {"x coordinate", "y coordinate", "z coordinate"};
            for (std::int64_t v = 0; v < section.declared(); ++v) {
                Point p{0, 0, 0};
                for (int c = 0; c < dimension; ++c) {
                    p[static_cast<std::size_t>(c)] =
                        in.to_double(section.need(v, axes[c]), axes[c]);
                    if (c == 0)
                        raw.point_lines.push_back(in.line());
                }
                in.to_integer(section.need(v, "reference"), "reference", INT_MIN, INT_MAX);
                raw.points.push_back(p);
            }
            section.finish();
        } else if (keyword == "Edges" || keyword == "Triangles" || keyword == "Tetrahedra") {
            CellList& cells = keyword == "Edges"       ? raw.edges
                              : keyword == "Triangles" ? raw.triangles
                                                       : raw.tetrahedra;
            if (!have_vertices)
                in.fail(std::string(keyword) + " before Vertices");
            if (have[cells.size])
                in.fail("section " + std::string(keyword) + " appears twice");
            have[cells.size] = true;
            if (cells.size == 4 && dimension == 2)
                in.fail("Tetrahedra in a Dimension 2 file");
            const std::string section_name(keyword);
            read_cells(in, section_name.c_str(), cells, raw.points.size(), bytes_left());
        } else {
            bool known = false;
            for (const Skipped& s : skipped_sections) {
                if (keyword != s.name)
                    continue;
                known = true;
                if (dimension == 0)
                    in.fail(std::string(s.name) + " before Dimension");
                Section section(in, s.name);
                const int numbers = s.numbers < 0 ? dimension : s.numbers;
                for (std::int64_t r = 0; r < section.declared(); ++r)
                    for (int j = 0; j < numbers; ++j)
                        in.to_double(section.need(r, "number"), "number");
                section.finish();
            }
            if (!known) {
                for (const char* s : unsupported_sections)
                    if (keyword == s)
                        in.fail(std::string(s) + " are not supported: simplicial meshes only");
                in.fail("unknown keyword " + quote(keyword));
            }
        }
    }
    if (!in.at_end()) {
        in.next();
        in.fail("unexpected data after End");
    }
    if (dimension == 0)
        in.fail("missing Dimension");
    return build_mesh(raw, name, options, report);
}

std::string write_medit(const Mesh& mesh, const WriteOptions& options) {
    const std::span<const Point> positions = chosen_positions(mesh, options);
    const int dimension = mesh.ambient_dimension();
    const int d = mesh.topological_dimension();
    std::string out;
    out.reserve(mesh.vertex_count() * 64 + mesh.element_count() * 40);
    out += "MeshVersionFormatted 2\n# written by simplexkit\nDimension ";
    append_number(out, dimension);
    out += "\n\nVertices\n";
    append_number(out, mesh.vertex_count());
    out += '\n';
    for (const Point& p : positions) {
        for (int c = 0; c < dimension; ++c) {
            append_number(out, p[static_cast<std::size_t>(c)]);
            out += ' ';
        }
        out += "0\n";
    }

    const auto faces = sorted_face_labels(mesh);
    if (!faces.empty()) {
        out += d == 3 ? "\nTriangles\n" : "\nEdges\n";
        append_number(out, faces.size());
        out += '\n';
        for (const auto& [face, label] : faces) {
            const auto v = oriented_vertices(face);
            for (int j = 0; j < d; ++j) {
                append_number(out, v[static_cast<std::size_t>(j)] + 1);
                out += ' ';
            }
            append_number(out, label);
            out += '\n';
        }
    }

    out += d == 3 ? "\nTetrahedra\n" : "\nTriangles\n";
    append_number(out, mesh.element_count());
    out += '\n';
    for (ElementId t : elements(mesh)) {
        const auto v = oriented_vertices(mesh.simplex(t));
        for (int j = 0; j <= d; ++j) {
            append_number(out, v[static_cast<std::size_t>(j)] + 1);
            out += ' ';
        }
        append_number(out, mesh.label(t));
        out += '\n';
    }
    out += "\nEnd\n";
    return out;
}

}  // namespace sxk::io
