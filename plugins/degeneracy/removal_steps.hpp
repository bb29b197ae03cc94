// The steps of remove_degeneracies, one file each: collapsing a flat tetrahedron or triangle
// (split + collapse, thesis Fig. 3.9), flipping an element out, cutting elements free.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "move_step.hpp"
#include "remove_degeneracies.hpp"
#include "sxk/mesh.hpp"
#include "sxk/predicates.hpp"
#include "sxk/point_math.hpp"

namespace sxk::degeneracy::detail {

// What the steps did, summed into the pass report.
struct Tally {
    std::size_t collapses = 0;
    std::size_t splits = 0;  // kept splits
    std::size_t flips = 0;
};

// What a step returns: nothing when it did its work, else the refusal of its last attempt (a
// kernel operation's, with its code, or the step's own).
using Refused = std::optional<Refusal>;

// How hard a removal tries (try_moves' rounds).
enum class Effort {
    clean,      // only moves that make no degenerate element
    paying,     // also moves that leave fewer degenerates, or none worse than the element
    follow_up,  // also moves whose new degenerates each go by a clean move right after
    any,        // also any move that succeeds, as the thesis keeps every collapse: the last
                // stage before cutting free, for what even follow-ups could not remove
};

// Removes the flat tetrahedron t by a collapse, after one or two splits where its shape asks
// for them (collapse_flat_tetrahedron.cpp). Returns nothing when t is gone, else why the last
// attempt was refused (the mesh is then as before, ids included).
// With Effort::follow_up, `inner` is the step of the follow-up moves (nested in `move`'s).
Refused collapse_flat_tetrahedron(Mesh& mesh, ElementId t, const Options& options, Tally& tally,
                                  MoveStep& step, Effort effort = Effort::paying,
                                  MoveStep* inner = nullptr);
// The same for a flat triangle (collapse_flat_triangle.cpp): a collapse, an edge flip, or a
// split and a collapse.
Refused collapse_flat_triangle(Mesh& mesh, ElementId t, const Options& options, Tally& tally,
                               MoveStep& step, Effort effort = Effort::paying,
                               MoveStep* inner = nullptr);
// Removes tetrahedron t by the 2-3, 3-2 or 4-4 flip whose new elements are best shaped, if
// none of them is degenerate (flip_out.cpp). Nothing on success.
Refused flip_out(Mesh& mesh, ElementId t, const Options& options, Tally& tally);
// Removes t when it has a face on the boundary and lies within options.boundary_tolerance of
// the plane of each such face (peel_off_boundary.cpp): its other faces become the boundary, no
// crack. Nothing on success.
Refused peel_off_boundary(Mesh& mesh, ElementId t, const Options& options);
// Cuts the elements free (dissect along all their faces, thesis §7.3) and removes them
// (cut_free.cpp): the cracks. Refuses, mesh untouched, when dissect or the removal does.
Outcome<Done> cut_free(Mesh& mesh, std::span<const ElementId> elements);

// Collapses a into b (reverse: b into a) with the boundary tolerance of the options; nothing
// on success (split_and_collapse.cpp).
Refused collapse_one_way(Mesh& mesh, VertexId a, VertexId b, bool reverse, const Options& options);

// ---- geometry in the measured positions -----------------------------------------------------

inline double distance(const Point& a, const Point& b) { return std::sqrt(dot(minus(a, b), minus(a, b))); }

// Thesis aspect ratio of the simplex with these vertices (3 or 4), in the measured positions.
double aspect_ratio_of(const Mesh& mesh, std::span<const VertexId> vertices, Positions positions);
// Aspect ratio and class of element t (DegenerateClass; triangles: needle or cap).
double element_aspect_ratio(const Mesh& mesh, ElementId t, Positions positions);
DegenerateClass classify_element(const Mesh& mesh, ElementId t, const Options& options);

// Parameter s of the foot of p on the line a-b (0 at a, 1 at b) and the distance to it.
struct Foot {
    double s = 0;
    double distance = 0;
};
Foot foot_on_line(const Point& a, const Point& b, const Point& p);

// Splits at parameters in (0,1) closer than this to an end are not tried: the vertex is then
// next to that end, and collapsing that edge is the same move without the split.
inline constexpr double end_margin = 1e-3;
// Moves longer than this times the element's longest edge are not tried: they would reshape
// the neighbours, not remove a flat element (its height is below aspect_ratio times that edge).
inline constexpr double longest_move = 0.25;

// The smallest aspect ratio of the elements (1 for none), and how many are degenerate.
struct Shapes {
    double worst = 1;
    std::size_t degenerate = 0;
};
Shapes shapes_of(const Mesh& mesh, std::span<const ElementId> elements, const Options& options);
Shapes shapes_of(const Mesh& mesh, std::span<const Simplex> simplexes, const Options& options);

// Some element containing all these vertices (a face's, an element's), or invalid_id: found in
// the star of the first one.
ElementId element_containing(const Mesh& mesh, std::span<const VertexId> vertices);
// The element with these vertices (sorted, sign +1), or invalid_id.
ElementId element_with(const Mesh& mesh, const Simplex& vertices);

// Tries the moves in order, each one step (MoveStep) rolled back when refused part way or when
// it does not pay. Beyond the thesis, which keeps every collapse that succeeds: a removal that makes
// another degenerate only moves the problem, and repeated passes then churn. Round 1 keeps a
// move only if it makes no degenerate element; when every move does, round 2 keeps the first
// move that leaves fewer degenerates than it removed, or none worse than the element itself
// (`before`); round 3 (Effort::follow_up, for what the passes could not remove) keeps a move
// whose new degenerates `follow_up` (their vertex sets) removes by clean moves at once, the
// rollback then undoing move and follow-ups together if that fails; round 4 (Effort::any) keeps
// the first move that succeeds. `execute(move)` returns a refusal or nothing; `count(move)`
// books a kept move. Returns nothing when a move was kept, else the last refusal.
template <class Move, class Execute, class Count, class FollowUp>
Refused try_moves(Mesh& mesh, std::span<const Move> moves, double before, const Options& options,
                  MoveStep& step, Effort effort, Execute execute, Count count, FollowUp follow_up) {
    // Round 1 does every move once and notes of each whether an operation refused it (later
    // rounds skip it) and whether round 2 would keep it. A move done again from the same mesh
    // makes the same shapes (the rollback restores the mesh, ids included), so rounds 2 and 4 do
    // again only the move they keep, not every move (issue 47, defect 10).
    enum class Tried : char { refused, succeeded, pays_round_2 };
    std::vector<Tried> tried(moves.size(), Tried::refused);
    const int rounds = effort == Effort::clean ? 1 : effort == Effort::paying ? 2 : effort == Effort::follow_up ? 3 : 4;
    // the last refusal, and the last "does not pay" (later rounds said it last, once)
    Refused why, not_paying;
    auto keep = [&](const Move& move) {
        step.keep();
        count(move);
        return Refused{};
    };
    for (int round = 0; round < rounds; ++round)
        for (std::size_t i = 0; i < moves.size(); ++i) {
            if (round > 0 && tried[i] == Tried::refused) continue;
            if (round == 1 && tried[i] != Tried::pays_round_2) continue;
            step.begin();
            Refused refusal = execute(moves[i]);
            if (!refusal) {
                if (round == 1 || round == 3) return keep(moves[i]);  // as round 1 found
                const std::vector<ElementId> created = step.created();
                const Shapes made = shapes_of(mesh, created, options);
                bool pays = made.degenerate == 0;
                if (round == 0 && !pays) {
                    tried[i] = Tried::succeeded;
                    if (rounds > 1 && (made.degenerate < shapes_of(mesh, step.removed(), options).degenerate ||
                                       made.worst > before))
                        tried[i] = Tried::pays_round_2;
                }
                if (round == 2) {
                    std::vector<Simplex> flat;
                    for (const ElementId t : created)
                        if (element_aspect_ratio(mesh, t, options.positions) < options.aspect_ratio)
                            flat.emplace_back(+1, mesh.simplex(t).vertices());
                    pays = follow_up(flat) && shapes_of(mesh, step.created(), options).degenerate == 0;
                }
                if (pays) return keep(moves[i]);
                refusal =
                    Refusal(RefusalCode::not_applicable,
                            "every move leaves a degenerate element (this one: aspect ratio " +
                                std::to_string(made.worst) + ")");
                not_paying = refusal;
            }
            step.undo();
            why = std::move(refusal);
        }
    return rounds > 1 && not_paying ? not_paying : why;
}

// try_moves for a removal step `remove(mesh, element, options, tally, step, effort, inner)`
// (collapse_flat_tetrahedron, collapse_flat_triangle) on element t: its follow-ups are the same
// removal with Effort::clean in the inner step, and what they do is booked with the move they
// follow. Effort::follow_up needs `inner`; without it the step tries no harder than paying.
template <class Move, class Execute, class Count, class Remove>
Refused try_moves_of(Mesh& mesh, ElementId t, std::span<const Move> moves, const Options& options,
                     Tally& tally, MoveStep& step, Effort effort, MoveStep* inner,
                         Execute execute, Count count, Remove remove) {
    const double before = element_aspect_ratio(mesh, t, options.positions);
    Tally follow_ups;
    auto follow_up = [&](const std::vector<Simplex>& flat) {
        follow_ups = {};
        for (const Simplex& key : flat) {
            const ElementId e = element_with(mesh, key);
            if (e == invalid_id || element_aspect_ratio(mesh, e, options.positions) >= options.aspect_ratio) continue;
            if (remove(mesh, e, options, follow_ups, *inner, Effort::clean, nullptr)) return false;
        }
        return true;
    };
    return try_moves(
        mesh, moves, before, options, step, inner ? effort : std::min(effort, Effort::paying), execute,
        [&](const Move& move) {
            count(move, tally);
            tally.collapses += follow_ups.collapses;
            tally.splits += follow_ups.splits;
            tally.flips += follow_ups.flips;
        },
        follow_up);
}

}  // namespace sxk::degeneracy::detail
