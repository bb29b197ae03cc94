// Lawson's flips around one node (star_flips.hpp).
#include "star_flips.hpp"

#include <array>

#include "surface_geometry.hpp"
#include "sxk/edit_journal.hpp"
#include "sxk/ops/flip_edge.hpp"
#include "sxk/ops/make_delaunay_by_flips.hpp"
#include "sxk/traversal.hpp"

namespace sxk::delaunaycut {

namespace {

// One flip of an edge of star(v) that fails the test and may be flipped; false when there is none.
bool flip_one(Mesh& mesh, VertexId v, const StarFlipRules& rules) {
    for (const ElementId t : star(mesh, v)) {
        const Simplex s = mesh.simplex(t);
        for (int k = 0; k < 3; ++k) {
            const ElementId other = mesh.neighbor(t, k);
            if (other == invalid_id) continue;
            const FaceId edge = mesh.face(t, k);
            if (is_locally_delaunay(mesh, edge, Positions::deformed)) continue;
            if (rules.may_join) {
                VertexId d = invalid_id;
                for (const VertexId w : mesh.simplex(other).vertices())
                    if (w != s.vertex((k + 1) % 3) && w != s.vertex((k + 2) % 3)) d = w;
                if (!rules.may_join(s.vertex(k), d)) continue;
            }
            if (!rules.no_new_folds) {
                if (flip_edge(mesh, edge)) return true;
                continue;
            }
            const std::array<ElementId, 2> was{t, other};
            const std::size_t folds_before = folds_at(mesh, was);
            EditStep attempt(*EditJournal::of(mesh));
            auto made = flip_edge(mesh, edge);
            if (made && folds_at(mesh, *made) <= folds_before && attempt.commit()) return true;
        }  // a flip taken back leaves the star as it was: the next edge
    }
    return false;
}

}  // namespace

std::size_t flip_star(Mesh& mesh, VertexId v, const StarFlipRules& rules) {
    std::size_t flips = 0;
    while (flips < rules.most && flip_one(mesh, v, rules)) ++flips;
    return flips;
}

}  // namespace sxk::delaunaycut
