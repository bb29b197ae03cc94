// The incision split (thesis §5.2.2, Fig. 5.5): "from a geometric point of view, we can identify
// both cut edges into a single edge, and check if this edge satisfies the empty-circle criterion.
// If it does not, new nodes are inserted, where the line connecting nodes opposite the cut edges
// intersect the scalpel path."
//
//             o1                     o1            The cut edges a-c1 and a-c2 (c1, c2 the two
//           /    \                 /  |  \         sides of the incision's last node) count as one
//         c ====== a     --->    c == q == a       edge a-c, c their midpoint: it fails the test
//           \    /                 \  |  /         when o2 lies in the circle through a, c and o1.
//             o2                     o2            Then each cut edge is split and its new node goes
//                                                  to q, where o1-o2 crosses the scalpel's path
// (dilated a `dilation` of the way towards o1 and o2). The scalpel went through q after removing the
// nodes near it, so the new edges are not short. The path kept is from q on.
#include "cut_methods.hpp"
#include "sxk/edit_journal.hpp"
#include "sxk/ops/split_edge.hpp"

namespace sxk::delaunaycut {

void DelaunayCutSession::split_incision(CutStepReport& report) {
    for (int split = 0; split < 8; ++split) {
        const VertexId a = m_state.active;
        const VertexFan fan = fan_around(mesh(), a);
        if (fan.closed || fan.triangles.size() < 3) return;
        const VertexId c1 = fan.ring.front(), o1 = fan.ring[1];
        const VertexId c2 = fan.ring.back(), o2 = fan.ring[fan.ring.size() - 2];
        // copies: the splits below add vertices, which may move the positions' storage
        const Point pa = at(mesh(), a);
        const Point c = lerp(at(mesh(), c1), at(mesh(), c2), 0.5);
        const Point p1 = at(mesh(), o1);
        const Point p2 = at(mesh(), o2);
        if (orient2d(pa, c, p1) != Sign::positive || incircle(pa, c, p1, p2) != Sign::positive) return;
        // where o1-o2 crosses the path, first from the incision's end; else the straight incision
        std::optional<Point> q;
        std::size_t kept_from = m_state.path.size();
        for (std::size_t i = 0; i + 1 < m_state.path.size() && !q; ++i)
            if (const auto s = crossing(m_state.path[i], m_state.path[i + 1], p1, p2)) {
                q = lerp(m_state.path[i], m_state.path[i + 1], *s);
                kept_from = i + 1;
            }
        if (!q)
            if (const auto s = crossing(c, pa, p1, p2)) q = lerp(c, pa, *s);
        if (!q) return;
        EditStep attempt(*EditJournal::of(mesh()));
        auto one_side = [&](VertexId from, VertexId to, const Point& opposite) {
            auto made = split_edge(mesh(), from, to, 0.5);
            return made && place_vertex(mesh(), made->vertex, lerp(*q, opposite, m_options.dilation));
        };
        if (!one_side(a, c1, p1) || !one_side(c2, a, p2)) return;  // rolled back: the incision stays
        if (!attempt.commit()) return;
        ++report.incision_splits;
        std::vector<Point> path{*q};
        path.insert(path.end(), m_state.path.begin() + static_cast<std::ptrdiff_t>(kept_from), m_state.path.end());
        if (path.size() == 1) path.push_back(at(mesh(), a));
        m_state.path = std::move(path);
    }
}

}  // namespace sxk::delaunaycut
