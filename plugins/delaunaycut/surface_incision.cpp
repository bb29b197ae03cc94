// Each incision after a piece of the blade's movement (thesis §5.3): "the line segment representing
// the new scalpel position is intersected with all active triangles. If a single intersection is
// found, then the active node is moved to that point"; "if multiple active triangles are
// intersected ... the cut will branch. New incisions are inserted, the old incision is marked as
// no longer active, and the edges connecting old and new active nodes are dissected."
//
// An entered incision (its entry node on the boundary, on an exposed edge or where the tip went
// through) waits until a pierce point is eps_entry from the entry (the entry postponed, as in the
// plane, Fig. 5.6). Then nodes go to the pierce points, and the cut from the entry node to them is
// opened: a dissection opens an edge only where a vertex's star falls apart (Fig. 7.7), which it
// does at a boundary node, or at an interior node cut along two or more edges. A single incision
// from an interior entry node is the thesis' constrained edge instead ("until that time, the edge is
// constrained, so it cannot be flipped away"): labelled, so no flip removes it, and opened by the
// first incision split (surface_incision_split.cpp).
#include <algorithm>

#include "planar_walk.hpp"
#include "scalpel_sweep.hpp"
#include "surface_cut.hpp"
#include "surface_geometry.hpp"
#include "sxk/edit_journal.hpp"
#include "sxk/ops/dissect.hpp"
#include "sxk/traversal.hpp"

namespace sxk::delaunaycut {

void SurfaceCutSession::end_incision(std::size_t i) {
    Incision& incision = m_state.incisions[i];
    if (incision.stage == Stage::constrained)
        mesh().erase_face_label(Simplex(+1, {incision.entry_node, incision.node}));
    incision.node = invalid_id;
}

Outcome<Done> SurfaceCutSession::follow(const Blade& blade, CutStepReport& report) {
    const std::size_t count = m_state.incisions.size();
    for (std::size_t i = 0; i < count; ++i) {
        if (m_state.incisions[i].node == invalid_id) continue;  // ended by another's exit this piece
        const VertexId node = m_state.incisions[i].node;
        const std::vector<ElementId> around = star(mesh(), node);
        auto pierces = pierce_points(mesh(), around, blade, 1e-6 * m_mean_edge);
        if (pierces.empty() && m_state.incisions[i].stage != Stage::entered) {
            auto caught = catch_up(i, blade, report);
            if (!caught) return caught.refusal();
            pierces = std::move(*caught);
        }
        if (pierces.empty()) {
            // Touching the node, the blade may miss its triangles by the rounding of the node's
            // position (an entry node on an exposed edge the blade only touches yet); an entered
            // incision waits while the blade is within eps_entry of it. Else the blade left: out of
            // the surface, or back into the incision behind the node.
            const double away = distance_to_blade(blade, mesh().deformed(m_state.incisions[i].node));
            if (away <= (m_state.incisions[i].stage == Stage::entered ? eps_entry() : 1e-6 * m_mean_edge)) continue;
            end_incision(i);
            ++report.retractions;
            continue;
        }
        const Point before = mesh().deformed(m_state.incisions[i].node);
        if (m_state.incisions[i].stage == Stage::entered) {
            double farthest = 0;
            for (const auto& [t, p] : pierces) farthest = std::max(farthest, distance3(p, m_state.incisions[i].entry));
            // waiting, the entry node's star must keep holding the pierce points: when the blade is
            // about to leave it (d_max below the pieces' floor: a blade touching a curved surface,
            // whose pierce points run apart fast), the incision begins with them where they are
            const bool cramped =
                largest_safe_move(blade.handle, blade.tip, far_edges(mesh(), node)) < 2 * least_piece * m_mean_edge;
            if (farthest <= eps_entry() && !cramped) continue;
            // an interior entry node with one pierce point: the other of a blade touching a curved
            // surface may have run one triangle beyond in the last piece; it is found there, and the
            // cut branches towards the edge in between
            if (pierces.size() == 1 && !on_boundary(mesh(), node))
                if (const std::optional<Beyond> beyond = pierced_beyond(mesh(), node, blade))
                    pierces.emplace_back(beyond->triangle, beyond->on_edge);
            if (auto opened = open_from(i, pierces, report); !opened) return opened;
            continue;
        }
        // a pierce point at the node itself (the blade still through it) is no branch
        if (pierces.size() > 1)
            std::erase_if(pierces, [&](const auto& pierce) {
                return distance3(pierce.second, before) <= 1e-3 * m_mean_edge;
            });
        if (pierces.size() > 1) {
            if (auto branched = open_from(i, pierces, report); !branched) return branched;
            continue;
        }
        const Point target = pierces.front().second;
        if (auto dragged = drag(i, target, report); !dragged) return dragged;
        Incision& incision = m_state.incisions[i];
        incision.path.push_back(target);
        Point heading = minus(mesh().deformed(incision.node), before);
        if (length3(heading) == 0 && incision.path.size() >= 2)
            heading = minus(incision.path.back(), incision.path[incision.path.size() - 2]);
        auto exited = try_exit(i, heading, report);
        if (!exited) return exited.refusal();
        if (!*exited) split_incision(i, report);
    }
    std::erase_if(m_state.incisions, [](const Incision& incision) { return incision.node == invalid_id; });
    return Done{};
}

Outcome<Done> SurfaceCutSession::open_from(std::size_t i, const std::vector<std::pair<ElementId, Point>>& pierces,
                                           CutStepReport& report) {
    const Incision was = m_state.incisions[i];
    const VertexId o = was.node;
    EditStep attempt(*EditJournal::of(mesh()));
    std::vector<std::pair<VertexId, Point>> nodes;
    bool runs_along_boundary = false;
    for (const auto& pierce : pierces) {
        const Point& p = pierce.second;
        if (distance3(p, mesh().deformed(o)) <= 1e-3 * m_mean_edge) continue;
        // found again: the node before may have split the pierce point's triangle (and its id be reused)
        const std::vector<ElementId> around = star(mesh(), o);
        const ElementId holder = nearest_point(mesh(), around, p).triangle;
        if (holder == invalid_id) continue;
        auto placed = node_on_triangle(mesh(), holder, p, 1e-3 * m_mean_edge);
        if (!placed || *placed == o || is_active(*placed)) continue;
        // a boundary edge from o: the blade along the boundary, nothing to cut there
        const std::optional<FaceId> along = edge_face(mesh(), o, *placed);
        if (along && mesh().neighbor(mesh().face_element(*along), mesh().face_slot(*along)) == invalid_id) {
            runs_along_boundary = true;
            continue;
        }
        if (std::none_of(nodes.begin(), nodes.end(), [&](const auto& known) { return known.first == *placed; }))
            nodes.emplace_back(*placed, p);
    }
    // a later node may have split the edge from o to an earlier one: that one is no longer next to o
    std::erase_if(nodes, [&](const auto& node) { return !edge_face(mesh(), o, node.first); });
    if (nodes.empty()) {
        if (runs_along_boundary) {  // the incision is over before it began
            m_state.incisions[i].node = invalid_id;
            m_state.forbidden.push_back(o);
            ++report.retractions;
            return attempt.commit();
        }
        return Done{};  // nothing to open yet (the new nodes' splits were refused)
    }
    const bool from_boundary = on_boundary(mesh(), o);
    if (was.stage == Stage::entered && !from_boundary && nodes.size() == 1) {
        // thesis §5.3.2: the edge from the entry node to the active node, constrained
        const auto [n, p] = nodes.front();
        mesh().set_face_label(Simplex(+1, {o, n}), m_options.cut_label);
        if (auto kept = attempt.commit(); !kept) return kept.refusal();
        Incision& incision = m_state.incisions[i];
        incision.stage = Stage::constrained;
        incision.entry_node = o;
        incision.node = n;
        incision.path = {was.entry, p};
        ++report.fix_ups;
        return Done{};
    }
    std::vector<Simplex> cut;
    std::vector<bool> reaches_boundary;
    for (const auto& [n, p] : nodes) {
        cut.push_back(Simplex(+1, {o, n}));
        reaches_boundary.push_back(on_boundary(mesh(), n));
    }
    if (was.stage == Stage::constrained && edge_face(mesh(), was.entry_node, o))
        cut.push_back(Simplex(+1, {was.entry_node, o}));
    DissectOptions options;
    options.cut_label = m_options.cut_label;
    auto opened = dissect(mesh(), cut, options);
    if (!opened) return opened.refusal().prefixed("delaunaycut: ");
    if (auto kept = attempt.commit(); !kept) return kept.refusal();
    report.faces_dissected += cut.size();
    if (was.stage == Stage::entered && nodes.size() == 1) ++report.fix_ups;
    else ++report.branches;
    m_state.incisions[i].node = invalid_id;  // the cut behind the old node is open: nothing to unlabel
    for (std::size_t k = 0; k < nodes.size(); ++k) {
        if (reaches_boundary[k]) {  // cut through to the boundary at once: that incision is over
            ++report.exits;
            m_state.forbidden.push_back(nodes[k].first);
            continue;
        }
        Incision incision;
        incision.stage = Stage::opened;
        incision.node = nodes[k].first;
        incision.entry = was.entry;
        incision.path = {mesh().deformed(o), nodes[k].second};
        m_state.incisions.push_back(std::move(incision));
    }
    return Done{};
}

}  // namespace sxk::delaunaycut
