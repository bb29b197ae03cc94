// Removing one flat triangle (thesis §3.2.3 for triangle meshes, planar or surfaces in space).
//
//   short edge (needle)          vertex v near the opposite edge ab (cap: a large angle at v)
//
//      a--b   collapse a-b              v                v              v
//     /    \ .                        /   \     flip    /|\    or     / | \ .
//                                   a-------b  ----->  a | b        a---m---b  split ab at
//                                     \   /             \|/           \ | /    v's foot m,
//                                       w                w              w      collapse m-v
//
// A needle collapses its shortest edge first (the thesis' move), then the others by length. A
// cap first flips ab (no vertex is added and nothing moves), else ab is split at v's foot and
// m-v collapsed (the spindle move in 2D). As for tetrahedra (try_moves), a move that makes a
// new flat triangle is undone while another may do without; moves longer than
// detail::longest_move times the longest edge are not tried.
#include <algorithm>
#include <array>
#include <vector>

#include "removal_steps.hpp"
#include "sxk/ops/flip_edge.hpp"
#include "sxk/ops/split_edge.hpp"
#include "sxk/traversal.hpp"

namespace sxk::degeneracy::detail {
namespace {

struct Move {
    enum class Kind { collapse_edge, flip_edge, split_edge } kind;
    double distance = 0;
    VertexId a = invalid_id, b = invalid_id, v = invalid_id;  // edge ab; v: the vertex near it
    double s = 0;                                              // v's foot on ab
    bool reverse = false;                                      // collapse the other way
};

// The face of the triangle {a, b, v} opposite v, found by vertices (an undone move renumbers
// elements).
FaceId edge_opposite(const Mesh& mesh, VertexId a, VertexId b, VertexId v) {
    for (const ElementId t : star(mesh, v))
        if (mesh.simplex(t).contains(a) && mesh.simplex(t).contains(b)) return mesh.opposite_face(t, v);
    return invalid_id;
}

Refused execute(Mesh& mesh, const Move& move, const Options& options) {
    switch (move.kind) {
        case Move::Kind::collapse_edge:
            return collapse_one_way(mesh, move.a, move.b, move.reverse, options);
        case Move::Kind::flip_edge: {
            const FaceId edge = edge_opposite(mesh, move.a, move.b, move.v);
            if (edge == invalid_id) return Refusal(RefusalCode::not_found,
                                                   "the flat triangle is gone");
            const auto flipped = flip_edge(mesh, edge);
            if (flipped) return std::nullopt;
            return flipped.refusal();
        }
        case Move::Kind::split_edge: {
            const std::array<VertexId, 1> vanishing{move.v};  // the flat triangle's pieces
            const auto split = split_edge(mesh, move.a, move.b, move.s, SplitOptions{vanishing});
            if (!split) return split.refusal();
            return collapse_one_way(mesh, split->vertex, move.v, move.reverse, options);
        }
    }
    return Refusal(RefusalCode::internal_error, "unknown move");
}

void count(const Move& move, Tally& tally) {
    if (move.kind == Move::Kind::flip_edge) {
        ++tally.flips;
        return;
    }
    ++tally.collapses;
    if (move.kind == Move::Kind::split_edge) ++tally.splits;
}

}  // namespace

Refused collapse_flat_triangle(Mesh& mesh, ElementId t, const Options& options, Tally& tally,
                               MoveStep& step, Effort effort, MoveStep* inner) {
    const Simplex tau = mesh.simplex(t);
    std::array<VertexId, 3> p{};
    std::array<Point, 3> x{};
    for (std::size_t i = 0; i < 3; ++i) {
        p[i] = tau.vertex(static_cast<int>(i));
        x[i] = position(mesh, p[i], options.positions);
    }
    double longest = 0;
    for (std::size_t i = 0; i < 3; ++i) longest = std::max(longest, distance(x[i], x[(i + 1) % 3]));
    const bool cap = classify_element(mesh, t, options) == DegenerateClass::cap;

    std::vector<Move> moves;
    for (std::size_t i = 0; i < 3; ++i) {
        const std::size_t j = (i + 1) % 3, k = (i + 2) % 3;
        moves.push_back({Move::Kind::collapse_edge, distance(x[i], x[j]), p[i], p[j]});
        const Foot foot = foot_on_line(x[i], x[j], x[k]);
        if (foot.s > end_margin && foot.s < 1 - end_margin) {
            moves.push_back({Move::Kind::flip_edge, foot.distance, p[i], p[j], p[k], foot.s});
            moves.push_back({Move::Kind::split_edge, foot.distance, p[i], p[j], p[k], foot.s});
        }
    }
    std::erase_if(moves, [&](const Move& m) { return m.distance > longest_move * longest; });
    // the thesis' order: a cap's vertex-edge moves first (flip before split), a needle's
    // shortest edge first
    auto rank = [&](const Move& m) {
        if (m.kind == Move::Kind::collapse_edge) return cap ? 1 : 0;
        return cap ? 0 : 1;
    };
    std::stable_sort(moves.begin(), moves.end(), [&](const Move& m1, const Move& m2) {
        if (rank(m1) != rank(m2)) return rank(m1) < rank(m2);
        return m1.distance < m2.distance;
    });
    if (moves.empty()) return Refusal(RefusalCode::not_applicable,
                                      "no flip, split or collapse fits its shape");
    std::vector<Move> both;
    for (const Move& move : moves) {
        both.push_back(move);
        if (move.kind == Move::Kind::flip_edge) continue;
        both.push_back(move);
        both.back().reverse = true;
    }
    return try_moves_of(
        mesh, t, std::span<const Move>(both), options, tally, step, effort, inner,
        [&](const Move& move) { return execute(mesh, move, options); }, count, collapse_flat_triangle);
}

}  // namespace sxk::degeneracy::detail
