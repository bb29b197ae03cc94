// VTK XML UnstructuredGrid (.vtu), ASCII, write only: for looking at meshes in ParaView.
//
// Points are written in 3D (z = 0 for planar meshes), cells as VTK_TRIANGLE (5) or VTK_TETRA
// (10) in positive orientation (VTK's tetra convention is ours: the fourth point lies on the
// side the right-handed normal of the first three points points to, det[b-a, c-a, d-a] > 0).
// Per-cell data, so ParaView can colour by label and quality:
//   label          the element label
//   aspect_ratio   thesis §3.2.3 aspect ratio (quality.hpp)
//   radius_ratio   d * inradius / circumradius
//   min_angle      smallest dihedral angle (tetrahedra) or angle (triangles), in degrees: the
//                  unit people read thresholds in
#include <algorithm>

#include "formats.hpp"
#include "sxk/quality.hpp"
#include "text.hpp"
#include "writing.hpp"

namespace sxk::io {

namespace {

void open_array(std::string& out, const char* type, const char* name, int components = 1) {
    out += "        <DataArray type=\"";
    out += type;
    out += "\" Name=\"";
    out += name;
    out += '"';
    if (components != 1) {
        out += " NumberOfComponents=\"";
        append_number(out, components);
        out += '"';
    }
    out += " format=\"ascii\">\n";
}

void close_array(std::string& out) {
    out += "        </DataArray>\n";
}

}  // namespace

std::string write_vtu(const Mesh& mesh, const WriteOptions& options) {
    const std::span<const Point> positions = chosen_positions(mesh, options);
    const int k = mesh.element_vertex_count();
    std::string out;
    out.reserve(mesh.vertex_count() * 64 + mesh.element_count() * 96);
    out +=
        "<?xml version=\"1.0\"?>\n"
        "<!-- written by simplexkit -->\n"
        "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
        "  <UnstructuredGrid>\n"
        "    <Piece NumberOfPoints=\"";
    append_number(out, mesh.vertex_count());
    out += "\" NumberOfCells=\"";
    append_number(out, mesh.element_count());
    out += "\">\n      <Points>\n";
    open_array(out, "Float64", "Points", 3);
    for (const Point& p : positions) {
        out += "          ";
        append_xyz(out, p);
        out += '\n';
    }
    close_array(out);
    out += "      </Points>\n      <Cells>\n";
    open_array(out, "Int64", "connectivity");
    for (ElementId t : elements(mesh)) {
        const auto v = oriented_vertices(mesh.simplex(t));
        out += "          ";
        for (int j = 0; j < k; ++j) {
            if (j)
                out += ' ';
            append_number(out, v[static_cast<std::size_t>(j)]);
        }
        out += '\n';
    }
    close_array(out);
    open_array(out, "Int64", "offsets");
    for (std::size_t i = 1; i <= mesh.element_count(); ++i) {
        out += "          ";
        append_number(out, i * static_cast<std::size_t>(k));
        out += '\n';
    }
    close_array(out);
    open_array(out, "UInt8", "types");
    const char* type = k == 4 ? "          10\n" : "          5\n";
    for (std::size_t i = 0; i < mesh.element_count(); ++i)
        out += type;
    close_array(out);
    out += "      </Cells>\n      <CellData Scalars=\"label\">\n";
    open_array(out, "Int32", "label");
    for (ElementId t : elements(mesh)) {
        out += "          ";
        append_number(out, mesh.label(t));
        out += '\n';
    }
    close_array(out);
    if (options.quality_cell_data) {
        const std::size_t n = mesh.element_count();
        std::vector<double> aspect(n), radius(n), angle(n);
        std::size_t i = 0;
        std::vector<Point> points(static_cast<std::size_t>(k));
        for (ElementId t : elements(mesh)) {
            const Simplex& s = mesh.simplex(t);
            for (int j = 0; j < k; ++j)
                points[static_cast<std::size_t>(j)] = positions[s.vertex(j)];
            aspect[i] = aspect_ratio(points);
            radius[i] = radius_ratio(points);
            double smallest = 0;
            if (k == 4) {
                const auto angles = dihedral_angles(points);
                smallest = *std::min_element(angles.begin(), angles.end());
            } else {
                const auto angles = triangle_angles(points);
                smallest = *std::min_element(angles.begin(), angles.end());
            }
            angle[i] = smallest * 180.0 / pi;
            ++i;
        }
        auto array = [&](const char* name, const std::vector<double>& values) {
            open_array(out, "Float64", name);
            for (double value : values) {
                out += "          ";
                // degenerate elements can give nan; VTK's ASCII parser reads "nan"
                append_number(out, value);
                out += '\n';
            }
            close_array(out);
        };
        array("aspect_ratio", aspect);
        array("radius_ratio", radius);
        array("min_angle", angle);
    }
    out += "      </CellData>\n    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n";
    return out;
}

}  // namespace sxk::io
