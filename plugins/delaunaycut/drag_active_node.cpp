// The active node follows the scalpel (thesis §5.2.2): "the active node is moved, and after each
// movement, local remeshing is applied to the active triangles": interior nodes closer than
// eps_edge are removed, and edges that fail the empty-circle test are flipped.
//
// A node may only move as far as its triangles stay counter-clockwise. Moving it onto the line of
// a triangle's far edge would flatten that triangle; before that, the Delaunay test flips the edge
// (the circle through a nearly flat triangle holds the node beyond it), and the node goes on
// through the new triangles. So the node moves in rounds: each as far as no triangle of its star
// gets below a quarter of its height (nor below a thousandth of the mean edge), then remeshing.
// When nothing flips and nothing is removed the node stops there: it lags behind the scalpel, the
// mesh stays valid, and the report says why.
#include <algorithm>
#include <cmath>

#include "cut_methods.hpp"
#include "star_flips.hpp"
#include "sxk/ops/remove_node.hpp"
#include "sxk/quality.hpp"
#include "sxk/traversal.hpp"

namespace sxk::delaunaycut {

namespace {
// The angle at p of the triangle (p, a, b), in radians.
double angle_at(const Point& p, const Point& a, const Point& b) {
    const std::array<Point, 3> corners{p, a, b};
    return triangle_angles(corners)[0];
}
// Rounds of one drag: each at least quarters the height of the triangle in the way, or flips or
// removes something; a piece of a movement (a quarter of the mean edge) takes a handful.
constexpr int max_rounds = 256;
// The least height a triangle of the active node's star keeps, in mean edge lengths.
constexpr double least_height = 1e-3;
}  // namespace

Outcome<DelaunayCutSession::DragEnd> DelaunayCutSession::drag(const Point& target, const Point& heading,
                                                              bool fix_up_waits, CutStepReport& report) {
    for (int round = 0; round < max_rounds; ++round) {
        remesh_around_active(report);
        if (m_state.phase == Phase::cutting) {
            auto exited = try_exit(heading, target, report, false);
            if (!exited) return exited.refusal();
            if (*exited) return DragEnd::exited;
        }
        const VertexId active = m_state.active;
        const Point a = at(mesh(), active);
        if (m_state.phase == Phase::entering && !fix_up_waits && distance(a, m_state.entry) > eps_entry())
            return DragEnd::fix_up_due;
        if (a[0] == target[0] && a[1] == target[1]) return DragEnd::reached;
        // how far towards the target the star lets the node go
        const VertexFan fan = fan_around(mesh(), active);
        double s = 1;
        for (std::size_t i = 0; i < fan.triangles.size(); ++i) {
            const Point& x = at(mesh(), fan.ring[i]);
            const Point& y = at(mesh(), fan.next(i));
            const double now = area2(a, x, y), then = area2(target, x, y);
            const double floor = std::max(now / 4, least_height * m_mean_edge * distance(x, y));
            if (then < floor) s = std::min(s, (now - floor) / (now - then));
        }
        // no way on (or one so short that the node would not move): the node is stuck; pressed
        // against the boundary by a scalpel that went along or out of it, the cut ends there
        if (s * distance(a, target) <= least_height * 1e-6 * m_mean_edge) {
            if (m_state.phase == Phase::cutting) {
                auto exited = try_exit(heading, target, report, true);
                if (!exited) return exited.refusal();
                if (*exited) return DragEnd::exited;
            }
            report.lag = distance(a, target);
            report.lag_reason = "a triangle ahead of it is nearly flat, its far edge cannot be flipped and no node "
                                "near it can be removed";
            return DragEnd::behind;
        }
        Outcome<Done> placed = place_vertex(mesh(), active, s == 1 ? target : lerp(a, target, s));
        for (int halving = 0; !placed && halving < 4; ++halving) {  // rounding at the limit: less far
            s /= 2;
            placed = place_vertex(mesh(), active, lerp(a, target, s));
        }
        if (!placed) {
            report.lag = distance(a, target);
            report.lag_reason = placed.reason();
            return DragEnd::behind;
        }
        ++report.moves;
    }
    report.lag = distance(at(mesh(), m_state.active), target);
    report.lag_reason = "the remeshing around it did not let it through in " + std::to_string(max_rounds) + " rounds";
    return DragEnd::behind;
}

void DelaunayCutSession::remesh_around_active(CutStepReport& report) {
    for (int round = 0; round < 16; ++round) {
        bool changed = false;
        while (remove_close_node(report)) changed = true;
        if (flip_around_active(report)) changed = true;
        if (!changed) return;
    }
}

bool DelaunayCutSession::remove_close_node(CutStepReport& report) {
    const Point a = at(mesh(), m_state.active);
    const VertexFan fan = fan_around(mesh(), m_state.active);
    // (how close, node): by distance (eps_edge), or by the larger angle opposite the edge (§5.5)
    std::vector<std::pair<double, VertexId>> close;
    for (std::size_t i = 0; i < fan.ring.size(); ++i) {
        const VertexId x = fan.ring[i];
        if (on_boundary(mesh(), x)) continue;  // an interior node's ring closes: both neighbours exist
        if (m_options.short_angle > 0) {
            const Point& px = at(mesh(), x);
            const VertexId before = fan.ring[(i + fan.ring.size() - 1) % fan.ring.size()], after = fan.next(i);
            const double opposite =
                std::max(angle_at(at(mesh(), before), a, px), angle_at(at(mesh(), after), a, px));
            if (opposite < m_options.short_angle * pi / 180) close.emplace_back(opposite, x);
        } else if (const double d = distance(a, at(mesh(), x)); d < eps_edge()) {
            close.emplace_back(d, x);
        }
    }
    std::sort(close.begin(), close.end());
    for (const auto& [d, x] : close)
        if (remove_node(mesh(), x, Positions::deformed)) {
            ++report.nodes_removed;
            return true;
        }
    return false;
}

bool DelaunayCutSession::flip_around_active(CutStepReport& report) {
    const std::size_t flips = flip_star(mesh(), m_state.active);
    report.flips += flips;
    return flips > 0;
}

}  // namespace sxk::delaunaycut
