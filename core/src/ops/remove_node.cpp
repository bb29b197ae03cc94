// Node removal by ear flips (thesis §5.3.1, Fig. 5.10), made on a scratch copy of the link and
// written by one replace-elements call (§7.3).
#include "sxk/ops/remove_node.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <utility>

#include "sxk/quality.hpp"
#include "sxk/traversal.hpp"

namespace sxk {
namespace {

using Triangle = std::array<VertexId, 3>;  // counter-clockwise

constexpr std::array<Positions, 2> both_positions{Positions::reference, Positions::deformed};

// The triangle (a, b, c) is proper in both position sets: counter-clockwise (orient2d strictly
// positive) in the plane; not collinear on a surface in space.
bool turns_left_in_both(const Mesh& mesh, VertexId a, VertexId b, VertexId c) {
    return std::all_of(both_positions.begin(), both_positions.end(), [&](Positions s) {
        const Point &pa = position(mesh, a, s), &pb = position(mesh, b, s), &pc = position(mesh, c, s);
        if (mesh.ambient_dimension() == 3) return !collinear(pa, pb, pc);
        return orient2d(pa, pb, pc) == Sign::positive;
    });
}

// On a surface in space: the triangles t and u face the same way (their normals' dot product is
// strictly positive) in both position sets, so that replacing u by t does not fold the surface.
bool same_side_in_both(const Mesh& mesh, const Triangle& t, const Triangle& u) {
    return std::all_of(both_positions.begin(), both_positions.end(), [&](Positions s) {
        return normal_alignment(position(mesh, t[0], s), position(mesh, t[1], s), position(mesh, t[2], s),
                                position(mesh, u[0], s), position(mesh, u[1], s), position(mesh, u[2], s)) ==
               Sign::positive;
    });
}

// The angle at b between the directions to a and c (radians, doubles): which ear the thesis' rule
// prefers on a surface, where it is a heuristic (§5.3.1).
double angle_at(const Point& a, const Point& b, const Point& c) {
    const std::array<Point, 3> corners{b, a, c};
    return triangle_angles(corners)[0];
}

// The edge x-y exists in an element outside `around` (sorted): a new edge there would be a second
// copy of it (thesis Fig. 5.9; on a surface the link polygon can hold such a chord).
bool edge_outside(const Mesh& mesh, VertexId x, VertexId y, const std::vector<ElementId>& around) {
    for (const ElementId t : star(mesh, x))
        if (mesh.simplex(t).contains(y) && !std::binary_search(around.begin(), around.end(), t)) return true;
    return false;
}

// u lies in the closed counter-clockwise triangle (a, b, c) in the given positions.
bool in_closed_triangle(const Mesh& mesh, VertexId u, const Triangle& t, Positions s) {
    const Point& p = position(mesh, u, s);
    for (int i = 0; i < 3; ++i)
        if (orient2d(position(mesh, t[static_cast<std::size_t>(i)], s),
                     position(mesh, t[static_cast<std::size_t>((i + 1) % 3)], s),
                     p) == Sign::negative)
            return false;
    return true;
}

// v lies on the open segment w-u, exactly (in both position sets): the boundary is straight
// at v, and removing v keeps the domain.
bool strictly_between(const Mesh& mesh, VertexId w, VertexId v, VertexId u) {
    return std::all_of(both_positions.begin(), both_positions.end(), [&](Positions s) {
        const Point &a = position(mesh, w, s), &p = position(mesh, v, s), &b = position(mesh, u, s);
        if (mesh.ambient_dimension() == 3 ? !collinear(a, p, b) : orient2d(a, p, b) != Sign::zero)
            return false;
        // collinear: compare along an axis on which the segment is not degenerate
        const std::size_t k = a[0] != b[0] ? 0 : a[1] != b[1] ? 1 : 2;
        return std::min(a[k], b[k]) < p[k] && p[k] < std::max(a[k], b[k]);
    });
}

// Lawson flips restricted to the diagonals of the hole (edges shared by two scratch triangles):
// the polygon's own edges belong to the rest of the mesh and stay. A flip is made when the
// opposite vertex is strictly inside the circumcircle in `positions` AND both new triangles are
// strictly counter-clockwise in both position sets, so every step keeps a valid triangulation
// and each flip lowers the lifted surface in `positions` (termination).
void make_hole_delaunay(const Mesh& mesh, std::vector<Triangle>& triangles, Positions positions) {
    // the triangle holding the directed edge a -> b, and its third vertex
    auto find = [&](VertexId a, VertexId b, std::size_t& index, VertexId& third) {
        for (std::size_t i = 0; i < triangles.size(); ++i)
            for (std::size_t k = 0; k < 3; ++k)
                if (triangles[i][k] == a && triangles[i][(k + 1) % 3] == b) {
                    index = i;
                    third = triangles[i][(k + 2) % 3];
                    return true;
                }
        return false;
    };
    std::vector<std::pair<VertexId, VertexId>> stack;
    for (const Triangle& t : triangles)
        for (std::size_t k = 0; k < 3; ++k)
            stack.emplace_back(t[k], t[(k + 1) % 3]);
    // On a surface the unfolded criterion need not terminate (thesis §5.3.1: "it is not clear
    // whether this flipping criterion leads to a terminating algorithm"): a bound on the flips.
    std::size_t flips = 0;
    const std::size_t most = 8 * triangles.size() * triangles.size();
    while (!stack.empty() && flips < most) {
        const auto [a, b] = stack.back();
        stack.pop_back();
        std::size_t i0 = 0, i1 = 0;
        VertexId c = invalid_id, d = invalid_id;
        if (!find(a, b, i0, c) || !find(b, a, i1, d))
            continue;  // a polygon edge, or gone
        const Point &pa = position(mesh, a, positions), &pb = position(mesh, b, positions);
        const Point &pc = position(mesh, c, positions), &pd = position(mesh, d, positions);
        // on a surface the two triangles unfolded about their edge (thesis §5.3.1)
        const Sign fails = mesh.ambient_dimension() == 3 ? unfolded_incircle(pa, pb, pc, pd) : incircle(pa, pb, pc, pd);
        if (fails != Sign::positive)
            continue;
        if (!turns_left_in_both(mesh, a, d, c) || !turns_left_in_both(mesh, d, b, c))
            continue;
        if (mesh.ambient_dimension() == 3 && !same_side_in_both(mesh, {a, d, c}, {d, b, c}))
            continue;  // the flip would fold the surface over the new edge
        triangles[i0] = {a, d, c};
        triangles[i1] = {d, b, c};
        ++flips;
        for (auto edge : {std::pair{a, d}, std::pair{d, b}, std::pair{b, c}, std::pair{c, a}})
            stack.push_back(edge);
    }
}

}  // namespace

Outcome<std::vector<ElementId>> remove_node(Mesh& mesh, VertexId v, Positions positions) {
    if (mesh.topological_dimension() != 2)
        return Refusal{RefusalCode::wrong_dimension, "remove_node: needs a triangle mesh (topological dimension 2)"};
    if (v >= mesh.vertex_count())
        return Refusal{RefusalCode::not_found,
                       "remove_node: " + std::to_string(v) + " is not a vertex"};
    const std::vector<ElementId> around = star(mesh, v);
    const std::string vertex_text = "vertex " + std::to_string(v);
    if (around.empty())
        return Refusal{RefusalCode::not_applicable,
                       "remove_node: " + vertex_text + " is in no element"};

    // w_0, ..., w_{n-1} around an interior vertex, w_0, ..., w_n on the boundary
    const VertexFan link = fan_around(mesh, v);
    const bool interior = link.closed && link.ring.size() == around.size();
    const bool straight_boundary =
        !link.closed && link.ring.size() == around.size() + 1 &&
        strictly_between(mesh, link.ring.back(), v, link.ring.front());
    if (!interior && !straight_boundary)
        return Refusal{
            RefusalCode::moves_boundary,
            "remove_node: " + vertex_text +
                " is on the boundary and the boundary is not straight there (its removal "
                "would change the domain)"};
    // On a straight boundary the two boundary edges w_n-v and v-w_0 become one, w_n-w_0: a face
    // label (Medit/Gmsh boundary reference) they carry moves to it, if they agree.
    const auto edge_key = [](VertexId a, VertexId b) {
        return Simplex(+1, {std::min(a, b), std::max(a, b)});
    };
    std::optional<int> boundary_label;
    if (straight_boundary) {
        auto label_of = [&](VertexId a, VertexId b) -> std::optional<int> {
            const auto it = mesh.face_labels().find(edge_key(a, b));
            return it == mesh.face_labels().end() ? std::nullopt : std::optional<int>(it->second);
        };
        const std::optional<int> before = label_of(link.ring.back(), v),
                                 after = label_of(v, link.ring.front());
        auto text = [](const std::optional<int>& label) {
            return label ? std::to_string(*label) : std::string("none");
        };
        if (before != after)
            return Refusal{RefusalCode::label_conflict,
                           "remove_node: the boundary edges at " + vertex_text +
                           " carry different face labels (" + text(before) + " and " + text(after) +
                           ")"};
        boundary_label = before;
    }
    // An interior edge v-w carrying a face label (a constraint: an interface drawn as edges)
    // would vanish with v; on an open link the first and last edges are the boundary ones above.
    for (std::size_t i = 0; i < link.ring.size(); ++i) {
        if (!link.closed && (i == 0 || i + 1 == link.ring.size())) continue;
        const auto it = mesh.face_labels().find(edge_key(v, link.ring[i]));
        if (it != mesh.face_labels().end())
            return Refusal{RefusalCode::label_conflict,
                           "remove_node: the edge " + to_text(it->first) + " at " + vertex_text +
                           " carries face label " + std::to_string(it->second) +
                           " (a constraint)"};
    }
    for (ElementId t : around)
        for (Positions s : both_positions)
            if (element_orientation(mesh, t, s) != Sign::positive)  // on a surface: collinear
                return Refusal{RefusalCode::not_applicable,
                               "remove_node: element " + std::to_string(t) + " of the star of " +
                               vertex_text + " is not counter-clockwise in the " +
                               to_string(s) + " positions"};
    const auto [lowest, highest] = std::minmax_element(
        around.begin(), around.end(),
        [&](ElementId s, ElementId t) { return mesh.label(s) < mesh.label(t); });
    if (mesh.label(*lowest) != mesh.label(*highest))
        return Refusal{RefusalCode::label_conflict,
                       "remove_node: the star of " + vertex_text + " mixes element labels " +
                       std::to_string(mesh.label(*lowest)) + " and " +
                       std::to_string(mesh.label(*highest))};

    // Ear clipping on the scratch polygon (thesis: flip ears until v has degree 3).
    std::vector<VertexId> polygon = link.ring;
    std::vector<Triangle> triangles;
    auto ear_at = [&](std::size_t i) {
        const std::size_t n = polygon.size();
        return Triangle{polygon[(i + n - 1) % n], polygon[i], polygon[(i + 1) % n]};
    };
    const bool surface = mesh.ambient_dimension() == 3;
    std::vector<ElementId> sorted_star = around;
    std::sort(sorted_star.begin(), sorted_star.end());
    // A new triangle with the link edge x-y as a side faces the way v's triangle on that edge did;
    // a side that is a chord of the hole is checked against the new triangle across it at the end.
    auto faces_like_star = [&](const Triangle& t, VertexId x, VertexId y) {
        for (std::size_t k = 0; k < link.triangles.size(); ++k)
            if (link.ring[k] == x && link.next(k) == y) return same_side_in_both(mesh, t, {v, x, y});
        return true;
    };
    auto is_ear = [&](std::size_t i) {
        const Triangle ear = ear_at(i);
        if (!turns_left_in_both(mesh, ear[0], ear[1], ear[2]))
            return false;
        if (surface) {
            // on a surface: the ear faces the way the two triangles of v it replaces face, the rest
            // of v's star stays proper, and the new edge is not one the mesh has already (Fig. 5.9)
            return faces_like_star(ear, ear[0], ear[1]) && faces_like_star(ear, ear[1], ear[2]) &&
                   !edge_outside(mesh, ear[0], ear[2], sorted_star);
        }
        for (VertexId u : polygon) {
            if (u == ear[0] || u == ear[1] || u == ear[2])
                continue;
            for (Positions s : both_positions)
                if (in_closed_triangle(mesh, u, ear, s))
                    return false;
        }
        return true;
    };
    // thesis ear: flipping v-w_i is valid, i.e. v sees the chord w_{i-1}-w_{i+1} strictly
    auto is_thesis_ear = [&](std::size_t i) {
        const Triangle ear = ear_at(i);
        return turns_left_in_both(mesh, v, ear[0], ear[2]) && is_ear(i);
    };
    // on a surface, the thesis' ear (the angles at w_i opposite v sum to less than pi) decided in
    // doubles: among the valid ears the one whose angles sum least
    auto ear_angles = [&](std::size_t i) {
        const Triangle ear = ear_at(i);
        const Point &pv = mesh.deformed(v), &w = mesh.deformed(ear[1]);
        return angle_at(pv, w, mesh.deformed(ear[0])) + angle_at(pv, w, mesh.deformed(ear[2]));
    };
    while (polygon.size() > 3) {
        std::size_t chosen = polygon.size();
        if (surface) {
            double best = 0;
            for (std::size_t i = 0; i < polygon.size(); ++i)
                if (is_ear(i) && (chosen == polygon.size() || ear_angles(i) < best)) {
                    chosen = i;
                    best = ear_angles(i);
                }
        }
        for (std::size_t i = 0; i < polygon.size() && chosen == polygon.size(); ++i)
            if (is_thesis_ear(i))
                chosen = i;
        for (std::size_t i = 0; i < polygon.size() && chosen == polygon.size(); ++i)
            if (is_ear(i))
                chosen = i;
        if (chosen == polygon.size())
            return Refusal{RefusalCode::not_applicable,
                           "remove_node: no ear of the link of " + vertex_text +
                           " is valid in both the reference and the deformed positions"};
        triangles.push_back(ear_at(chosen));
        polygon.erase(polygon.begin() + static_cast<std::ptrdiff_t>(chosen));
    }
    // the last three: v's degree-3 star becomes one triangle (positive: the polygon is simple;
    // on a surface it must face the way the three triangles of v it replaces face)
    const Triangle last{polygon[0], polygon[1], polygon[2]};
    if (!turns_left_in_both(mesh, polygon[0], polygon[1], polygon[2]) ||
        (surface && !(faces_like_star(last, last[0], last[1]) && faces_like_star(last, last[1], last[2]) &&
                      faces_like_star(last, last[2], last[0]))))
        return Refusal{RefusalCode::not_applicable,
                       "remove_node: no ear of the link of " + vertex_text +
                       " is valid in both the reference and the deformed positions"};
    triangles.push_back({polygon[0], polygon[1], polygon[2]});
    // on a surface: no fold inside the hole either (the new triangles on a chord face one way)
    if (surface)
        for (std::size_t i = 0; i < triangles.size(); ++i)
            for (std::size_t j = i + 1; j < triangles.size(); ++j) {
                int shared = 0;
                for (const VertexId x : triangles[i]) shared += std::count(triangles[j].begin(), triangles[j].end(), x);
                if (shared == 2 && !same_side_in_both(mesh, triangles[i], triangles[j]))
                    return Refusal{RefusalCode::not_applicable,
                                   "remove_node: the triangles that would replace the star of " + vertex_text +
                                       " fold over each other"};
            }

    // thesis: "the involved edges are flipped back if they violate the empty-circle criterion"
    make_hole_delaunay(mesh, triangles, positions);

    std::vector<Simplex> simplexes;
    for (const Triangle& t : triangles)
        simplexes.emplace_back(+1, std::initializer_list<VertexId>{t[0], t[1], t[2]});
    const std::vector<int> labels(simplexes.size(), mesh.label(around.front()));
    auto replaced = mesh.replace_elements(around, simplexes, labels);
    if (!replaced)
        return replaced.refusal().prefixed("remove_node: ");
    if (boundary_label) {
        mesh.erase_face_label(edge_key(link.ring.back(), v));
        mesh.erase_face_label(edge_key(v, link.ring.front()));
        mesh.set_face_label(edge_key(link.ring.back(), link.ring.front()), *boundary_label);
    }
    return std::move(*replaced);
}

}  // namespace sxk
