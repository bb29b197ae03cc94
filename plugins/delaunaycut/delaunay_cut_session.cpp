// Delaunay cutting's movement (thesis §5.2.2): the phases of planar_cut.hpp, one piece at a time.
#include <algorithm>
#include <cmath>
#include <string>

#include "cut_methods.hpp"
#include "sxk/ops/split_edge.hpp"

namespace sxk::delaunaycut {

Outcome<Done> DelaunayCutSession::move(const Point& from, const Point& to, CutStepReport& report) {
    // The thesis' scalpel is a mouse: many short movements. A long one is cut in pieces of a
    // quarter of the mean edge, so that the incision is split behind the node as it goes, not once
    // after a long drag (the 3D version subdivides large movements too, Fig. 5.11).
    const double length = distance(from, to);
    const auto pieces = static_cast<std::size_t>(std::ceil(length / (0.25 * m_mean_edge)));
    Point start = from;
    for (std::size_t i = 1; i <= std::max<std::size_t>(pieces, 1); ++i) {
        const Point end = i >= pieces ? to : lerp(from, to, static_cast<double>(i) / static_cast<double>(pieces));
        if (auto moved = move_piece(start, end, report); !moved) return moved;
        start = end;
    }
    return Done{};
}

Outcome<Done> DelaunayCutSession::move_piece(const Point& from, const Point& to, CutStepReport& report) {
    const Point heading{to[0] - from[0], to[1] - from[1], 0};
    Point scalpel = from;  // where the scalpel is as far as the piece has been handled
    bool fix_up_waits = false;
    // each round handles one phase; an exit followed by an entry again in the same piece is the
    // most a piece can hold
    for (int round = 0; round < 8; ++round) {
        if (m_state.phase == Phase::outside) {
            const std::optional<Entry> entry = first_entry(scalpel, to);
            if (!entry) return Done{};
            if (auto entered = enter(*entry, report); !entered) return entered;
            scalpel = entry->at;
            continue;
        }
        if (m_state.phase == Phase::entering && !in_mesh(to)) {
            // the scalpel went back out before the incision began: the dent stays (§5.2.2)
            ++report.retractions;
            m_state.phase = Phase::outside;
            m_state.active = invalid_id;
            return Done{};
        }
        if (m_state.phase == Phase::cutting) m_state.path.push_back(to);
        auto dragged = drag(to, heading, fix_up_waits, report);
        if (!dragged) return dragged.refusal();
        if (*dragged == DragEnd::exited) {
            scalpel = m_state.exit_point;
            continue;
        }
        if (*dragged == DragEnd::fix_up_due) {
            auto fixed = fix_up(report);
            if (!fixed) return fixed.refusal();
            // cutting now, or the dent goes on until the fix-up can be made (after this piece)
            if (!*fixed) fix_up_waits = true;
            continue;
        }
        if (m_state.phase == Phase::cutting) split_incision(report);
        return Done{};
    }
    return Done{};
}

Outcome<Done> DelaunayCutSession::enter(const Entry& entry, CutStepReport& report) {
    const Point& pu = at(mesh(), entry.u);
    const Point& pv = at(mesh(), entry.v);
    const double to_u = distance(entry.at, pu), to_v = distance(entry.at, pv);
    if (std::min(to_u, to_v) <= eps_entry()) {
        // close to a node: that node follows the scalpel, and the incision begins where it was
        m_state.active = to_u <= to_v ? entry.u : entry.v;
    } else {
        auto split = split_edge(mesh(), entry.u, entry.v, entry.on_edge);
        if (!split) return split.refusal().prefixed("entry: ");
        ++report.edges_split;
        m_state.active = split->vertex;
    }
    m_state.entry = at(mesh(), m_state.active);
    m_state.entry_reference = mesh().reference(m_state.active);
    m_state.phase = Phase::entering;
    m_state.path.clear();
    ++report.entries;
    return Done{};
}

}  // namespace sxk::delaunaycut
