// Crumbs a cut would make stay attached (loose_pieces.hpp).
#include <algorithm>

#include "loose_pieces.hpp"
#include "sxk/traversal.hpp"

namespace sxk::snapcut {

namespace {

Simplex unoriented(const Simplex& face) { return Simplex(+1, face.vertices()); }

// The two elements on either side of interior face `face` (a star walk from its first corner),
// none when it is not a face of the mesh.
void add_elements_of(const Mesh& mesh, const Simplex& face, std::vector<ElementId>& around,
                     std::vector<ElementId>& sides) {
    around.clear();
    const VertexId v = face.vertex(0);
    if (mesh.vertex_element(v) == invalid_id) return;
    collect_star(mesh, v, mesh.vertex_element(v), around);
    for (const ElementId t : around) {
        const Simplex s = mesh.simplex(t);
        if (!s.contains(face.vertex(1)) || !s.contains(face.vertex(2))) continue;
        for (int i = 0; i < s.count(); ++i)
            if (!face.contains(s.vertex(i))) {  // face i of t, opposite its vertex i, is `face`
                sides.push_back(t);
                if (mesh.neighbor(t, i) != invalid_id) sides.push_back(mesh.neighbor(t, i));
                return;
            }
    }
}

}  // namespace

std::vector<Simplex> keep_crumbs_attached(const Mesh& mesh, std::vector<Simplex> faces, std::size_t crumb,
                                          const CutMarks* marks) {
    if (crumb == 0 || faces.empty()) return faces;
    const int n = mesh.element_vertex_count();
    // every corner of t is on the cut: t lies flat along it (see "Layers")
    const auto flat_on_cut = [&](ElementId t) {
        if (marks == nullptr) return false;
        const Simplex s = mesh.simplex(t);
        for (int i = 0; i < n; ++i)
            if (!marks->snapped(s.vertex(i))) return false;
        return true;
    };
    // face i of t is open after the cut: on the boundary already, or one of the faces to open
    const auto open = [&](ElementId t, int i) {
        const FaceId f = mesh.face(t, i);
        return mesh.mate(f) == invalid_id || std::binary_search(faces.begin(), faces.end(), unoriented(mesh.face_simplex(f)));
    };
    std::vector<ElementId> sides, around;
    for (const Simplex& face : faces) add_elements_of(mesh, face, around, sides);
    std::sort(sides.begin(), sides.end());
    sides.erase(std::unique(sides.begin(), sides.end()), sides.end());
    std::vector<ElementId> piece;
    for (const ElementId start : sides) {
        // the piece about `start` the open faces close off, searched up to crumb + 1 elements, or
        // largest_layer + 1 while all of them lie flat along the cut
        piece.assign(1, start);
        bool layer = flat_on_cut(start);
        bool larger = false;
        for (std::size_t k = 0; k < piece.size() && !larger; ++k)
            for (int i = 0; i < n && !larger; ++i) {
                const ElementId next = mesh.neighbor(piece[k], i);
                if (open(piece[k], i) || std::find(piece.begin(), piece.end(), next) != piece.end()) continue;
                piece.push_back(next);
                layer = layer && flat_on_cut(next);
                larger = piece.size() > (layer ? std::max(crumb, largest_layer) : crumb);
            }
        if (larger) continue;
        // a crumb: the lowest of the faces to open around it stays closed
        const Simplex* keep = nullptr;
        for (const ElementId t : piece)
            for (int i = 0; i < n; ++i) {
                if (mesh.mate(mesh.face(t, i)) == invalid_id) continue;
                const Simplex face = unoriented(mesh.face_simplex(mesh.face(t, i)));
                const auto found = std::lower_bound(faces.begin(), faces.end(), face);
                if (found != faces.end() && *found == face && (keep == nullptr || *found < *keep)) keep = &*found;
            }
        if (keep != nullptr) faces.erase(faces.begin() + (keep - faces.data()));
    }
    return faces;
}

}  // namespace sxk::snapcut
