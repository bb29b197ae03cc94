// The active node follows the blade on the surface (thesis §5.3.1): it moves to the pierce point,
// and "the active triangles are subjected to flipping", by the 2D criterion on the two triangles of
// an edge unfolded into one plane (is_locally_delaunay on a surface: unfolded_incircle), interior
// nodes closer than eps_edge removed as in the plane (remove_node: ears on the surface). "Flipping
// on 3D surfaces is a delicate operation: some flips are topologically impossible" (Fig. 5.9):
// flip_edge refuses those, and flips that fold the surface, and every refusal here just leaves the
// edge. §5.3.2's restrictions keep incisions apart: no flip makes an edge between two incisions'
// nodes, no node next to another incision's node is removed.
//
// The pierce point lies in a triangle of the node's star (the movement's pieces are shorter than
// d_max), so the node moves inside that triangle's plane; the other triangles of its star turn
// with it, and where one would become flat or fold against a neighbour the node goes a half, a
// quarter, an eighth of the way, the remeshing runs, and it tries again. When nothing lets it on it
// stays behind the blade (the report says how far and why); the next piece finds the blade again
// in its triangles or ends the incision.
#include <algorithm>
#include <cmath>

#include "planar_walk.hpp"
#include "surface_cut.hpp"
#include "star_flips.hpp"
#include "surface_geometry.hpp"
#include "sxk/edit_journal.hpp"
#include "sxk/ops/remove_node.hpp"
#include "sxk/quality.hpp"
#include "sxk/traversal.hpp"

namespace sxk::delaunaycut {

namespace {
constexpr int max_rounds = 16;
}  // namespace

Outcome<Done> SurfaceCutSession::drag(std::size_t i, const Point& target, CutStepReport& report) {
    for (int round = 0; round < max_rounds; ++round) {
        const VertexId a = m_state.incisions[i].node;
        const Point at = mesh().deformed(a);
        if (distance3(at, target) <= 1e-12 * m_mean_edge) break;
        double s = 1;
        Outcome<Done> placed = place_on_surface(mesh(), a, target);
        for (int halving = 0; !placed && halving < 3; ++halving) {
            s /= 2;
            placed = place_on_surface(mesh(), a, lerp3(at, target, s));
        }
        if (placed) ++report.moves;
        const std::size_t changes = report.flips + report.nodes_removed;
        remesh_around(i, report);
        if (placed && s == 1) return Done{};
        if (!placed && report.flips + report.nodes_removed == changes) {
            report.lag = std::max(report.lag, distance3(at, target));
            report.lag_reason = placed.reason();
            return Done{};
        }
    }
    const double behind = distance3(mesh().deformed(m_state.incisions[i].node), target);
    if (behind > 1e-12 * m_mean_edge) {
        report.lag = std::max(report.lag, behind);
        report.lag_reason =
            "the remeshing around it did not let it through in " + std::to_string(max_rounds) + " rounds";
    }
    return Done{};
}

Outcome<std::vector<std::pair<ElementId, Point>>> SurfaceCutSession::catch_up(std::size_t i, const Blade& blade,
                                                                              CutStepReport& report) {
    for (int round = 0; round < 4; ++round) {
        const VertexId a = m_state.incisions[i].node;
        const std::optional<Beyond> beyond = pierced_beyond(mesh(), a, blade);
        if (!beyond) return std::vector<std::pair<ElementId, Point>>{};
        // the point of the edge between nearest the pierce point, a little inside the node's triangle
        const Point toward = lerp3(beyond->on_edge, mesh().deformed(a), 0.1);
        const std::size_t changes = report.moves + report.flips + report.nodes_removed;
        if (auto dragged = drag(i, toward, report); !dragged) return dragged.refusal();
        const std::vector<ElementId> around = star(mesh(), m_state.incisions[i].node);
        auto pierces = pierce_points(mesh(), around, blade, 1e-6 * m_mean_edge);
        if (!pierces.empty() || report.moves + report.flips + report.nodes_removed == changes) return pierces;
    }
    return std::vector<std::pair<ElementId, Point>>{};
}

void SurfaceCutSession::remesh_around(std::size_t i, CutStepReport& report) {
    for (int round = 0; round < 16; ++round) {
        bool changed = false;
        while (remove_close_node(i, report)) changed = true;
        if (flip_around(i, report)) changed = true;
        if (!changed) return;
    }
}

bool SurfaceCutSession::remove_close_node(std::size_t i, CutStepReport& report) {
    const VertexId a = m_state.incisions[i].node;
    const Point pa = mesh().deformed(a);
    const VertexFan fan = fan_around(mesh(), a);
    std::vector<std::pair<double, VertexId>> close;
    for (std::size_t k = 0; k < fan.ring.size(); ++k) {
        const VertexId x = fan.ring[k];
        if (is_active(x) || separates(x, i) || on_boundary(mesh(), x)) continue;
        const Point& px = mesh().deformed(x);
        if (m_options.short_angle > 0) {
            // §5.5: the edge a-x is short when both angles opposite it are small
            if (!fan.closed && (k == 0 || k + 1 == fan.ring.size())) continue;
            const VertexId before = fan.ring[(k + fan.ring.size() - 1) % fan.ring.size()], after = fan.next(k);
            const std::array<Point, 3> one{mesh().deformed(before), pa, px}, two{mesh().deformed(after), pa, px};
            const double opposite = std::max(triangle_angles(one)[0], triangle_angles(two)[0]);
            if (opposite < m_options.short_angle * pi / 180) close.emplace_back(opposite, x);
        } else if (const double d = distance3(pa, px); d < eps_edge()) {
            close.emplace_back(d, x);
        }
    }
    std::sort(close.begin(), close.end());
    for (const auto& [d, x] : close) {
        const std::vector<ElementId> was = star(mesh(), x);
        const std::size_t folds_before = folds_at(mesh(), was);
        EditStep attempt(*EditJournal::of(mesh()));
        auto removed = remove_node(mesh(), x, Positions::deformed);
        if (!removed || folds_at(mesh(), *removed) > folds_before) continue;  // rolled back
        if (!attempt.commit()) continue;
        ++report.nodes_removed;
        return true;
    }
    return false;
}

bool SurfaceCutSession::flip_around(std::size_t i, CutStepReport& report) {
    StarFlipRules rules;
    rules.may_join = [&](VertexId c, VertexId d) { return !(is_active(c) && is_active(d)); };
    rules.no_new_folds = true;
    const std::size_t flips = flip_star(mesh(), m_state.incisions[i].node, rules);
    report.flips += flips;
    return flips > 0;
}

}  // namespace sxk::delaunaycut
