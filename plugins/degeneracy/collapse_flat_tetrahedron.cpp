// Removing one flat tetrahedron by a collapse (thesis §3.2.3, Figs. 3.8-3.9).
//
// A flat tetrahedron has its four vertices near one plane, and one of four things makes it
// flat, each with a short distance between two points that one collapse can merge:
//
//   two vertices close together        (needle)   collapse that edge
//   a vertex v close to an edge ab     (spindle)  split ab at v's foot m, collapse m-v
//   two edges ab, cd passing close     (sliver)   split each at the closest points, collapse
//   a vertex d close to the face abc   (cap)      split abc at d's foot m, collapse m-d
//
// The thesis picks the move by the number of large dihedral angles; that move is tried first
// (unless it is long: see moves_for). When the checks refuse it (link condition, boundary,
// orientation in either position set), the other moves are tried by increasing distance, up to
// detail::longest_move times the longest edge, each collapse both ways. Beyond the thesis, a
// move must pay (try_moves in removal_steps.hpp: no new flat element, or fewer, or better
// shapes, or new ones that follow-up moves remove); one that does not is undone (a rolled-back MoveStep)
// and the next is tried. Every failed try leaves the mesh as it was, up to element ids.
#include <algorithm>
#include <array>
#include <utility>
#include <vector>

#include "move_step.hpp"
#include "removal_steps.hpp"
#include "sxk/ops/split_edge.hpp"
#include "sxk/ops/split_face.hpp"
#include "sxk/quality.hpp"
#include "sxk/traversal.hpp"

namespace sxk::degeneracy::detail {
namespace {

struct Move {
    enum class Kind { collapse_edge, split_edge, split_two_edges, split_face } kind;
    double distance = 0;  // between the two points the collapse merges
    bool thesis = false;  // the move the thesis prescribes for the class
    // collapse_edge: v0-v1. split_edge: edge v0-v1 at s, then m-v2. split_two_edges: v0-v1 at
    // s and v2-v3 at u, then m2-m1. split_face: the face v0 v1 v2 (sorted) opposite v3, at
    // weights w, then m-v3.
    std::array<VertexId, 4> v{};
    double s = 0, u = 0;
    std::array<double, 3> w{};
    bool reverse = false;  // collapse the other way: the old vertex into the new one (or b into a)
};

// Edges of a tetrahedron by dihedral_angles' order: (01, 02, 03, 12, 13, 23).
constexpr std::array<std::pair<int, int>, 6> edges{{{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}}};

// Does the move's edits; nothing on success. A refusal part way (the collapse after the
// split) leaves the split: the caller's step rolls it back.
Refused execute(Mesh& mesh, const Move& move, const Options& options) {
    switch (move.kind) {
        case Move::Kind::collapse_edge:
            return collapse_one_way(mesh, move.v[0], move.v[1], move.reverse, options);
        case Move::Kind::split_edge: {
            // the elements with ab and v vanish in the collapse: the flat one among them may be
            // split into flat pieces (SplitOptions)
            const std::array<VertexId, 1> vanishing{move.v[2]};
            const auto split = split_edge(mesh, move.v[0], move.v[1], move.s, SplitOptions{vanishing});
            if (!split) return split.refusal();
            return collapse_one_way(mesh, split->vertex, move.v[2], move.reverse, options);
        }
        case Move::Kind::split_two_edges: {
            // the flat element (the one with both edges) and its pieces vanish in the collapse
            const std::array<VertexId, 2> with_cd{move.v[2], move.v[3]};
            const auto first = split_edge(mesh, move.v[0], move.v[1], move.s, SplitOptions{with_cd});
            if (!first) return first.refusal();
            const std::array<VertexId, 1> with_m1{first->vertex};
            const auto second = split_edge(mesh, move.v[2], move.v[3], move.u, SplitOptions{with_m1});
            if (!second) return second.refusal();
            return collapse_one_way(mesh, second->vertex, first->vertex, move.reverse, options);
        }
        case Move::Kind::split_face: {
            // The face abc opposite d, looked up again: an undone move before this one may have
            // given the flat element a new id. It is the face of the element {a,b,c,d}.
            FaceId face = invalid_id;
            const std::array<VertexId, 3> abc{move.v[0], move.v[1], move.v[2]};  // sorted
            for (const ElementId t : star(mesh, move.v[3])) {
                const Simplex& tau = mesh.simplex(t);
                if (tau.contains(abc[0]) && tau.contains(abc[1]) && tau.contains(abc[2])) {
                    face = mesh.opposite_face(t, move.v[3]);
                    break;
                }
            }
            if (face == invalid_id) return Refusal(RefusalCode::not_found,
                                                   "the face to split is gone");
            const std::array<VertexId, 1> vanishing{move.v[3]};
            const auto split = split_face(mesh, face, move.w, SplitOptions{vanishing});
            if (!split) return split.refusal();
            return collapse_one_way(mesh, split->vertex, move.v[3], move.reverse, options);
        }
    }
    return Refusal(RefusalCode::internal_error, "unknown move");
}

void count(const Move& move, Tally& tally) {
    ++tally.collapses;
    if (move.kind == Move::Kind::split_edge || move.kind == Move::Kind::split_face) tally.splits += 1;
    if (move.kind == Move::Kind::split_two_edges) tally.splits += 2;
}

// Every move with a short distance for the flat tetrahedron with vertices p (positions x),
// the thesis' move for its class marked.
std::vector<Move> moves_for(const Mesh& mesh, ElementId t, const Options& options) {
    const Simplex& tau = mesh.simplex(t);
    std::array<VertexId, 4> p{};
    std::array<Point, 4> x{};
    for (std::size_t i = 0; i < 4; ++i) {
        p[i] = tau.vertex(static_cast<int>(i));
        x[i] = position(mesh, p[i], options.positions);
    }
    double longest = 0;
    for (const auto& [i, j] : edges) longest = std::max(longest, distance(x[i], x[j]));
    const double reach = longest_move * longest;

    // the thesis' class (Fig. 3.8) by the large dihedral angles
    const std::array<double, 6> angles = dihedral_angles(x);
    std::vector<int> large;
    for (int e = 0; e < 6; ++e)
        if (angles[static_cast<std::size_t>(e)] > options.large_angle) large.push_back(e);

    std::vector<Move> moves;
    // needles: collapse an edge; the thesis takes the shortest
    int shortest = 0;
    for (int e = 0; e < 6; ++e) {
        const auto [i, j] = edges[static_cast<std::size_t>(e)];
        const double length = distance(x[i], x[j]);
        if (length < distance(x[edges[static_cast<std::size_t>(shortest)].first],
                               x[edges[static_cast<std::size_t>(shortest)].second]))
            shortest = e;
        Move move{Move::Kind::collapse_edge, length, false, {p[i], p[j], 0, 0}};
        moves.push_back(move);
    }
    if (large.empty()) moves[static_cast<std::size_t>(shortest)].thesis = true;

    // spindles: a vertex near the opposite... any edge it is not on
    for (int e = 0; e < 6; ++e) {
        const auto [i, j] = edges[static_cast<std::size_t>(e)];
        const auto [k, l] = edges[static_cast<std::size_t>(5 - e)];  // the opposite edge
        for (const int v : {k, l}) {
            const Foot foot = foot_on_line(x[i], x[j], x[v]);
            if (foot.s <= end_margin || foot.s >= 1 - end_margin) continue;
            Move move{Move::Kind::split_edge, foot.distance, false,
                      {p[i], p[j], p[v], 0}, foot.s};
            // the thesis splits the edge opposite the single large angle (at edge k-l)
            move.thesis = large.size() == 1 && large[0] == 5 - e;
            moves.push_back(move);
        }
    }

    // slivers: the two opposite edges (i,j), (k,l) pass close to each other
    for (int e = 0; e < 3; ++e) {
        const auto [i, j] = edges[static_cast<std::size_t>(e)];
        const auto [k, l] = edges[static_cast<std::size_t>(5 - e)];
        const Point d1 = minus(x[j], x[i]), d2 = minus(x[l], x[k]), r = minus(x[i], x[k]);
        const double a11 = dot(d1, d1), a22 = dot(d2, d2), a12 = dot(d1, d2);
        const double b1 = dot(d1, r), b2 = dot(d2, r);
        const double denominator = a11 * a22 - a12 * a12;
        if (!(denominator > 1e-12 * a11 * a22)) continue;  // (nearly) parallel
        const double s = (a12 * b2 - a22 * b1) / denominator;
        const double u = (a11 * b2 - a12 * b1) / denominator;
        if (s <= end_margin || s >= 1 - end_margin || u <= end_margin || u >= 1 - end_margin) continue;
        const Point on1{x[i][0] + s * d1[0], x[i][1] + s * d1[1], x[i][2] + s * d1[2]};
        const Point on2{x[k][0] + u * d2[0], x[k][1] + u * d2[1], x[k][2] + u * d2[2]};
        Move move{Move::Kind::split_two_edges, distance(on1, on2), false, {p[i], p[j], p[k], p[l]}, s, u};
        move.thesis = large.size() == 2 && ((large[0] == e && large[1] == 5 - e));
        moves.push_back(move);
    }

    // caps: vertex d over the face opposite it, its foot inside the face
    for (std::size_t d = 0; d < 4; ++d) {
        std::array<std::size_t, 3> f{};
        for (std::size_t i = 0, n = 0; i < 4; ++i)
            if (i != d) f[n++] = i;
        // sorted vertex ids of the face, for split_face's weights
        std::sort(f.begin(), f.end(), [&](std::size_t a, std::size_t b) { return p[a] < p[b]; });
        const Point n = cross(minus(x[f[1]], x[f[0]]), minus(x[f[2]], x[f[0]]));
        const double nn = dot(n, n);
        if (!(nn > 0)) continue;
        const double height = dot(minus(x[d], x[f[0]]), n) / nn;
        const Point foot{x[d][0] - height * n[0], x[d][1] - height * n[1], x[d][2] - height * n[2]};
        std::array<double, 3> w{};
        for (std::size_t q = 0; q < 3; ++q)
            w[q] = dot(cross(minus(x[f[(q + 1) % 3]], foot), minus(x[f[(q + 2) % 3]], foot)), n) / nn;
        if (*std::min_element(w.begin(), w.end()) <= end_margin) continue;
        Move move{Move::Kind::split_face, std::abs(height) * std::sqrt(nn), false,
                  {p[f[0]], p[f[1]], p[f[2]], p[d]}};
        move.w = w;
        // the thesis splits the face opposite the three large angles (their common vertex)
        if (large.size() >= 3) {
            const auto at_d = std::count_if(large.begin(), large.end(), [&](int e) {
                const auto [i, j] = edges[static_cast<std::size_t>(e)];
                return static_cast<std::size_t>(i) == d || static_cast<std::size_t>(j) == d;
            });
            move.thesis = at_d >= 3;
        }
        moves.push_back(move);
    }

    // The thesis' move first, unless it is a long one: a flat element with no large angle
    // above the threshold but no short edge either (a TetGen sliver whose largest dihedral
    // angle is 173 degrees is a "needle" by the count) would collapse an edge as long as its
    // neighbours' and make new flat elements; the short moves come first then, the long one
    // last. Other long moves are not tried.
    std::erase_if(moves, [&](const Move& move) { return !move.thesis && move.distance > reach; });
    auto rank = [&](const Move& move) { return move.thesis ? (move.distance <= reach ? 0 : 2) : 1; };
    std::stable_sort(moves.begin(), moves.end(), [&](const Move& a, const Move& b) {
        if (rank(a) != rank(b)) return rank(a) < rank(b);
        return a.distance < b.distance;
    });
    // each collapse both ways: the new vertex into the old one first (the old one stays where
    // the cut put it), then the other way
    std::vector<Move> both;
    for (const Move& move : moves) {
        both.push_back(move);
        both.push_back(move);
        both.back().reverse = true;
    }
    return both;
}

}  // namespace

Refused collapse_flat_tetrahedron(Mesh& mesh, ElementId t, const Options& options, Tally& tally,
                                  MoveStep& step, Effort effort, MoveStep* inner) {
    const std::vector<Move> moves = moves_for(mesh, t, options);
    if (moves.empty()) return Refusal(RefusalCode::not_applicable,
                                      "no split or collapse fits its shape");
    return try_moves_of(
        mesh, t, std::span<const Move>(moves), options, tally, step, effort, inner,
        [&](const Move& move) { return execute(mesh, move, options); }, count, collapse_flat_tetrahedron);
}

}  // namespace sxk::degeneracy::detail
