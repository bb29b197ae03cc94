// STL (stereolithography): a triangle surface, each triangle listed with its own three corners.
//
// ASCII                                   binary (little-endian)
//   solid NAME                              80 bytes   header (anything, often "solid ...")
//     facet normal nx ny nz                 uint32     number of triangles n
//       outer loop                          n x 50 bytes: normal and three corners, 12 float32,
//         vertex x y z      (three times)               then a uint16 attribute
//       endloop
//     endfacet                              so the file is exactly 84 + 50 n bytes long
//   endsolid NAME
//
// Reading. Which of the two a file is: binary when its size is 84 + 50 n for the n in bytes
// 80..83, otherwise ASCII when it is all text; anything else is a binary file of the wrong size
// (or, when it starts with "solid" and its count could not be a binary file's, an ASCII file with
// a byte that cannot be text).
// The size test alone cannot mistake a text file for binary: text bytes are at least 0x09, so
// the n of a text file is at least 0x09000000 and its binary size over 7 GB, beyond the 1 GiB
// any input may have (max_input_bytes). Headers that start with "solid" (many binary writers
// put one there) therefore do not matter. An ASCII file may hold several solids, one after the
// other; names after solid/endsolid and the normals are read and ignored: a triangle's
// orientation is the order of its corners.
//
// STL has no vertex list: corners with exactly equal coordinates (-0 and +0 are equal) are
// welded into one vertex, numbered from 1 in order of first appearance (the line of that
// appearance is the vertex's line). A triangle two of whose corners weld into one vertex is
// dropped (and a vertex only it brought in with it): such zero-area slivers are common in STL
// files from CAD exporters, carry no surface, and cannot be an element (build_mesh would refuse
// the whole file for one). Triangles are numbered from 1 in file order, dropped ones included,
// in every message. Messages name the ASCII line; binary files have no lines, so there the line
// is 0 and the message names the triangle ("triangle 7: coordinate is not finite").
// Always x y z: a mesh whose z are all 0 is planar (RawMesh::ambient_from_z). No labels.
//
// Writing: the triangle surface (writing.hpp: a tetrahedral mesh gives its boundary, outward).
// Encoding::standard and ::binary write binary STL, whose float32 coordinates round what the
// mesh holds (a coordinate beyond float32's range is refused: it would be written as infinity);
// Encoding::ascii writes shortest round-trip doubles, which read back exactly. Normals are the
// unit normals of the oriented triangles (0 0 0 for a triangle of zero area).
#include <bit>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <limits>
#include <unordered_map>

#include "binary_numbers.hpp"
#include "formats.hpp"
#include "raw_mesh.hpp"
#include "text.hpp"
#include "writing.hpp"

namespace sxk::io {

namespace {

constexpr std::size_t binary_header_bytes = 84;  // 80 bytes of header, the uint32 count
constexpr std::size_t binary_triangle_bytes = 50;

struct PointBitsHash {
    std::size_t operator()(const Point& p) const {
        std::uint64_t h = 0;
        for (double c : p)
            h = (h ^ std::bit_cast<std::uint64_t>(c)) * 0x9e3779b97f4a7c15ULL;
        return static_cast<std::size_t>(h ^ (h >> 29));
    }
};

// The triangles dropped as slivers (ReadReport::dropped_triangles).
struct Slivers {
    std::size_t count = 0;
    std::string first;
};

// Turns the corners of each triangle into welded vertex ids, and the triangles into cells.
class Welder {
public:
    Welder(RawMesh& raw, Slivers& slivers) : m_raw(raw), m_slivers(slivers) {}

    void reserve(std::size_t triangles) {
        m_ids.reserve(triangles / 2 + 3);  // a closed surface has about half as many vertices
        m_raw.triangles.reserve(triangles, true);
    }

    // The triangle numbered `number` in the file, on line `line` with its corners on `lines`
    // (all 0 in binary files).
    void add(const std::array<Point, 3>& corners, std::int64_t number, std::size_t line,
             const std::array<std::size_t, 3>& lines) {
        std::array<VertexId, 3> ids{};
        std::array<Point, 3> fresh{};  // the keys this triangle added, if it must be undone
        int added = 0;
        for (std::size_t i = 0; i < 3; ++i) {
            Point key = corners[i];
            for (double& c : key)
                c += 0.0;  // -0.0 + 0.0 is +0.0: one key for equal coordinates
            const auto next = static_cast<VertexId>(m_raw.points.size());
            const auto [at, inserted] = m_ids.emplace(key, next);
            if (inserted) {
                if (next == invalid_id)
                    throw InputError(m_raw.vertex_file, lines[i], "too many vertices");
                m_raw.points.push_back(corners[i]);
                m_raw.point_lines.push_back(lines[i]);
                fresh[static_cast<std::size_t>(added++)] = key;
            }
            ids[i] = at->second;
        }
        if (ids[0] == ids[1] || ids[1] == ids[2] || ids[0] == ids[2]) {
            // a sliver (see the top of this file): its new vertices go with it, so that no
            // vertex is left in no element
            for (int i = 0; i < added; ++i) {
                m_ids.erase(fresh[static_cast<std::size_t>(i)]);
                m_raw.points.pop_back();
                m_raw.point_lines.pop_back();
            }
            if (m_slivers.count++ == 0)
                m_slivers.first = m_raw.vertex_file + ":" + std::to_string(line) + ": triangle " +
                                  std::to_string(number) + " has two corners at one position";
            return;
        }
        CellList& cells = m_raw.triangles;
        cells.vertices.insert(cells.vertices.end(), ids.begin(), ids.end());
        cells.labels.push_back(0);
        cells.lines.push_back(line);
        cells.numbers.push_back(number);
    }

private:
    RawMesh& m_raw;
    Slivers& m_slivers;
    std::unordered_map<Point, VertexId, PointBitsHash> m_ids;
};

RawMesh raw_for(const std::string& name) {
    RawMesh raw;
    raw.vertex_file = raw.triangles.file = name;
    raw.vertex_base = 1;
    raw.ambient_from_z = true;
    return raw;
}

void read_binary(std::string_view bytes, const std::string& name, RawMesh& raw, Slivers& slivers) {
    ByteCursor in(bytes);
    in.take(80);
    const std::uint32_t count = load_number<std::uint32_t>(in.take(4));
    Welder welder(raw, slivers);
    welder.reserve(count);  // the caller checked that the file holds `count` triangles
    for (std::uint32_t t = 0; t < count; ++t) {
        const char* record = in.take(binary_triangle_bytes);
        std::array<Point, 3> corners{};
        for (std::size_t i = 0; i < 3; ++i)
            for (std::size_t c = 0; c < 3; ++c) {
                const float value = load_number<float>(record + 12 * (i + 1) + 4 * c);
                if (!std::isfinite(value))
                    throw InputError(name, 0,
                                     "triangle " + std::to_string(t + 1) +
                                         ": coordinate is not finite");
                corners[i][c] = value;
            }
        welder.add(corners, static_cast<std::int64_t>(t) + 1, 0, {0, 0, 0});
    }
}

// The next line, which must be exactly these keywords.
void expect_line(Cursor& in, std::string_view first, std::string_view second = {}) {
    const std::string wanted = second.empty() ? std::string(first)
                                              : std::string(first) + " " + std::string(second);
    if (!in.next_line())
        in.fail("truncated file: expected " + wanted);
    for (std::string_view keyword : {first, second}) {
        if (keyword.empty())
            break;
        const std::string_view token = in.next_in_line();
        if (token != keyword)
            in.fail("expected " + wanted + ", found " +
                    (token.empty() ? std::string("the end of the line") : quote(token)));
    }
    if (!in.line_done())
        in.fail("unexpected value " + quote(in.next_in_line()) + " at the end of the line");
}

void read_ascii(std::string_view text, const std::string& name, RawMesh& raw, Slivers& slivers) {
    Cursor in(text, name, '\0');
    Welder welder(raw, slivers);
    std::int64_t facets = 0;
    static constexpr const char* axes[] = {"x coordinate", "y coordinate", "z coordinate"};
    while (in.next_line()) {
        const std::string_view solid = in.next_in_line();
        if (solid != "solid")
            in.fail("expected solid, found " + quote(solid));
        while (!in.line_done())  // the name
            in.next_in_line();
        for (;;) {
            if (!in.next_line())
                in.fail("truncated file: expected endsolid");
            const std::string_view keyword = in.next_in_line();
            if (keyword == "endsolid") {
                while (!in.line_done())
                    in.next_in_line();
                break;
            }
            if (keyword != "facet")
                in.fail("expected facet or endsolid, found " + quote(keyword));
            const std::string facet = "facet " + std::to_string(++facets);
            const std::size_t facet_line = in.line();
            if (const std::string_view normal = in.next_in_line(); normal != "normal")
                in.fail("expected normal, found " +
                        (normal.empty() ? std::string("the end of the line") : quote(normal)));
            // three components, not used: a writer's normal may even be nan for a sliver
            for (int c = 0; c < 3; ++c)
                in.need_in_line("normal component");
            if (!in.line_done())
                in.fail("unexpected value " + quote(in.next_in_line()) + " at the end of the line");
            expect_line(in, "outer", "loop");
            std::array<Point, 3> corners{};
            std::array<std::size_t, 3> lines{};
            std::size_t fourth_line = 0;
            int count = 0;
            for (;;) {
                if (!in.next_line())
                    in.fail("truncated file: expected vertex or endloop");
                const std::string_view corner = in.next_in_line();
                if (corner == "endloop") {
                    if (!in.line_done())
                        in.fail("unexpected value " + quote(in.next_in_line()) +
                                " at the end of the line");
                    break;
                }
                if (corner != "vertex")
                    in.fail("expected vertex or endloop, found " + quote(corner));
                Point p{};
                for (std::size_t c = 0; c < 3; ++c)
                    p[c] = in.to_double(in.need_in_line(axes[c]), axes[c]);
                if (!in.line_done())
                    in.fail("unexpected value " + quote(in.next_in_line()) +
                            " at the end of the line");
                if (count < 3) {
                    corners[static_cast<std::size_t>(count)] = p;
                    lines[static_cast<std::size_t>(count)] = in.line();
                } else if (count == 3) {
                    fourth_line = in.line();
                }
                ++count;
            }
            if (count > 3)
                in.fail_at(fourth_line, facet + " has " + std::to_string(count) +
                                            " vertices: only triangles are supported "
                                            "(triangulate the polygons first)");
            if (count < 3)
                in.fail(facet + " has " + std::to_string(count) + " vertices: a facet needs 3");
            expect_line(in, "endfacet");
            welder.add(corners, facets, facet_line, lines);
        }
    }
}

void append_float(std::string& out, double value) {
    append_little_endian(out, static_cast<float>(value));
}

// The unit normal of the triangle a b c as it is oriented, or 0 0 0 when it has no area (or
// its cross product overflows).
Point unit_normal(const Point& a, const Point& b, const Point& c) {
    const Point u{b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    const Point v{c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    const Point n{u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (!(length > 0) || !std::isfinite(length))
        return {0, 0, 0};
    return {n[0] / length + 0.0, n[1] / length + 0.0, n[2] / length + 0.0};  // no "-0"
}

std::string write_ascii(const Surface& surface, std::span<const Point> positions) {
    std::string out;
    out.reserve(surface.triangles.size() * 260 + 64);
    out += "solid simplexkit\n";
    for (const auto& t : surface.triangles) {
        const Point& a = positions[surface.vertices[t[0]]];
        const Point& b = positions[surface.vertices[t[1]]];
        const Point& c = positions[surface.vertices[t[2]]];
        out += "  facet normal ";
        append_xyz(out, unit_normal(a, b, c));
        out += "\n    outer loop\n";
        for (const Point* p : {&a, &b, &c}) {
            out += "      vertex ";
            append_xyz(out, *p);
            out += '\n';
        }
        out += "    endloop\n  endfacet\n";
    }
    out += "endsolid simplexkit\n";
    return out;
}

std::string write_binary(const Surface& surface, std::span<const Point> positions) {
    if (surface.triangles.size() > std::numeric_limits<std::uint32_t>::max())
        throw OutputError("binary STL holds at most 4294967295 triangles, the surface has " +
                          std::to_string(surface.triangles.size()));
    constexpr double largest = std::numeric_limits<float>::max();
    for (VertexId v : surface.vertices)
        for (double c : positions[v])
            if (std::abs(c) > largest) {
                std::string value;
                append_number(value, c);
                throw OutputError("coordinate " + value + " of vertex " + std::to_string(v) +
                                  " is beyond the range of binary STL's 32-bit floats (ASCII "
                                  "STL holds it)");
            }
    std::string out;
    out.reserve(binary_header_bytes + surface.triangles.size() * binary_triangle_bytes);
    // not "solid ...": that is how ASCII files start, and some readers look no further
    std::string header = "binary STL written by simplexkit";
    header.resize(80, ' ');
    out += header;
    append_little_endian(out, static_cast<std::uint32_t>(surface.triangles.size()));
    for (const auto& t : surface.triangles) {
        const Point& a = positions[surface.vertices[t[0]]];
        const Point& b = positions[surface.vertices[t[1]]];
        const Point& c = positions[surface.vertices[t[2]]];
        for (double n : unit_normal(a, b, c))
            append_float(out, n);
        for (const Point* p : {&a, &b, &c})
            for (double x : *p)
                append_float(out, x);
        append_little_endian(out, std::uint16_t{0});
    }
    return out;
}

}  // namespace

Mesh read_stl(std::string_view bytes, const std::string& name, const ReadOptions& options,
              ReadReport* report) {
    RawMesh raw = raw_for(name);
    Slivers slivers;
    // the mesh, with what was dropped said in the report
    auto built = [&] {
        Mesh mesh = build_mesh(raw, name, options, report);
        if (report) {
            report->dropped_triangles = slivers.count;
            report->first_dropped_triangle = slivers.first;
        }
        return mesh;
    };
    const std::size_t size = bytes.size();
    const std::uint64_t count =
        size >= binary_header_bytes ? load_number<std::uint32_t>(bytes.data() + 80) : 0;
    const std::uint64_t binary_size = binary_header_bytes + binary_triangle_bytes * count;
    if (size >= binary_header_bytes && size == binary_size) {
        read_binary(bytes, name, raw, slivers);
        return built();
    }
    std::string_view text;
    try {
        text = check_text(bytes, name);
    } catch (const InputError&) {
        // Not text. A binary file whose size does not match its count, unless it starts as an
        // ASCII file does and its count could not be a binary file's (see the top of this
        // file): then it is ASCII with a byte that cannot be text, and check_text says where.
        const std::size_t first = bytes.find_first_not_of(" \t\r\n\v\f");
        const std::string_view start =
            first == std::string_view::npos ? std::string_view{} : bytes.substr(first);
        const bool solid = start.substr(0, 5) == "solid" &&
                           (start.size() == 5 || std::isspace(static_cast<unsigned char>(start[5])));
        if (solid && (size < binary_header_bytes || binary_size > max_input_bytes))
            throw;
        if (size < binary_header_bytes)
            throw InputError(name, 0,
                             "truncated file: a binary STL starts with 84 bytes of header and "
                             "count, found " +
                                 std::to_string(size) + " bytes");
        throw InputError(name, 0,
                         std::string(size < binary_size ? "truncated file: " : "") +
                             "the header declares " + std::to_string(count) + " triangles (" +
                             std::to_string(binary_size) + " bytes), found " +
                             std::to_string(size) + " bytes");
    }
    read_ascii(text, name, raw, slivers);
    return built();
}

std::string write_stl(const Mesh& mesh, const WriteOptions& options) {
    const std::span<const Point> positions = chosen_positions(mesh, options);
    const Surface surface = triangle_surface(mesh);
    return options.encoding == Encoding::ascii ? write_ascii(surface, positions)
                                               : write_binary(surface, positions);
}

}  // namespace sxk::io
