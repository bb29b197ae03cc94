#include "writing.hpp"

#include <algorithm>

#include "text.hpp"

namespace sxk::io {

std::span<const Point> chosen_positions(const Mesh& mesh, const WriteOptions& options) {
    return options.positions == Positions::reference ? mesh.reference_positions()
                                                     : mesh.deformed_positions();
}

std::array<VertexId, 4> oriented_vertices(const Simplex& s) {
    std::array<VertexId, 4> v{invalid_id, invalid_id, invalid_id, invalid_id};
    for (int j = 0; j < s.count(); ++j)
        v[static_cast<std::size_t>(j)] = s.vertex(j);
    if (s.sign() < 0 && s.count() >= 2)
        std::swap(v[0], v[1]);
    return v;
}

std::vector<std::pair<Simplex, int>> sorted_face_labels(const Mesh& mesh) {
    std::vector<std::pair<Simplex, int>> faces(mesh.face_labels().begin(),
                                               mesh.face_labels().end());
    std::sort(faces.begin(), faces.end(),
              [](const auto& a, const auto& b) { return a.first < b.first; });
    for (auto& [face, label] : faces)
        if (mesh.find_boundary_face(face) == invalid_id &&
            mesh.find_boundary_face(face.mate()) != invalid_id)
            face = face.mate();
    return faces;
}

Surface triangle_surface(const Mesh& mesh) {
    Surface surface;
    if (mesh.topological_dimension() == 2) {
        surface.vertices.resize(mesh.vertex_count());
        for (VertexId v = 0; v < mesh.vertex_count(); ++v)
            surface.vertices[v] = v;
        surface.triangles.reserve(mesh.element_count());
        for (ElementId t : elements(mesh)) {
            const auto v = oriented_vertices(mesh.simplex(t));
            surface.triangles.push_back({v[0], v[1], v[2]});
        }
        return surface;
    }
    const std::vector<FaceId> boundary = mesh.boundary_faces();
    std::vector<VertexId> renumbered(mesh.vertex_count(), invalid_id);
    for (FaceId f : boundary) {
        // a named copy: vertices() is a view into the simplex, which face_simplex returns by value
        const Simplex face = mesh.face_simplex(f);
        for (VertexId v : face.vertices())
            renumbered[v] = 0;
    }
    for (VertexId v = 0; v < mesh.vertex_count(); ++v)
        if (renumbered[v] == 0) {
            renumbered[v] = static_cast<VertexId>(surface.vertices.size());
            surface.vertices.push_back(v);
        }
    surface.triangles.reserve(boundary.size());
    for (FaceId f : boundary) {
        // the face of an element, as invariant 7.1 orients it: outward for a positive element
        const auto v = oriented_vertices(mesh.face_simplex(f));
        surface.triangles.push_back({renumbered[v[0]], renumbered[v[1]], renumbered[v[2]]});
    }
    return surface;
}

void append_surface_lines(std::string& out, const Surface& surface, std::span<const Point> positions) {
    for (VertexId v : surface.vertices) {
        append_xyz(out, positions[v]);
        out += '\n';
    }
    for (const auto& t : surface.triangles) {
        out += '3';
        for (VertexId v : t) {
            out += ' ';
            append_number(out, v);
        }
        out += '\n';
    }
}

}  // namespace sxk::io
