// collapse_edge (thesis §3.2.3, Fig. 3.10; connectivity edit by §7.3 replace-elements).
#include "sxk/ops/collapse_edge.hpp"

#include <algorithm>
#include <array>
#include <cstddef>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "ops/filtered_triangle_tests.hpp"
#include "ops/link_condition.hpp"
#include "ops/orientation_checks.hpp"
#include "sxk/quality.hpp"

namespace sxk {
namespace {

// A vertex star: 2D stars have ~6 elements, 3D stars ~25.
using Star = detail::SmallVector<ElementId, 64>;

bool on_boundary(const Mesh& mesh, std::span<const ElementId> around, VertexId v, VertexId w = invalid_id) {
    for (const ElementId t : around) {
        const Simplex& tau = mesh.simplex(t);
        if (w != invalid_id && !tau.contains(w)) continue;
        for (int i = 0; i < tau.count(); ++i)
            if (tau.vertex(i) != v && tau.vertex(i) != w && mesh.neighbor(t, i) == invalid_id)
                return true;
    }
    return false;
}

// True when point p lies on the affine hull of the boundary face (line in 2D, plane in 3D):
// exactly when tolerance is 0, else within tolerance times the face's longest edge.
bool on_hull_of(const Simplex& face, const Mesh& mesh, const Point& p, Positions positions,
                double tolerance) {
    auto point = [&](int j) -> const Point& {
        return positions == Positions::reference ? mesh.reference(face.vertex(j)) : mesh.deformed(face.vertex(j));
    };
    if (tolerance == 0) {
        if (face.count() == 2) return collinear(point(0), point(1), p);
        return orient3d(point(0), point(1), point(2), p) == Sign::zero;
    }
    std::array<Point, 3> points{};
    for (int i = 0; i < face.count(); ++i) points[static_cast<std::size_t>(i)] = point(i);
    // a face with no line or plane (collinear vertices) is infinitely far: any move refuses
    return relative_distance_to_hull(std::span<const Point>(points.data(), static_cast<std::size_t>(face.count())), p) <=
           tolerance;
}

std::string in_the(Positions positions) {
    return std::string(" in the ") + to_string(positions) + " positions";
}

Outcome<VertexId> collapse(Mesh& mesh, VertexId from, VertexId to, const detail::MovedVertex& moved,
                           const CollapseOptions& options) {
    if (!(options.boundary_tolerance >= 0 && options.boundary_tolerance < 1))
        return Refusal{RefusalCode::bad_argument,
                       "collapse_edge: boundary tolerance must be in [0, 1)"};
    const std::size_t n = mesh.vertex_count();
    if (from >= n || to >= n)
        return Refusal{
            RefusalCode::not_found,
            "collapse_edge: " + std::to_string(from >= n ? from : to) + " is not a vertex"};
    if (from == to)
        return Refusal{RefusalCode::bad_argument,
                       "collapse_edge: the two ends are the same vertex"};
    // Both stars are walked once (in sxk::star order) and serve every check and the edit.
    Star star_from, star_to;
    detail::star_into(mesh, from, star_from);
    detail::star_into(mesh, to, star_to);
    const Simplex edge(+1, {from, to});
    if (std::none_of(star_from.begin(), star_from.end(),
                     [&](ElementId t) { return mesh.simplex(t).contains(to); }))
        return Refusal{RefusalCode::not_found,
                       "collapse_edge: " + to_text(edge) + " is not an edge"};

    // The boundary keeps its shape (thesis §3.2.3: collapses must not change the domain): a
    // boundary vertex may only slide along the boundary, i.e. along a boundary edge.
    if (on_boundary(mesh, star_from, from) && !on_boundary(mesh, star_from, from, to))
        return Refusal{RefusalCode::moves_boundary,
                       "collapse_edge: " + to_text(edge) + " is interior but vertex " +
                           std::to_string(from) +
                           " is on the boundary: the collapse would move the boundary"};

    // Link condition (thesis Fig. 3.10): otherwise the result is not a manifold. Triangle meshes
    // test it on the two stars directly (link_condition.hpp: the same answer).
    if (!(mesh.topological_dimension() == 2
              ? detail::link_condition_holds_2d(mesh, star_from, star_to, from, to)
              : detail::link_condition_holds(mesh, star_from, star_to, from, to)))
        return Refusal{RefusalCode::link_condition,
                       "collapse_edge: " + to_text(edge) +
                           " violates the link condition (the result would not be a manifold)"};

    // Boundary faces whose vertex moves must keep their line / plane: for from, the faces of
    // star(from) not containing to (they get `to` in place of `from`); for the point overload
    // also the faces of star(to) not containing from.
    const bool moves_to = moved.vertex == to;
    for (const Positions positions : {Positions::reference, Positions::deformed}) {
        const Point& target = detail::position_of(mesh, to, positions, moved);
        for (const Star* around : {&star_from, &star_to}) {
            const VertexId mover = around == &star_from ? from : to;
            if (mover == to && !moves_to) continue;
            for (const ElementId t : *around) {
                const Simplex& tau = mesh.simplex(t);
                for (int i = 0; i < tau.count(); ++i) {
                    if (mesh.neighbor(t, i) != invalid_id) continue;
                    const Simplex face = tau.subn(i);  // invariant 7.1
                    if (!face.contains(mover) || (face.contains(from) && face.contains(to))) continue;
                    if (!on_hull_of(face, mesh, target, positions, options.boundary_tolerance))
                        return Refusal{RefusalCode::moves_boundary,
                                       "collapse_edge: boundary face " + to_text(face) +
                                       " would leave its " + (face.count() == 2 ? "line" : "plane") +
                                       in_the(positions) + ": the collapse would move the boundary"};
                }
            }
        }
    }

    detail::SmallVector<Simplex, 32> survivors;
    detail::SmallVector<ElementId, 32> originals;
    detail::SmallVector<std::uint32_t, 32> origins;  // a survivor keeps its element's label and attributes
    for (std::uint32_t i = 0; i < star_from.size(); ++i) {
        const Simplex& tau = mesh.simplex(star_from[i]);
        if (tau.contains(to)) continue;
        survivors.push_back(tau.substituted(from, to));
        originals.push_back(star_from[i]);
        origins.push_back(i);
    }
    // Geometry of what changes shape: the re-attached elements (survivors[i], before: the
    // simplex of originals[i]), and for the point overload the elements of star(to) that stay
    // (the same simplex before and after). Index i runs over both lists in that order.
    detail::SmallVector<ElementId, 64> kept_at_to;
    if (moves_to)
        for (const ElementId t : star_to)
            if (!mesh.simplex(t).contains(from)) kept_at_to.push_back(t);
    const std::size_t reshaped_count = survivors.size() + kept_at_to.size();
    auto reshaped = [&](std::size_t i) -> const Simplex& {
        return i < survivors.size() ? survivors[i] : mesh.simplex(kept_at_to[i - survivors.size()]);
    };
    auto before = [&](std::size_t i) -> const Simplex& {
        return mesh.simplex(i < survivors.size() ? originals[i] : kept_at_to[i - survivors.size()]);
    };
    const bool surface = mesh.topological_dimension() < mesh.ambient_dimension();
    for (const Positions positions : {Positions::reference, Positions::deformed})
        for (std::size_t i = 0; i < reshaped_count; ++i) {
            if (!surface) {
                const Sign s = detail::simplex_orientation(mesh, reshaped(i), positions, moved);
                if (s != Sign::positive)
                    return Refusal{detail::orientation_code(s),
                                   "collapse_edge: element " + to_text(reshaped(i)) +
                                       (s == Sign::zero ? " would be flat" : " would be inverted") +
                                       in_the(positions),
                                   i};
                continue;
            }
            // A triangle in space: flat when its vertices are collinear (simplex_orientation's
            // Sign::zero; it is never "inverted"); and it cannot be inverted, but it can turn
            // over: compare the normal before and after (degree-4 sign, exact). Both tests on
            // normals computed once (filtered exact tests, filtered_triangle_tests.hpp).
            const Simplex& old_simplex = before(i);
            std::array<Point, 3> old_points{}, new_points{};
            for (int j = 0; j < 3; ++j) {
                const VertexId v = old_simplex.vertex(j);
                // the same vertex order as before, with from -> to and `to` where it goes
                old_points[static_cast<std::size_t>(j)] =
                    positions == Positions::reference ? mesh.reference(v) : mesh.deformed(v);
                new_points[static_cast<std::size_t>(j)] =
                    detail::position_of(mesh, v == from ? to : v, positions, moved);
            }
            const detail::TriangleNormal new_normal =
                detail::triangle_normal(new_points[0], new_points[1], new_points[2]);
            if (detail::collinear_filtered(new_points[0], new_points[1], new_points[2], new_normal))
                return Refusal{RefusalCode::would_flatten,
                               "collapse_edge: element " + to_text(reshaped(i)) + " would be flat" +
                                   in_the(positions),
                               i};
            const detail::TriangleNormal old_normal =
                detail::triangle_normal(old_points[0], old_points[1], old_points[2]);
            if (detail::normal_alignment_filtered(old_points[0], old_points[1], old_points[2], old_normal,
                                                  new_points[0], new_points[1], new_points[2],
                                                  new_normal) != Sign::positive)
                return Refusal{RefusalCode::would_invert,
                               "collapse_edge: triangle " + to_text(reshaped(i)) +
                                   " would turn over" + in_the(positions),
                               i};
        }

    // Face labels (keyed by vertex set) of the faces around `from`: a face with both ends
    // vanishes with its label; a face with `from` but not `to` becomes the face with `to` in its
    // place and takes its label along, unless that face has a label of its own.
    std::vector<Simplex> gone_labels;
    std::vector<std::pair<Simplex, int>> moved_labels;
    if (!mesh.face_labels().empty())
        for (const ElementId t : star_from)
            for (int i = 0; i < mesh.simplex(t).count(); ++i) {
                const Simplex face(+1, mesh.simplex(t).subn(i).vertices());
                if (!face.contains(from)) continue;
                const auto label = mesh.face_labels().find(face);
                if (label == mesh.face_labels().end()) continue;
                if (std::find(gone_labels.begin(), gone_labels.end(), face) != gone_labels.end()) continue;
                gone_labels.push_back(face);
                if (!face.contains(to))
                    moved_labels.emplace_back(Simplex(+1, face.substituted(from, to).vertices()), label->second);
            }

    // Triangle meshes (planar or surfaces) skip replace_elements' star walks, which the checks
    // above prove (mesh_checks.hpp, ProvenEdit). On a valid triangle mesh every vertex link is
    // a path or a cycle (faces in at most two triangles, face-connected stars); `from`'s link
    // L is a cycle (or, `from` on the boundary, a path ending at `to`, since a boundary `from`
    // must slide along a boundary edge). (a) A new element tau[from -> to] is `to` joined to
    // the edge rho of tau opposite `from`; were it an element already, rho would be in
    // link(from) and link(to) but not in link(from-to) (that would make from, to and rho a
    // tetrahedron): the link condition refuses that. A new face {to, x} with x in L: if it is
    // an edge already, x is in link(from) and link(to), so (link condition) x is opposite the
    // edge, (from, to, x) is a removed triangle and the re-attached triangle across {from, x}
    // takes over exactly that triangle's face <to, x>, orientation included (the mate of
    // {from, x} in it is the face the removed triangle had; substituting `to` for `from` in
    // both gives equal oriented faces): a reused face, not a new one. (b) The link of `to`
    // becomes link(to) with `from` replaced by the part of L between the two vertices opposite
    // the edge (one, on a boundary edge), which share no other vertex with link(to) (link
    // condition): a path or cycle again, so star(to) stays face-connected; the link of x in L
    // gets `to` in place of `from` (x not opposite the edge: `to` is not in it already, by the
    // link condition) or loses `from` next to `to` (x opposite the edge): connected again.
    // Tetrahedral meshes allow vertex links that are not spheres or discs, so they keep the
    // generic checks.
    auto result = mesh.topological_dimension() == 2
                      ? ProvenEdit::replace(mesh, star_from, survivors, {}, origins)
                      : mesh.replace_elements(star_from, survivors, {}, origins);
    if (!result.ok()) return result.refusal().prefixed("collapse_edge: ");
    for (const Simplex& face : gone_labels) mesh.erase_face_label(face);
    for (const auto& [face, label] : moved_labels)
        if (!mesh.face_label(face)) mesh.set_face_label(face, label);
    if (moves_to) {
        // Attributes follow the position: the parameter s of the new reference position
        // projected onto the edge (to = 0, from = 1, clamped), the same rule as a split at s.
        const Point& a = mesh.reference(to);
        const Point& b = mesh.reference(from);
        double along = 0, length2 = 0;
        for (std::size_t k = 0; k < 3; ++k) {
            along += (moved.reference[k] - a[k]) * (b[k] - a[k]);
            length2 += (b[k] - a[k]) * (b[k] - a[k]);
        }
        const double s = length2 > 0 ? std::clamp(along / length2, 0.0, 1.0) : 0.0;
        if (s > 0)
            for (const AttributeId attribute : mesh.vertex_attributes()) {
                const std::span<const double> survivor = mesh.vertex_attribute(attribute, to);
                const std::span<const double> merged = std::as_const(mesh).vertex_attribute(attribute, from);
                std::vector<double> value(survivor.size());
                for (std::size_t c = 0; c < survivor.size(); ++c)
                    value[c] = (1 - s) * survivor[c] + s * merged[c];
                (void)mesh.set_vertex_attribute(attribute, to, value);  // a live attribute, a vertex: cannot refuse
            }
        mesh.set_reference(to, moved.reference);
        mesh.set_deformed(to, moved.deformed);
    }
    return to;
}

}  // namespace

Outcome<VertexId> collapse_edge(Mesh& mesh, VertexId from, VertexId to, const CollapseOptions& options) {
    return collapse(mesh, from, to, {}, options);
}

Outcome<VertexId> collapse_edge(Mesh& mesh, VertexId from, VertexId to, const Point& reference,
                                const Point& deformed, const CollapseOptions& options) {
    return collapse(mesh, from, to, detail::MovedVertex{to, reference, deformed}, options);
}

}  // namespace sxk
