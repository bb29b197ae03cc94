// Delaunay cutting's movement (thesis §5.2.2): the phases of planar_cut.hpp, one piece at a time.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "cut_methods.hpp"
#include "sxk/ops/split_edge.hpp"

namespace sxk::delaunaycut {

Outcome<Done> DelaunayCutSession::move(const Point& from, const Point& to, CutStepReport& report) {
    // The thesis' scalpel is a mouse: many short movements. A long one is cut in pieces of a
    // quarter of the mean edge, so that the incision is split behind the node as it goes, not once
    // after a long drag (the 3D version subdivides large movements too, Fig. 5.11). Only the part
    // of the movement over the mesh's bounding box is cut so; what lies beyond is one piece each.
    double enter = 0, leave = 1;  // the movement's part in the box (Liang-Barsky clipping)
    for (std::size_t k = 0; k < 2; ++k) {
        const double d = to[k] - from[k];
        if (d == 0) {
            if (from[k] < m_reach.low(k) || from[k] > m_reach.high(k)) enter = 1, leave = 0;
            continue;
        }
        const double a = (m_reach.low(k) - from[k]) / d, b = (m_reach.high(k) - from[k]) / d;
        enter = std::max(enter, std::min(a, b));
        leave = std::min(leave, std::max(a, b));
    }
    std::vector<double> ends;  // where the pieces end, along the movement
    if (enter < leave) {
        if (enter > 0) ends.push_back(enter);
        const double inside = (leave - enter) * distance(from, to);
        const double pieces = std::min(std::ceil(inside / (0.25 * m_mean_edge)), 1e6);
        for (double i = 1; i <= pieces; ++i) ends.push_back(enter + (leave - enter) * i / pieces);
    }
    if (ends.empty() || ends.back() < 1) ends.push_back(1);
    Point start = from;
    for (const double s : ends) {
        const Point end = s >= 1 ? to : lerp(from, to, s);
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
    } else if (auto split = split_edge(mesh(), entry.u, entry.v, entry.on_edge)) {
        ++report.edges_split;
        m_state.active = split->vertex;
    } else {
        m_state.active = to_u <= to_v ? entry.u : entry.v;  // a split refused by rounding: the nearer end
    }
    m_state.entry = at(mesh(), m_state.active);
    m_state.entry_reference = mesh().reference(m_state.active);
    m_state.phase = Phase::entering;
    m_state.path.clear();
    ++report.entries;
    return Done{};
}

}  // namespace sxk::delaunaycut
