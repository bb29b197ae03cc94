// Peeling a flat element off the boundary (beyond the thesis): a degenerate element with a face
// on the boundary whose other vertices lie within the boundary tolerance of that face's plane is
// removed, and its other faces become the boundary. No crack opens and no vertex moves: the
// boundary moves by the element's height over its boundary face, which the tolerance bounds, as
// it bounds every boundary move of a collapse.
//
//      interior                    interior
//    a -------- b                a -------- b      the flat element a b c (a triangle here:
//     \   t   /          -->      \       /        c lies on the boundary line a-b within the
//  ----c-----              ----------c-----        tolerance) goes; a-c and c-b are the boundary
//      boundary (a-b was on it)
#include <algorithm>
#include <array>
#include <string>
#include <vector>

#include "sxk/ops/remove_elements.hpp"
#include "removal_steps.hpp"
#include "sxk/quality.hpp"

namespace sxk::degeneracy::detail {
Refused peel_off_boundary(Mesh& mesh, ElementId t, const Options& options) {
    const Simplex tau = mesh.simplex(t);
    std::vector<Simplex> boundary, exposed;
    for (int i = 0; i < tau.count(); ++i)
        (mesh.neighbor(t, i) == invalid_id ? boundary : exposed).push_back(tau.subn(i));
    if (boundary.empty()) return Refusal(RefusalCode::not_applicable,
                                         "it has no face on the boundary");
    if (exposed.empty()) return Refusal(RefusalCode::not_applicable,
                                        "it is a whole component (no interior face)");
    for (const Simplex& face : boundary)
        for (const VertexId v : tau.vertices()) {
            if (face.contains(v)) continue;
            for (const Positions positions : {Positions::reference, Positions::deformed}) {
                std::array<Point, 3> corners{};
                for (int i = 0; i < face.count(); ++i)
                    corners[static_cast<std::size_t>(i)] = position(mesh, face.vertex(i), positions);
                const double d = relative_distance_to_hull(
                    std::span<const Point>(corners.data(), static_cast<std::size_t>(face.count())),
                    position(mesh, v, positions));
                if (!(d <= options.boundary_tolerance))
                    return Refusal(RefusalCode::moves_boundary,
                                   "peeling it off would move the boundary face " + to_text(face) +
                                       " by " + std::to_string(d) + " of its longest edge");
            }
        }
    int label = 0;
    bool labelled = false;
    for (const Simplex& face : boundary) {
        const auto found = mesh.face_labels().find(Simplex(+1, face.vertices()));
        if (found != mesh.face_labels().end()) {
            label = found->second;
            labelled = true;
            break;
        }
    }
    // its boundary faces go with it, and their labels (remove_elements); the faces it exposed
    // carry the boundary's label on (recorded setters: the removal runs inside the plug-in's
    // EditStep, whose rollback puts them back)
    const std::array<ElementId, 1> doomed{t};
    if (Outcome<Done> removed = remove_elements(mesh, doomed); !removed) return removed.refusal();
    if (labelled)
        for (const Simplex& face : exposed)
            if (!mesh.face_label(face)) mesh.set_face_label(face, label);
    return std::nullopt;
}

}  // namespace sxk::degeneracy::detail
