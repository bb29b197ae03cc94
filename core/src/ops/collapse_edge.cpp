// collapse_edge (thesis §3.2.3, Fig. 3.10; connectivity edit by §7.3 replace-elements).
#include "sxk/ops/collapse_edge.hpp"

#include <algorithm>
#include <array>
#include <cstddef>
#include <utility>
#include <vector>

#include "ops/split_collapse_checks.hpp"

namespace sxk {
namespace {

// The virtual vertex standing for "outside": joined to every boundary face, it turns a mesh
// with boundary into a closed complex for the link condition (Dey et al., edge contraction).
constexpr VertexId outside = invalid_id;

// A simplex of a link: {size, its vertices sorted, 0 padding}. The links of one edge collapse
// have a few dozen simplexes of at most 3 vertices: flat sorted arrays searched by bisection,
// with no allocation per simplex.
using LinkSimplex = std::array<VertexId, 4>;

// Adds every non-empty subset of the first n of `vertices` (which exclude the apex) to `link`.
void add_faces_of(std::array<VertexId, 3> vertices, std::size_t n, std::vector<LinkSimplex>& link) {
    for (std::size_t i = 1; i < n; ++i)  // at most three: insertion sort
        for (std::size_t j = i; j > 0 && vertices[j] < vertices[j - 1]; --j)
            std::swap(vertices[j], vertices[j - 1]);
    for (unsigned mask = 1; mask < (1u << n); ++mask) {
        LinkSimplex s{};
        for (std::size_t i = 0; i < n; ++i)
            if (mask & (1u << i)) s[++s[0]] = vertices[i];
        link.push_back(s);
    }
}

// link(sigma) for sigma = {v} or {v, w}: the simplexes tau disjoint from sigma with tau * sigma
// in the closed star, the boundary joined to `outside`. Sorted, without repeats.
std::vector<LinkSimplex> link_of(const Mesh& mesh, std::span<const ElementId> around,
                                 std::span<const VertexId> sigma) {
    std::vector<LinkSimplex> link;
    auto in_sigma = [&](VertexId v) { return std::find(sigma.begin(), sigma.end(), v) != sigma.end(); };
    for (const ElementId t : around) {
        const Simplex& tau = mesh.simplex(t);
        if (!std::all_of(sigma.begin(), sigma.end(), [&](VertexId v) { return tau.contains(v); }))
            continue;
        std::array<VertexId, 3> rest{};
        std::size_t rest_count = 0;
        for (const VertexId v : tau.vertices())
            if (!in_sigma(v)) rest[rest_count++] = v;
        add_faces_of(rest, rest_count, link);
        // boundary faces of t containing sigma, joined to the outside vertex
        for (int i = 0; i < tau.count(); ++i) {
            if (in_sigma(tau.vertex(i)) || mesh.mate(mesh.face(t, i)) != invalid_id) continue;
            std::array<VertexId, 3> face_rest{outside};
            std::size_t face_count = 1;
            for (std::size_t j = 0; j < rest_count; ++j)
                if (rest[j] != tau.vertex(i)) face_rest[face_count++] = rest[j];
            add_faces_of(face_rest, face_count, link);
        }
    }
    std::sort(link.begin(), link.end());
    link.erase(std::unique(link.begin(), link.end()), link.end());
    return link;
}

bool on_boundary(const Mesh& mesh, std::span<const ElementId> around, VertexId v, VertexId w = invalid_id) {
    for (const ElementId t : around) {
        const Simplex& tau = mesh.simplex(t);
        if (w != invalid_id && !tau.contains(w)) continue;
        for (int i = 0; i < tau.count(); ++i)
            if (tau.vertex(i) != v && tau.vertex(i) != w && mesh.mate(mesh.face(t, i)) == invalid_id)
                return true;
    }
    return false;
}

// True when point p lies on the affine hull of the boundary face (line in 2D, plane in 3D).
bool on_hull_of(const Simplex& face, const Mesh& mesh, const Point& p, Positions positions) {
    auto point = [&](int j) -> const Point& {
        return positions == Positions::reference ? mesh.reference(face.vertex(j)) : mesh.deformed(face.vertex(j));
    };
    if (face.count() == 2) return collinear(point(0), point(1), p);
    return orient3d(point(0), point(1), point(2), p) == Sign::zero;
}

Outcome<VertexId> collapse(Mesh& mesh, VertexId from, VertexId to, const detail::MovedVertex& moved) {
    const std::size_t n = mesh.vertex_count();
    if (from >= n || to >= n)
        return Refusal{"collapse_edge: " + std::to_string(from >= n ? from : to) + " is not a vertex"};
    if (from == to) return Refusal{"collapse_edge: the two ends are the same vertex"};
    const std::vector<ElementId> star_from = star(mesh, from);
    const std::vector<ElementId> star_to = star(mesh, to);
    const Simplex edge(+1, {from, to});
    if (std::none_of(star_from.begin(), star_from.end(),
                     [&](ElementId t) { return mesh.simplex(t).contains(to); }))
        return Refusal{"collapse_edge: " + to_text(edge) + " is not an edge"};

    // The boundary keeps its shape (thesis §3.2.3: collapses must not change the domain): a
    // boundary vertex may only slide along the boundary, i.e. along a boundary edge.
    if (on_boundary(mesh, star_from, from) && !on_boundary(mesh, star_from, from, to))
        return Refusal{"collapse_edge: " + to_text(edge) +
                       " is interior but vertex " + std::to_string(from) +
                       " is on the boundary: the collapse would move the boundary"};

    // Link condition (thesis Fig. 3.10): otherwise the result is not a manifold.
    {
        const std::array<VertexId, 1> just_from{from}, just_to{to};
        const std::array<VertexId, 2> both{from, to};
        const std::vector<LinkSimplex> link_from = link_of(mesh, star_from, just_from);
        const std::vector<LinkSimplex> link_to = link_of(mesh, star_to, just_to);
        const std::vector<LinkSimplex> link_edge = link_of(mesh, star_from, both);
        for (const LinkSimplex& s : link_from)
            if (std::binary_search(link_to.begin(), link_to.end(), s) &&
                !std::binary_search(link_edge.begin(), link_edge.end(), s))
                return Refusal{"collapse_edge: " + to_text(edge) +
                               " violates the link condition (the result would not be a manifold)"};
    }

    // Boundary faces whose vertex moves must keep their line / plane: for from, the faces of
    // star(from) not containing to (they get `to` in place of `from`); for the point overload
    // also the faces of star(to) not containing from.
    const bool moves_to = moved.vertex == to;
    for (const Positions positions : {Positions::reference, Positions::deformed}) {
        const Point& target = detail::position_of(mesh, to, positions, moved);
        for (const auto* around : {&star_from, &star_to}) {
            const VertexId mover = around == &star_from ? from : to;
            if (mover == to && !moves_to) continue;
            for (const ElementId t : *around) {
                const Simplex& tau = mesh.simplex(t);
                for (int i = 0; i < tau.count(); ++i) {
                    const FaceId f = mesh.face(t, i);
                    if (mesh.mate(f) != invalid_id) continue;
                    const Simplex face = mesh.face_simplex(f);
                    if (!face.contains(mover) || (face.contains(from) && face.contains(to))) continue;
                    if (!on_hull_of(face, mesh, target, positions))
                        return Refusal{"collapse_edge: boundary face " + to_text(face) +
                                       " would leave its " + (face.count() == 2 ? "line" : "plane") +
                                       " in the " + detail::positions_text(positions) +
                                       " positions: the collapse would move the boundary"};
                }
            }
        }
    }

    std::vector<Simplex> survivors;
    std::vector<ElementId> originals;
    std::vector<int> labels;
    for (const ElementId t : star_from) {
        const Simplex& tau = mesh.simplex(t);
        if (tau.contains(to)) continue;
        survivors.push_back(tau.substituted(from, to));
        originals.push_back(t);
        labels.push_back(mesh.label(t));
    }
    // Geometry of what changes shape: the re-attached elements, and for the point overload the
    // elements of star(to) that stay.
    std::vector<Simplex> reshaped = survivors;
    std::vector<Simplex> before;
    for (const ElementId t : originals) before.push_back(mesh.simplex(t));
    if (moves_to)
        for (const ElementId t : star_to)
            if (!mesh.simplex(t).contains(from)) {
                reshaped.push_back(mesh.simplex(t));
                before.push_back(mesh.simplex(t));
            }
    const bool surface = mesh.topological_dimension() < mesh.ambient_dimension();
    for (const Positions positions : {Positions::reference, Positions::deformed})
        for (std::size_t i = 0; i < reshaped.size(); ++i) {
            const Sign s = detail::simplex_orientation(mesh, reshaped[i], positions, moved);
            const std::string where = std::string(" in the ") + detail::positions_text(positions) + " positions";
            if (s != Sign::positive)
                return Refusal{"collapse_edge: element " + to_text(reshaped[i]) +
                                   (s == Sign::zero ? " would be flat" : " would be inverted") + where,
                               i};
            if (surface) {
                // A triangle in space cannot be "inverted", but it can turn over: compare the
                // normal before and after (degree-4 sign, exact).
                auto point_before = [&](int j) -> const Point& {
                    const VertexId v = before[i].vertex(j);
                    return positions == Positions::reference ? mesh.reference(v) : mesh.deformed(v);
                };
                // the same vertex order as `before`, with from -> to and `to` where it goes
                std::array<Point, 3> after{};
                for (int j = 0; j < 3; ++j) {
                    const VertexId v = before[i].vertex(j) == from ? to : before[i].vertex(j);
                    after[static_cast<std::size_t>(j)] = detail::position_of(mesh, v, positions, moved);
                }
                if (normal_alignment(point_before(0), point_before(1), point_before(2), after[0],
                                     after[1], after[2]) != Sign::positive)
                    return Refusal{"collapse_edge: triangle " + to_text(reshaped[i]) +
                                       " would turn over" + where,
                                   i};
            }
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

    auto result = mesh.replace_elements(star_from, survivors, labels);
    if (!result.ok()) return Refusal{"collapse_edge: " + result.reason()};
    for (const Simplex& face : gone_labels) mesh.face_labels().erase(face);
    for (const auto& [face, label] : moved_labels) mesh.face_labels().try_emplace(face, label);
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
                const std::span<double> survivor = mesh.vertex_attribute(attribute, to);
                const std::span<const double> merged = std::as_const(mesh).vertex_attribute(attribute, from);
                for (std::size_t c = 0; c < survivor.size(); ++c)
                    survivor[c] = (1 - s) * survivor[c] + s * merged[c];
            }
        mesh.set_reference(to, moved.reference);
        mesh.set_deformed(to, moved.deformed);
    }
    return to;
}

}  // namespace

Outcome<VertexId> collapse_edge(Mesh& mesh, VertexId from, VertexId to) {
    return collapse(mesh, from, to, {});
}

Outcome<VertexId> collapse_edge(Mesh& mesh, VertexId from, VertexId to, const Point& reference,
                                const Point& deformed) {
    return collapse(mesh, from, to, detail::MovedVertex{to, reference, deformed});
}

}  // namespace sxk
