// OFF (Object File Format, as Geomview, CGAL and the CGAL data sets write it): triangles only.
//
//   OFF                     (or COFF, NOFF, CNOFF: vertices may carry colours/normals)
//   nv nf ne                (may stand on the OFF line; ne is ignored)
//   x y z                   nv lines
//   3 a b c [colour]        nf lines, 0-based vertex indices; colour: an index or RGB[A]
//
// Faces with more than three vertices are refused (the mesh is simplicial). OFF holds no labels.
// Always x y z: a mesh whose z are all 0 is planar (ambient dimension 2), and then the
// triangles must be counter-clockwise. Written tetrahedral meshes become their boundary.
#include "formats.hpp"
#include "raw_mesh.hpp"
#include "text.hpp"
#include "writing.hpp"

namespace sxk::io {

Mesh read_off(std::string_view text, const std::string& name, const ReadOptions& options,
              ReadReport* report) {
    Cursor in(text, name, '#');
    RawMesh raw;
    raw.vertex_file = raw.triangles.file = name;
    raw.vertex_base = 0;
    raw.ambient_from_z = true;

    if (!in.next_line())
        in.fail("truncated file: expected OFF");
    const std::string_view header = in.need_in_line("OFF");
    if (header != "OFF" && header != "COFF" && header != "NOFF" && header != "CNOFF") {
        if (header.size() >= 3 && header.substr(header.size() - 3) == "OFF")
            in.fail("unsupported OFF variant " + quote(header));
        in.fail("expected OFF, found " + quote(header));
    }
    const bool extras = header != "OFF";  // colours or normals after the coordinates
    if (in.line_done() && !in.next_line())
        in.fail("truncated file: expected the number of vertices");
    const std::int64_t nv =
        in.to_integer(in.need_in_line("number of vertices"), "number of vertices", 0,
                      static_cast<std::int64_t>(invalid_id) - 1);
    const std::int64_t nf = in.to_integer(in.need_in_line("number of faces"), "number of faces", 0,
                                          static_cast<std::int64_t>(invalid_id) - 1);
    if (!in.line_done())  // ignored, but a count all the same
        in.to_integer(in.next_in_line(), "number of edges", 0, INT64_MAX);
    if (!in.line_done())
        in.fail("unexpected value " + quote(in.next_in_line()) + " after the counts");

    const std::size_t reserve = plausible_count(nv, text.size(), 6);
    raw.reserve_points(reserve);
    static constexpr const char* axes[] = {"x coordinate", "y coordinate", "z coordinate"};
    for (std::int64_t v = 0; v < nv; ++v) {
        if (!in.next_line())
            in.fail("truncated file: the header declares " + std::to_string(nv) +
                    " vertices, found " + std::to_string(v));
        Point p{0, 0, 0};
        for (std::size_t c = 0; c < 3; ++c)
            p[c] = in.to_double(in.need_in_line(axes[c]), axes[c]);
        if (extras) {
            while (!in.line_done())
                in.to_double(in.next_in_line(), "colour or normal component");
        } else if (!in.line_done()) {
            in.fail("unexpected value " + quote(in.next_in_line()) +
                    " after the vertex coordinates");
        }
        raw.points.push_back(p);
        raw.point_lines.push_back(in.line());
    }

    CellList& cells = raw.triangles;
    const std::size_t faces = plausible_count(nf, text.size(), 8);
    cells.reserve(faces);
    for (std::int64_t f = 0; f < nf; ++f) {
        if (!in.next_line())
            in.fail("truncated file: the header declares " + std::to_string(nf) + " faces, found " +
                    std::to_string(f));
        const std::string face = "face " + std::to_string(f + 1);
        const std::int64_t size =
            in.to_integer(in.need_in_line("number of face vertices"), "number of face vertices");
        if (size > 3)
            in.fail(face + " has " + std::to_string(size) +
                    " vertices: only triangles are supported");
        if (size < 3)
            in.fail(face + " has " + std::to_string(size) + " vertices: a face needs 3");
        cells.lines.push_back(in.line());
        for (int j = 0; j < 3; ++j) {
            if (in.line_done())
                in.fail(face + " declares 3 vertices but has " + std::to_string(j));
            const std::int64_t index =
                in.to_integer(in.next_in_line(), "vertex index");
            if (index < 0 || index >= nv)
                in.fail("vertex index " + std::to_string(index) + " out of range (0.." +
                        std::to_string(nv - 1) + ")");
            cells.vertices.push_back(static_cast<VertexId>(index));
        }
        // a colour may follow: a colour map index or RGB[A], so 1, 3 or 4 values; any other
        // number of values is a face with more vertices than it declares, or a broken colour
        int colour = 0;
        while (!in.line_done()) {
            in.to_double(in.next_in_line(), "colour component");
            ++colour;
        }
        if (colour == 2 || colour > 4)
            in.fail(face + " has " + std::to_string(colour) +
                    " values after its 3 vertices (a colour is 1, 3 or 4 values)");
        cells.labels.push_back(0);
    }
    if (in.next_line())
        in.fail("more data than the header declares (" + std::to_string(nv) + " vertices, " +
                std::to_string(nf) + " faces)");
    return build_mesh(raw, name, options, report);
}

std::string write_off(const Mesh& mesh, const WriteOptions& options) {
    const std::span<const Point> positions = chosen_positions(mesh, options);
    const Surface surface = triangle_surface(mesh);
    std::string out;
    out.reserve(surface.vertices.size() * 60 + surface.triangles.size() * 24);
    out += "OFF\n# written by simplexkit\n";
    append_number(out, surface.vertices.size());
    out += ' ';
    append_number(out, surface.triangles.size());
    out += " 0\n";
    append_surface_lines(out, surface, positions);
    return out;
}

}  // namespace sxk::io
