// The subdivision cutter (thesis §5.4: "a subdivision approach, where each sliced triangle is
// replaced by three triangles"; Fig. 5.2): the baseline Delaunay cutting is measured against.
//
//            w                          w             The path enters triangle (P, v, w) at P, the
//          /   \                      / | \           cut's last node, and leaves it through v-w at
//        /   ~~~~X     --->         /   |   X         X: v-w is split at X (its other triangle too),
//      P ~~~     \                P ----+--/ \        which makes P-X an edge, and P-X is dissected.
//        \         \                \   | /   \       The triangle the path crossed is three, and
//          v ------                   v --               the cut runs through every crossing.
//
// The cut lags at most one triangle behind the scalpel: the crossing it leaves by is not known
// before it leaves (the thesis' subdivision moves a temporary subdivision along with the scalpel
// inside the triangle, which is only drawn; what stays is this). Each crossing is where the segment
// from the cut's last node to the scalpel crosses the edge: with the path's samples inside a
// triangle it is the chord the cut follows anyway, and a walk that starts at a node (not at a
// crossing point rounded to doubles) cannot turn back.
//
// A crossing so near a corner that the split would make a flat triangle is that corner; the
// triangles the cut leaves are as thin as the path makes them (thesis Fig. 5.2).
#include "cut_methods.hpp"
#include "sxk/ops/dissect.hpp"
#include "sxk/ops/split_edge.hpp"

namespace sxk::delaunaycut {

Outcome<Done> SubdivisionCutSession::move(const Point& from, const Point& to, CutStepReport& report) {
    Point scalpel = from;
    VertexId previous = invalid_id;  // the node the cut came from in this movement
    // every round crosses an edge, or enters; a movement crosses a bounded number of edges
    for (std::size_t round = 0; round < 100000; ++round) {
        if (m_state.phase == Phase::outside) {
            const std::optional<Entry> entry = first_entry(scalpel, to);
            if (!entry) return Done{};
            auto node = node_on_edge(entry->u, entry->v, entry->on_edge, report);
            if (!node) return node.refusal().prefixed("entry: ");
            m_state.active = *node;
            m_state.phase = Phase::cutting;
            ++report.entries;
            scalpel = at(mesh(), *node);
            continue;
        }
        // The cut goes on from its last node towards the scalpel: the crossings of that segment are
        // where the path crossed the edges up to rounding, and walking from a node (not from a
        // crossing point computed in doubles) never turns back to the node before.
        const VertexId last = m_state.active;
        const Point start = at(mesh(), last);
        const ElementId t = triangle_entered(mesh(), last, start, to);
        if (t == invalid_id)
            return Refusal{RefusalCode::internal_error, "subdivision: the cut's last node is in no triangle"};
        const Leaving leaving = leave_triangle(mesh(), t, start, to, last, invalid_id);
        // `to` in a triangle of the last node, or back across the incision: the cut waits there
        if (leaving.kind == Leaving::Kind::stays) return Done{};
        VertexId node = leaving.u;
        bool leaves_mesh = false;
        if (leaving.kind == Leaving::Kind::edge) {
            const std::optional<FaceId> edge = edge_face(mesh(), leaving.u, leaving.v);
            leaves_mesh = edge && mesh().mate(*edge) == invalid_id;
            auto made = node_on_edge(leaving.u, leaving.v, leaving.on_edge, report);
            if (!made) return made.refusal();
            node = *made;
        } else {
            leaves_mesh = on_boundary(mesh(), node);
        }
        // A crossing rounded onto a corner can send the walk from that corner straight back (the
        // segment runs along an edge to within rounding): the cut waits at its last node then.
        if (node == previous) return Done{};
        previous = last;
        if (auto cut = cut_to(node, report); !cut) return cut;
        scalpel = at(mesh(), node);
        if (leaves_mesh) {
            ++report.exits;
            m_state.phase = Phase::outside;
            m_state.active = invalid_id;
        }
    }
    return Refusal{RefusalCode::internal_error, "subdivision: the movement crosses too many edges"};
}

Outcome<VertexId> SubdivisionCutSession::node_on_edge(VertexId u, VertexId v, double on_edge, CutStepReport& report) {
    if (on_edge <= 0) return u;
    if (on_edge >= 1) return v;
    auto split = split_edge(mesh(), u, v, on_edge);
    if (!split) return on_edge < 0.5 ? u : v;  // so near a corner that a child would be flat
    ++report.edges_split;
    return split->vertex;
}

Outcome<Done> SubdivisionCutSession::cut_to(VertexId node, CutStepReport& report) {
    const VertexId last = m_state.active;
    if (node != last) {
        DissectOptions dissecting;
        dissecting.cut_label = m_options.cut_label;
        const std::array<Simplex, 1> cut{Simplex(+1, {last, node})};
        auto opened = dissect(mesh(), cut, dissecting);
        if (!opened) return opened.refusal().prefixed("subdivision: ");
        if (!opened->opened.empty()) ++report.faces_dissected;
    }
    m_state.active = node;
    return Done{};
}

}  // namespace sxk::delaunaycut
