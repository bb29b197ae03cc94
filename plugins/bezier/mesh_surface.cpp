#include "mesh_surface.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

#include "sxk/components.hpp"
#include "sxk/quality.hpp"

namespace sxk::bezier {

namespace {

// The vertices of a simplex in an order of its orientation: the canonical (sorted) order, with
// the first two swapped when the sign is negative (as the writers orient faces).
std::array<VertexId, 4> oriented_vertices(const Simplex& simplex) {
    std::array<VertexId, 4> vertices{invalid_id, invalid_id, invalid_id, invalid_id};
    for (int j = 0; j < simplex.count(); ++j)
        vertices[static_cast<std::size_t>(j)] = simplex.vertex(j);
    if (simplex.sign() < 0)
        std::swap(vertices[0], vertices[1]);
    return vertices;
}

double normalised_quality(const Mesh& mesh, ElementId t, Positions positions) {
    // the thesis aspect ratio of the regular tetrahedron and of the equilateral triangle
    const double regular =
        mesh.topological_dimension() == 3 ? std::sqrt(2.0 / 3.0) : std::sqrt(3.0) / 2.0;
    const double ratio = aspect_ratio(element_points(mesh, t, positions)) / regular;
    return std::isfinite(ratio) ? std::clamp(ratio, 0.0, 1.0) : 0.0;
}

// A boundary face as the set of its reference positions (sorted; unused slots stay zero), so
// that the two sides of a cut, whose vertices are distinct copies at the same points, compare
// equal.
// Compared coordinate by coordinate by hand: g++ 12 warns (-Warray-bounds, falsely) inside
// the operator<=> that std::array's operator< goes through, and in std::sort over the key.
using PositionKey = std::array<Point, 3>;

template <typename Array>
bool lexicographically_less(const Array& a, const Array& b) {
    for (std::size_t q = 0; q < a.size(); ++q)
        if (a[q] != b[q]) return a[q] < b[q];
    return false;
}

bool key_less(const PositionKey& a, const PositionKey& b) {
    for (std::size_t corner = 0; corner < 3; ++corner)
        if (a[corner] != b[corner]) return lexicographically_less(a[corner], b[corner]);
    return false;
}

PositionKey position_key(const Mesh& mesh, const Simplex& face) {
    PositionKey key{};
    const std::size_t count = std::min<std::size_t>(static_cast<std::size_t>(face.count()), key.size());
    for (std::size_t j = 0; j < count; ++j) key[j] = mesh.reference(face.vertex(static_cast<int>(j)));
    // insertion sort of at most three points (std::sort on a part of the array trips the warning too)
    for (std::size_t a = 1; a < count; ++a)
        for (std::size_t b = a; b > 0 && lexicographically_less(key[b], key[b - 1]); --b) std::swap(key[b], key[b - 1]);
    return key;
}

// Which boundary faces (by position in `boundary`, mesh.boundary_faces()) are on a cut: they
// coincide with another one, or carry the cut label.
std::vector<bool> cut_boundary_faces(const Mesh& mesh, const std::vector<FaceId>& boundary,
                                     const std::optional<int>& cut_label) {
    std::vector<std::pair<PositionKey, std::size_t>> keyed;
    keyed.reserve(boundary.size());
    for (std::size_t index = 0; index < boundary.size(); ++index)
        keyed.emplace_back(position_key(mesh, mesh.face_simplex(boundary[index])), index);
    std::sort(keyed.begin(), keyed.end(), [](const auto& a, const auto& b) { return key_less(a.first, b.first); });
    std::vector<bool> cut(boundary.size(), false);
    for (std::size_t first = 0; first < keyed.size();) {
        std::size_t last = first + 1;
        while (last < keyed.size() && keyed[last].first == keyed[first].first)
            ++last;
        if (last - first > 1)
            for (std::size_t run = first; run < last; ++run)
                cut[keyed[run].second] = true;
        first = last;
    }
    if (cut_label && !mesh.face_labels().empty())
        for (std::size_t index = 0; index < boundary.size(); ++index) {
            // face labels are keyed by the vertex set, sign +1
            const Simplex face = mesh.face_simplex(boundary[index]);
            const auto label = mesh.face_labels().find(Simplex(+1, face.vertices()));
            if (label != mesh.face_labels().end() && label->second == *cut_label)
                cut[index] = true;
        }
    return cut;
}

// Adds the vertices of `used` (indexed by VertexId) to the soup in increasing id order and
// returns their new numbers.
std::vector<std::uint32_t> add_used_vertices(const Mesh& mesh, const std::vector<bool>& used,
                                             Positions positions, TriangleSoup& soup) {
    std::vector<std::uint32_t> renumbered(mesh.vertex_count(), invalid_id);
    for (VertexId v = 0; v < mesh.vertex_count(); ++v)
        if (used[v]) {
            renumbered[v] = static_cast<std::uint32_t>(soup.vertices.size());
            soup.vertices.push_back(positions == Positions::reference ? mesh.reference(v)
                                                                      : mesh.deformed(v));
        }
    return renumbered;
}

MeshSurface tetrahedral_surface(const Mesh& mesh, const MeshSurfaceOptions& options) {
    const Positions positions = options.positions;
    const std::vector<FaceId> boundary = mesh.boundary_faces();
    const std::vector<bool> cut = cut_boundary_faces(mesh, boundary, options.cut_label);
    std::vector<bool> used(mesh.vertex_count(), false);
    for (FaceId f : boundary) {
        const Simplex face = mesh.face_simplex(f);  // named: vertices() views into it
        for (VertexId v : face.vertices())
            used[v] = true;
    }
    MeshSurface surface;
    const std::vector<std::uint32_t> renumbered =
        add_used_vertices(mesh, used, positions, surface.soup);
    surface.soup.triangles.reserve(boundary.size());
    surface.keys.reserve(boundary.size());
    for (std::size_t index = 0; index < boundary.size(); ++index) {
        const FaceId f = boundary[index];
        const auto v = oriented_vertices(mesh.face_simplex(f));
        surface.soup.triangles.push_back({renumbered[v[0]], renumbered[v[1]], renumbered[v[2]]});
        const ElementId t = mesh.face_element(f);
        surface.keys.push_back(
            {t, normalised_quality(mesh, t, positions), mesh.label(t), cut[index], 0});
    }
    return surface;
}

MeshSurface triangle_surface(const Mesh& mesh, const MeshSurfaceOptions& options) {
    const Positions positions = options.positions;
    // a cut of a triangle mesh is a pair of coinciding boundary edges: flag their triangles
    const std::vector<FaceId> boundary = mesh.boundary_faces();
    const std::vector<bool> cut_edge = cut_boundary_faces(mesh, boundary, options.cut_label);
    std::vector<bool> cut_element(mesh.element_capacity(), false);
    for (std::size_t index = 0; index < boundary.size(); ++index)
        if (cut_edge[index])
            cut_element[mesh.face_element(boundary[index])] = true;

    std::vector<bool> used(mesh.vertex_count(), false);
    for (ElementId t : elements(mesh))
        for (VertexId v : mesh.simplex(t).vertices())
            used[v] = true;
    MeshSurface surface;
    const std::vector<std::uint32_t> renumbered =
        add_used_vertices(mesh, used, positions, surface.soup);
    surface.soup.triangles.reserve(mesh.element_count());
    surface.keys.reserve(mesh.element_count());
    for (ElementId t : elements(mesh)) {
        const auto v = oriented_vertices(mesh.simplex(t));
        surface.soup.triangles.push_back({renumbered[v[0]], renumbered[v[1]], renumbered[v[2]]});
        surface.keys.push_back(
            {t, normalised_quality(mesh, t, positions), mesh.label(t), cut_element[t], 0});
    }
    return surface;
}

}  // namespace

std::size_t MeshSurface::cut_count() const {
    return static_cast<std::size_t>(std::count_if(
        keys.begin(), keys.end(), [](const SurfaceTriangleKeys& k) { return k.cut; }));
}

MeshSurface mesh_surface(const Mesh& mesh, const MeshSurfaceOptions& options) {
    MeshSurface surface = mesh.topological_dimension() == 3 ? tetrahedral_surface(mesh, options)
                                                            : triangle_surface(mesh, options);
    // one pass over the elements (O(n), as the boundary itself): a picture is not a tool's step
    const Components components = connected_components(mesh);
    surface.pieces = static_cast<std::uint32_t>(components.count);
    for (SurfaceTriangleKeys& key : surface.keys) key.piece = components.element_component[key.element];
    return surface;
}

}  // namespace sxk::bezier
