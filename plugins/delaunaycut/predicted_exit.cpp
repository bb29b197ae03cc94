// The predicted exit (thesis §5.2.2, Fig. 5.7): "the exit point is predicted, and the cut is
// finished before the scalpel actually hits the boundary. At every step, the movement of the
// scalpel is extrapolated. When this extrapolation hits the boundary, and is close to the active
// node, the cut is finished: a node is inserted at the extrapolation, and the cut is dissected.
// [...] these edges are contracted. [...] The boundary edges that are created with this exit
// operation are added to a list of forbidden edges."
//
//      (a) the heading from a meets      (b) node x there      (c) a-x dissected     (d) the short
//          the boundary within eps_exit                                                  edges contracted
//      ----------X---------          -------x--------      ----x'  x-----        --x'     x--
//               /                           |                  |  |               /         \ .
//              a                            a                  a' a             ...         ...
//
// The heading is the scalpel's movement and, when the node lags behind the scalpel, the direction to
// the scalpel too (a scalpel that went out of the mesh sideways); a node that cannot move on at all
// also looks at the boundary nodes of its ring (a scalpel running along the boundary). A corner of the edge nearer the
// exit than eps_exit is the exit node itself (the edges the contraction makes are that short). The
// boundary must be the far edge of a triangle of the active node (or one of its neighbours), so that
// a-x is an edge; when it is one triangle further, the edge in between is flipped first. Otherwise
// the node moves on and the test is made again.
#include <cmath>

#include "cut_methods.hpp"
#include "sxk/edit_journal.hpp"
#include "sxk/ops/collapse_edge.hpp"
#include "sxk/ops/dissect.hpp"
#include "sxk/ops/flip_edge.hpp"
#include "sxk/ops/split_edge.hpp"

namespace sxk::delaunaycut {

namespace {

// Where the ray from the active node meets the boundary within reach: a corner `vertex`, or the
// edge (u, v) at `on_edge`; `through`: an interior edge crossed on the way (one at most).
struct BoundaryAhead {
    VertexId vertex = invalid_id;
    VertexId u = invalid_id, v = invalid_id;
    double on_edge = 0;
    Point point{};
    std::optional<FaceId> through;
};

std::optional<BoundaryAhead> boundary_ahead(const Mesh& mesh, VertexId a, const Point& reach) {
    const Point from = at(mesh, a);
    ElementId t = triangle_entered(mesh, a, from, reach);
    if (t == invalid_id) return std::nullopt;
    VertexId behind = a, came_through = invalid_id;
    Point cur = from;
    BoundaryAhead ahead;
    for (int crossed = 0; crossed < 2; ++crossed) {
        const Leaving leaving = leave_triangle(mesh, t, cur, reach, behind, came_through);
        if (leaving.kind == Leaving::Kind::stays) return std::nullopt;
        if (leaving.kind == Leaving::Kind::vertex) {
            if (crossed > 0 || !on_boundary(mesh, leaving.u)) return std::nullopt;
            ahead.vertex = leaving.u;
            ahead.point = leaving.point;
            return ahead;
        }
        const std::optional<FaceId> edge = edge_face(mesh, leaving.u, leaving.v);
        if (!edge) return std::nullopt;
        const FaceId mate = mesh.mate(*edge);
        const bool boundary = mate == invalid_id;
        if (boundary) {
            ahead.u = leaving.u;
            ahead.v = leaving.v;
            ahead.on_edge = leaving.on_edge;
            ahead.point = leaving.point;
            return ahead;
        }
        // one triangle further: through the edge (its face in t)
        const FaceId in_t = mesh.face_element(*edge) == t ? *edge : mate;
        ahead.through = in_t;
        const ElementId next = mesh.face_element(mesh.mate(in_t));
        came_through = mesh.opposite_vertex(next, mesh.mate(in_t));
        behind = invalid_id;
        cur = leaving.point;
        t = next;
    }
    return std::nullopt;
}

}  // namespace

Outcome<bool> DelaunayCutSession::try_exit(const Point& heading, const Point& target, CutStepReport& report,
                                           bool stuck) {
    for (int attempt = 0; attempt < 2; ++attempt) {
        const VertexId a = m_state.active;
        const Point pa = at(mesh(), a);
        std::vector<Point> directions{heading, Point{target[0] - pa[0], target[1] - pa[1], 0}};
        if (stuck) {
            // the boundary nodes of the ring within reach, but for the incision's own (its two ends)
            const VertexFan fan = fan_around(mesh(), a);
            for (std::size_t i = 1; i + 1 < fan.ring.size(); ++i) {
                const Point& p = at(mesh(), fan.ring[i]);
                if (distance(p, pa) <= eps_exit() && on_boundary(mesh(), fan.ring[i]))
                    directions.push_back({p[0] - pa[0], p[1] - pa[1], 0});
            }
        }
        std::optional<BoundaryAhead> ahead;
        for (const Point& direction : directions) {
            const double length = std::hypot(direction[0], direction[1]);
            if (length == 0) continue;
            const double reach = eps_exit() / length;
            ahead = boundary_ahead(mesh(), a, {pa[0] + reach * direction[0], pa[1] + reach * direction[1], 0});
            if (ahead) break;
        }
        if (!ahead) return false;
        EditStep exit_step(*EditJournal::of(mesh()));
        if (ahead->through) {
            // the boundary is one triangle further: make it the active node's own
            if (!flip_edge(mesh(), *ahead->through)) return false;
            if (auto kept = exit_step.commit(); !kept) return kept.refusal();
            ++report.flips;
            continue;
        }
        VertexId x = ahead->vertex;
        // a corner nearer the exit than eps_exit is the exit (no short boundary edge is made)
        if (x == invalid_id && distance(ahead->point, at(mesh(), ahead->u)) < eps_exit()) x = ahead->u;
        if (x == invalid_id && distance(ahead->point, at(mesh(), ahead->v)) < eps_exit()) x = ahead->v;
        if (x == invalid_id) {
            auto split = split_edge(mesh(), ahead->u, ahead->v, ahead->on_edge);
            if (!split) {
                // a crossing too near a corner to split: the corner
                x = ahead->on_edge < 0.5 ? ahead->u : ahead->v;
            } else {
                x = split->vertex;
                ++report.edges_split;
            }
        }
        DissectOptions dissecting;
        dissecting.cut_label = m_options.cut_label;
        const std::array<Simplex, 1> cut{Simplex(+1, {a, x})};
        auto opened = dissect(mesh(), cut, dissecting);
        if (!opened) return opened.refusal().prefixed("exit: ");
        if (!opened->opened.empty()) ++report.faces_dissected;
        // the short edges from the node (and its copy) to the exit node (and its copy) contracted
        std::vector<VertexId> nodes{a}, exits{x};
        for (const auto& [original, copy] : opened->new_vertices) (original == a ? nodes : exits).push_back(copy);
        CollapseOptions loose;
        loose.boundary_tolerance = 0.5;  // the incision's last edges may turn: the cut ends at x
        for (const VertexId from : nodes)
            for (const VertexId to : exits)
                if (edge_face(mesh(), from, to) && distance(at(mesh(), from), at(mesh(), to)) <= eps_exit() &&
                    collapse_edge(mesh(), from, to, loose)) {
                    ++report.collapses;
                    break;
                }
        if (auto kept = exit_step.commit(); !kept) return kept.refusal();
        ++report.exits;
        // the boundary edges at the exit are not entries until the scalpel is away from it
        m_state.forbidden.clear();
        for (const VertexId e : exits) {
            const VertexFan fan = fan_around(mesh(), e);
            if (fan.closed) continue;
            m_state.forbidden.push_back({e, fan.ring.front()});
            m_state.forbidden.push_back({fan.ring.back(), e});
        }
        m_state.exit_point = ahead->point;
        m_state.phase = Phase::outside;
        m_state.active = invalid_id;
        m_state.path.clear();
        return true;
    }
    return false;
}

}  // namespace sxk::delaunaycut
