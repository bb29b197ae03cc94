// The incision split on a surface (thesis §5.3.1, Fig. 5.5): "during a cut, the last path of the
// scalpel is stored. When the cut edges violate the 3D empty-circle criterion, new nodes are
// inserted where the path is closest to the line connecting the nodes opposite the cut edges."
//
// An open incision: the cut edges a-c1 and a-c2 (the ends of the active node's fan) count as one
// edge a-c, c their midpoint, tested with the triangles (a, c, o1) and (c, a, o2) unfolded about it
// (unfolded_incircle). Each cut edge is split and its node goes to q, the path's point nearest the
// line o1-o2, a `dilation` of the way towards o1 or o2, as in the plane (incision_split.cpp).
//
// A constrained incision (an interior entry, surface_incision.cpp): the constrained edge e-a with
// its two triangles. When it fails the test a node goes on it at q and the two halves are
// dissected: that node's star falls apart, the incision opens, and its two copies are dilated.
#include <algorithm>
#include <limits>

#include "surface_cut.hpp"
#include "surface_geometry.hpp"
#include "sxk/edit_journal.hpp"
#include "sxk/ops/dissect.hpp"
#include "sxk/ops/split_edge.hpp"
#include "sxk/predicates.hpp"
#include "sxk/traversal.hpp"

namespace sxk::delaunaycut {

namespace {


// The point of the polyline `path` nearest the line through o1 and o2, and the index of the first
// path point after it; none for a path of fewer than two points.
std::optional<std::pair<Point, std::size_t>> nearest_to_line(const std::vector<Point>& path, const Point& o1,
                                                             const Point& o2) {
    std::optional<std::pair<Point, std::size_t>> best;
    double least = std::numeric_limits<double>::infinity();
    const Point d = minus(o2, o1);
    const double dd = dot(d, d);
    if (!(dd > 0)) return best;
    auto off_line = [&](const Point& p) {
        const Point r = minus(p, o1);
        const Point c = cross(r, d);
        return dot(c, c) / dd;
    };
    for (std::size_t k = 0; k + 1 < path.size(); ++k) {
        // the squared distance from the line is a quadratic along the segment: its least point
        const Point u = minus(path[k + 1], path[k]);
        const Point r = minus(path[k], o1);
        const Point uc = cross(u, d), rc = cross(r, d);
        const double a = dot(uc, uc), b = dot(uc, rc);
        const double s = a > 0 ? std::clamp(-b / a, 0.0, 1.0) : 0.0;
        const Point p = lerp3(path[k], path[k + 1], s);
        if (const double e = off_line(p); e < least) least = e, best = std::pair{p, k + 1};
    }
    return best;
}

}  // namespace

void SurfaceCutSession::split_incision(std::size_t i, CutStepReport& report) {
    for (int split = 0; split < 8; ++split) {
        const Incision incision = m_state.incisions[i];
        const VertexId a = incision.node;
        const VertexFan fan = fan_around(mesh(), a);
        const Point pa = mesh().deformed(a);
        VertexId o1 = invalid_id, o2 = invalid_id;
        Point c{};
        if (incision.stage == Stage::opened) {
            if (fan.closed || fan.triangles.size() < 3) return;
            o1 = fan.ring[1];
            o2 = fan.ring[fan.ring.size() - 2];
            c = lerp3(mesh().deformed(fan.ring.front()), mesh().deformed(fan.ring.back()), 0.5);
        } else if (incision.stage == Stage::constrained) {
            const auto e = std::find(fan.ring.begin(), fan.ring.end(), incision.entry_node);
            if (!fan.closed || e == fan.ring.end()) return;
            const std::size_t k = static_cast<std::size_t>(e - fan.ring.begin()), n = fan.ring.size();
            o1 = fan.ring[(k + n - 1) % n];
            o2 = fan.ring[(k + 1) % n];
            c = mesh().deformed(incision.entry_node);
        } else {
            return;
        }
        const Point p1 = mesh().deformed(o1), p2 = mesh().deformed(o2);
        if (unfolded_incircle(pa, c, p1, p2) != Sign::positive) return;
        const auto nearest = nearest_to_line(incision.path, p1, p2);
        if (!nearest) return;
        const Point q = nearest->first;
        EditStep attempt(*EditJournal::of(mesh()));
        if (incision.stage == Stage::opened) {
            auto one_side = [&](VertexId from, VertexId to, const Point& opposite) {
                auto made = split_edge(mesh(), from, to, 0.5);
                return made && place_on_surface(mesh(), made->vertex, lerp3(q, opposite, m_options.dilation)).ok();
            };
            if (!one_side(a, fan.ring.front(), p1) || !one_side(fan.ring.back(), a, p2)) return;  // rolled back
        } else {
            const VertexId e = incision.entry_node;
            const double along = std::clamp(nearest_on_segment(c, pa, q), 0.1, 0.9);
            auto made = split_edge(mesh(), e, a, along);
            if (!made) return;
            const VertexId m = made->vertex;
            (void)place_on_surface(mesh(), m, q);  // refused: the node stays on the edge, as good a place
            DissectOptions options;
            options.cut_label = m_options.cut_label;
            const std::array<Simplex, 2> halves{Simplex(+1, {e, m}), Simplex(+1, {m, a})};
            auto opened = dissect(mesh(), halves, options);
            if (!opened || opened->new_vertices.empty()) return;  // rolled back: the edge stays constrained
            report.faces_dissected += 2;
            // each copy of m towards the node opposite it
            const Point at = mesh().deformed(m);
            for (const VertexId copy : {m, opened->new_vertices.front().second}) {
                const VertexFan around = fan_around(mesh(), copy);
                const bool sees_o1 = std::find(around.ring.begin(), around.ring.end(), o1) != around.ring.end();
                (void)place_on_surface(mesh(), copy, lerp3(at, sees_o1 ? p1 : p2, m_options.dilation));
            }
        }
        if (!attempt.commit()) return;
        ++report.incision_splits;
        Incision& kept = m_state.incisions[i];
        kept.stage = Stage::opened;
        kept.entry_node = invalid_id;
        std::vector<Point> path{q};
        path.insert(path.end(), incision.path.begin() + static_cast<std::ptrdiff_t>(nearest->second),
                    incision.path.end());
        if (path.size() == 1) path.push_back(pa);
        kept.path = std::move(path);
    }
}

}  // namespace sxk::delaunaycut
