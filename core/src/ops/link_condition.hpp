// The link condition of an edge collapse (thesis Fig. 3.10), on the stars of the edge's two
// ends: link_condition_holds for any dimension (the links built as sorted flat arrays) and
// link_condition_holds_2d, the same answer for triangle meshes without building the links
// (tests/ops/surface_fast_paths_test.cpp compares the two). Used by collapse_edge.cpp.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <span>

#include "small_vector.hpp"
#include "sxk/mesh.hpp"

namespace sxk::detail {

// The link condition (thesis Fig. 3.10; Dey et al.):
// link(from) ∩ link(to) == link(from-to), the boundary joined to a virtual vertex `outside`
// (so that a collapse cannot glue two boundary pieces either). star_from and star_to are the
// stars of the two ends.

// The virtual vertex standing for "outside": joined to every boundary face, it turns a mesh
// with boundary into a closed complex for the link condition.
constexpr VertexId link_outside = invalid_id;

// A simplex of a link: {size, its vertices sorted, 0 padding}. The links of one edge collapse
// have a few dozen simplexes of at most 3 vertices: flat sorted arrays searched by bisection,
// with no allocation for links of up to 128 simplexes.
using LinkSimplex = std::array<VertexId, 4>;
using Link = SmallVector<LinkSimplex, 128>;

// Adds every non-empty subset of the first n of `vertices` (which exclude the apex) to `link`.
inline void add_faces_of(std::array<VertexId, 3> vertices, std::size_t n, Link& link) {
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
// in the closed star, the boundary joined to `link_outside`. Sorted, without repeats.
inline void link_of(const Mesh& mesh, std::span<const ElementId> around, std::span<const VertexId> sigma,
                    Link& link) {
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
            if (in_sigma(tau.vertex(i)) || mesh.neighbor(t, i) != invalid_id) continue;
            std::array<VertexId, 3> face_rest{link_outside};
            std::size_t face_count = 1;
            for (std::size_t j = 0; j < rest_count; ++j)
                if (rest[j] != tau.vertex(i)) face_rest[face_count++] = rest[j];
            add_faces_of(face_rest, face_count, link);
        }
    }
    std::sort(link.begin(), link.end());
    link.resize(static_cast<std::size_t>(std::unique(link.begin(), link.end()) - link.begin()));
}

// The link condition on all simplexes of the links, any dimension.
inline bool link_condition_holds(const Mesh& mesh, std::span<const ElementId> star_from,
                                 std::span<const ElementId> star_to, VertexId from, VertexId to) {
    const std::array<VertexId, 1> just_from{from}, just_to{to};
    const std::array<VertexId, 2> both{from, to};
    Link link_from, link_to, link_edge;
    link_of(mesh, star_from, just_from, link_from);
    link_of(mesh, star_to, just_to, link_to);
    link_of(mesh, star_from, both, link_edge);
    for (const LinkSimplex& s : link_from)
        if (std::binary_search(link_to.begin(), link_to.end(), s) &&
            !std::binary_search(link_edge.begin(), link_edge.end(), s))
            return false;
    return true;
}

// The same test for triangle meshes, without building the links. With T = {from, x, y} over
// star(from) (and likewise for `to`), the links are: vertices x, y; edges {x, y}; `outside`
// and edges {outside, y} for each boundary edge {from, y}; link(from-to) holds the third
// vertices of the triangles containing the edge, and `outside` when the edge is a boundary
// edge (no edges: a link of an edge in a surface has dimension 0). So the condition fails
// exactly when (1) a vertex x (not from, to) is in both stars without being opposite the edge,
// (2) both ends are on the boundary but the edge is not, (3) triangles {from, x, y} and
// {to, x, y} both exist, or (4) boundary edges {from, y} and {to, y} both exist.
inline bool link_condition_holds_2d(const Mesh& mesh, std::span<const ElementId> star_from,
                                    std::span<const ElementId> star_to, VertexId from, VertexId to) {
    // per star: the vertices other than the centre, the opposite edges {x, y} (sorted), and
    // the far ends y of boundary edges {centre, y}
    struct Side {
        SmallVector<VertexId, 64> vertices;
        SmallVector<std::array<VertexId, 2>, 64> opposite_edges;
        SmallVector<VertexId, 16> boundary_ends;
    };
    auto collect = [&](std::span<const ElementId> around, VertexId centre, Side& side) {
        for (const ElementId t : around) {
            const Simplex& tau = mesh.simplex(t);
            std::array<VertexId, 2> pair{};
            for (int i = 0, o = 0; i < 3; ++i) {
                const VertexId v = tau.vertex(i);
                if (v == centre) continue;
                side.vertices.push_back(v);
                pair[static_cast<std::size_t>(o++)] = v;  // canonical order: sorted
                // the face opposite v is the edge {centre, other}
                if (mesh.neighbor(t, i) == invalid_id) {
                    for (int j = 0; j < 3; ++j)
                        if (tau.vertex(j) != centre && tau.vertex(j) != v) side.boundary_ends.push_back(tau.vertex(j));
                }
            }
            side.opposite_edges.push_back(pair);
        }
    };
    Side at_from, at_to;
    collect(star_from, from, at_from);
    collect(star_to, to, at_to);
    auto holds = [](const auto& list, const auto& value) {
        return std::find(list.begin(), list.end(), value) != list.end();
    };
    // the third vertices of the triangles around the edge; is the edge on the boundary?
    SmallVector<VertexId, 4> opposite;
    bool edge_on_boundary = false;
    for (const ElementId t : star_from) {
        const Simplex& tau = mesh.simplex(t);
        if (!tau.contains(to)) continue;
        for (int i = 0; i < 3; ++i)
            if (tau.vertex(i) != from && tau.vertex(i) != to) {
                opposite.push_back(tau.vertex(i));
                edge_on_boundary = edge_on_boundary || mesh.neighbor(t, i) == invalid_id;
            }
    }
    for (const VertexId x : at_from.vertices)  // (1)
        if (x != to && holds(at_to.vertices, x) && !holds(opposite, x)) return false;
    if (!at_from.boundary_ends.empty() && !at_to.boundary_ends.empty() && !edge_on_boundary)
        return false;  // (2)
    for (const auto& pair : at_from.opposite_edges)  // (3)
        if (holds(at_to.opposite_edges, pair)) return false;
    for (const VertexId y : at_from.boundary_ends)  // (4)
        if (holds(at_to.boundary_ends, y)) return false;
    return true;
}

}  // namespace sxk::detail
