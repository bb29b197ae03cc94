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
// inside the triangle, which is only drawn; what stays is this).
#include "cut_methods.hpp"
#include "sxk/ops/dissect.hpp"
#include "sxk/ops/split_edge.hpp"

namespace sxk::delaunaycut {

Outcome<Done> SubdivisionCutSession::move(const Point& from, const Point& to, CutStepReport& report) {
    Point scalpel = from;
    // every round crosses an edge, enters or leaves; a movement crosses a bounded number of edges
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
        const VertexId last = m_state.active;
        const bool at_last = scalpel == at(mesh(), last);
        const ElementId t = triangle_entered(mesh(), last, scalpel, to);
        if (t == invalid_id) {  // not around the last node: it went out of the mesh there
            m_state.phase = Phase::outside;
            m_state.active = invalid_id;
            continue;
        }
        const Leaving leaving = leave_triangle(mesh(), t, scalpel, to, at_last ? last : invalid_id, invalid_id);
        if (leaving.kind == Leaving::Kind::stays) return Done{};
        if (leaving.kind == Leaving::Kind::edge && (leaving.u == last || leaving.v == last)) {
            // back across an edge at the last node: into its next triangle, or out through the incision
            const std::optional<FaceId> edge = edge_face(mesh(), leaving.u, leaving.v);
            if (edge && mesh().mate(*edge) == invalid_id) {
                m_state.phase = Phase::outside;
                m_state.active = invalid_id;
            }
            scalpel = leaving.point;
            continue;
        }
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
