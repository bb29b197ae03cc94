// Wavefront OBJ, the polygonal part: triangles only.
//
//   v x y z [w | r g b]     vertices, numbered 1, 2, ... in the order they appear
//   f a b c                 a face; each corner is "v", "v/vt", "v//vn" or "v/vt/vn", and a
//                           negative v counts back from the last vertex read so far (-1)
//   vt vn vp o g s usemtl mtllib l p     read and ignored
//
// Faces with more than three corners are refused with a message that says so (triangulate
// first); any other statement is an unknown keyword. OBJ holds no labels. Always x y z: a mesh
// whose z are all 0 is planar. Written tetrahedral meshes become their boundary.
#include <algorithm>
#include <array>

#include "../fresh_array.hpp"
#include "formats.hpp"
#include "raw_mesh.hpp"
#include "text.hpp"
#include "writing.hpp"

namespace sxk::io {

namespace {

constexpr std::array<std::string_view, 9> ignored_statements{"vt", "vn",     "vp",     "o", "g",
                                                             "s",  "usemtl", "mtllib", "l"};

}  // namespace

RawMesh parse_obj(std::string_view text, const std::string& name) {
    Cursor in(text, name, '#');
    RawMesh raw;
    raw.vertex_file = raw.triangles.file = name;
    raw.vertex_base = 1;
    raw.ambient_from_z = true;
    CellList& cells = raw.triangles;
    // OBJ numbers vertices over the whole file, so positive indices are checked once every vertex
    // is known (negative ones are resolved at once: they count back from the current vertex);
    // 1-based meanwhile
    std::vector<std::int64_t> indices;

    static constexpr const char* axes[] = {"x coordinate", "y coordinate", "z coordinate"};
    while (in.next_line()) {
        const std::string_view keyword = in.next_in_line();
        if (keyword == "v") {
            Point p{0, 0, 0};
            for (std::size_t c = 0; c < 3; ++c)
                p[c] = in.to_double(in.need_in_line(axes[c]), axes[c]);
            // a weight w, or the common r g b colour extension
            for (int extra = 0; extra < 4 && !in.line_done(); ++extra)
                in.to_double(in.next_in_line(), "vertex colour or weight");
            if (!in.line_done())
                in.fail("unexpected value " + quote(in.next_in_line()) + " after the vertex");
            raw.points.push_back(p);
            raw.point_lines.push_back(in.line());
        } else if (keyword == "f") {
            std::array<std::int64_t, 3> corner{};
            int corners = 0;
            for (std::string_view token = in.next_in_line(); !token.empty();
                 token = in.next_in_line()) {
                if (corners == 3) {
                    int total = 4;
                    while (!in.next_in_line().empty())
                        ++total;
                    in.fail(
                        "face has " + std::to_string(total) +
                        " vertices: only triangles are supported (triangulate the polygons first)");
                }
                // "v", "v/vt", "v//vn", "v/vt/vn": the vertex comes first; the others must be
                // numbers (or empty) but are not used
                const std::size_t slash = token.find('/');
                const std::string_view vertex = token.substr(0, slash);
                if (slash != std::string_view::npos) {
                    std::string_view rest = token.substr(slash + 1);
                    for (int part = 0; part < 2; ++part) {
                        const std::size_t next = rest.find('/');
                        const std::string_view number = rest.substr(0, next);
                        if (!number.empty())
                            in.to_integer(number, "texture or normal index");
                        if (next == std::string_view::npos)
                            break;
                        if (part == 1)
                            in.fail("malformed face corner " + quote(token));
                        rest = rest.substr(next + 1);
                    }
                }
                std::int64_t index = in.to_integer(vertex, "vertex index");
                if (index == 0)
                    in.fail("vertex index 0: indices start at 1");
                if (index < 0) {
                    const auto so_far = static_cast<std::int64_t>(raw.points.size());
                    if (-index > so_far)
                        in.fail("relative vertex index " + std::to_string(index) +
                                " out of range (" + std::to_string(so_far) + " vertices so far)");
                    index += so_far + 1;
                }
                corner[static_cast<std::size_t>(corners++)] = index;
            }
            if (corners < 3)
                in.fail("face has " + std::to_string(corners) + " vertices: a face needs 3");
            indices.insert(indices.end(), corner.begin(), corner.end());
            cells.lines.push_back(in.line());
            cells.labels.push_back(0);
        } else if (std::find(ignored_statements.begin(), ignored_statements.end(), keyword) !=
                   ignored_statements.end()) {
            while (!in.line_done())
                in.next_in_line();
        } else {
            in.fail("unknown keyword " + quote(keyword));
        }
    }
    const auto count = static_cast<std::int64_t>(raw.points.size());
    detail::reserve_fresh(cells.vertices, indices.size());
    for (std::size_t i = 0; i < indices.size(); ++i) {
        if (indices[i] > count)
            in.fail_at(cells.lines[i / 3], "vertex index " + std::to_string(indices[i]) +
                                               " out of range (1.." + std::to_string(count) + ")");
        cells.vertices.push_back(static_cast<VertexId>(indices[i] - 1));
    }
    return raw;
}

Mesh read_obj(std::string_view text, const std::string& name, const ReadOptions& options,
              ReadReport* report) {
    RawMesh raw = parse_obj(text, name);
    return build_mesh(raw, name, options, report);
}

std::string write_obj(const Mesh& mesh, const WriteOptions& options) {
    const std::span<const Point> positions = chosen_positions(mesh, options);
    const Surface surface = triangle_surface(mesh);
    std::string out;
    out.reserve(surface.vertices.size() * 60 + surface.triangles.size() * 24);
    out += "# written by simplexkit\n";
    for (VertexId v : surface.vertices) {
        const Point& p = positions[v];
        out += "v ";
        append_xyz(out, p);
        out += '\n';
    }
    for (const auto& t : surface.triangles) {
        out += 'f';
        for (VertexId v : t) {
            out += ' ';
            append_number(out, v + 1);
        }
        out += '\n';
    }
    return out;
}

}  // namespace sxk::io
