// Exits and annihilations (thesis §5.3.2, Figs. 5.7 and 5.13): "when an active node moves towards
// a restricted node, an annihilation is performed: all edges from the restricted node to an active
// node are dissected. ... When an active node comes close to an edge separating active nodes, then
// its movement is extrapolated, and a new node is inserted at the extrapolated point. The
// annihilation now proceeds with the newly inserted node. A normal boundary exit is a special case
// of an annihilation."
//
//   restricted node r (next to another         edge x-y ahead of the node within eps_exit: a
//   incision's node b) within eps_edge         boundary edge, or one whose other triangle holds
//   of the active node a:                      another incision's node b:
//
//        x                                          x
//      /   \                                      / | \            a node r on x-y where a's
//     a --- r --- b    dissect a-r, r-b          a  r  b           movement meets it (or x or y
//      \   /                                      \ | /            when within eps_exit), then as
//        y                                          y              on the left
//
// Every incision whose node is next to the meeting node ends there; the meeting node is forbidden
// to entries until the blade is away (as after a planar exit).
#include <algorithm>
#include <limits>
#include <utility>

#include "planar_walk.hpp"
#include "surface_cut.hpp"
#include "surface_geometry.hpp"
#include "sxk/edit_journal.hpp"
#include "sxk/ops/collapse_edge.hpp"
#include "sxk/ops/dissect.hpp"
#include "sxk/ops/split_edge.hpp"
#include "sxk/traversal.hpp"

namespace sxk::delaunaycut {

Outcome<bool> SurfaceCutSession::try_exit(std::size_t i, const Point& heading, CutStepReport& report) {
    const VertexId a = m_state.incisions[i].node;
    const Point pa = mesh().deformed(a);
    const VertexFan fan = fan_around(mesh(), a);
    auto other_incision = [&](VertexId v) {
        for (std::size_t j = 0; j < m_state.incisions.size(); ++j)
            if (j != i && m_state.incisions[j].node == v && m_state.incisions[j].stage != Stage::entered) return true;
        return false;
    };
    // a restricted node (interior: the cut's own nodes behind a branch are next to both new
    // incisions, and cut already), or another incision's node, within eps_edge
    for (const VertexId x : fan.ring)
        if ((other_incision(x) || (!is_active(x) && separates(x, i) && !on_boundary(mesh(), x))) &&
            distance3(pa, mesh().deformed(x)) < eps_edge()) {
            if (auto met = annihilate(x, report); !met) return met.refusal();
            return true;
        }
    // the boundary, or an edge separating incisions, ahead within eps_exit
    if (!(length3(heading) > 0)) return false;
    double nearest = std::numeric_limits<double>::infinity();
    VertexId x = invalid_id, y = invalid_id;
    double along = 0;
    for (std::size_t k = 0; k < fan.triangles.size(); ++k) {
        const ElementId t = fan.triangles[k];
        const VertexId u = fan.ring[k], v = fan.next(k);
        const ElementId beyond = mesh().neighbor(t, mesh().simplex(t).index(a));
        // a separating edge is interior, ends and all (after a branch, the edges from the cut's node
        // behind both new incisions separate them and are cut at that end already)
        bool exit_edge = beyond == invalid_id;
        if (!exit_edge && !on_boundary(mesh(), u) && !on_boundary(mesh(), v) &&
            !mesh().face_label(Simplex(+1, {u, v})))  // not another's constrained edge
            for (const VertexId w : mesh().simplex(beyond).vertices())
                if (w != u && w != v && other_incision(w)) exit_edge = true;
        if (!exit_edge) continue;
        const Point& pu = mesh().deformed(u);
        const Point& pv = mesh().deformed(v);
        const double on = nearest_on_segment(pu, pv, pa);
        const Point point = lerp3(pu, pv, on);
        const double d = distance3(pa, point);
        if (d > eps_exit() || d >= nearest || dot(heading, minus(point, pa)) <= 0) continue;
        nearest = d, x = u, y = v, along = on;
    }
    if (x == invalid_id) return false;
    const Point point = lerp3(mesh().deformed(x), mesh().deformed(y), along);
    VertexId meeting = invalid_id;
    if (distance3(point, mesh().deformed(x)) <= eps_exit() && !is_active(x) &&
        distance3(point, mesh().deformed(x)) <= distance3(point, mesh().deformed(y))) {
        meeting = x;
    } else if (distance3(point, mesh().deformed(y)) <= eps_exit() && !is_active(y)) {
        meeting = y;
    } else if (auto split = split_edge(mesh(), x, y, along)) {
        ++report.edges_split;
        meeting = split->vertex;
    } else {
        return false;  // a split refused by rounding: the node goes on, and tries again
    }
    if (auto met = annihilate(meeting, report); !met) return met.refusal();
    return true;
}

Outcome<Done> SurfaceCutSession::annihilate(VertexId meeting, CutStepReport& report) {
    const VertexFan fan = fan_around(mesh(), meeting);
    std::vector<Simplex> cut;
    std::vector<std::size_t> ending;
    for (std::size_t j = 0; j < m_state.incisions.size(); ++j) {
        const Incision& incision = m_state.incisions[j];
        if (incision.node == invalid_id || incision.stage == Stage::entered) continue;
        const bool here = incision.node == meeting;
        if (!here && std::find(fan.ring.begin(), fan.ring.end(), incision.node) == fan.ring.end()) continue;
        if (!here) cut.push_back(Simplex(+1, {meeting, incision.node}));
        if (incision.stage == Stage::constrained && edge_face(mesh(), incision.entry_node, incision.node))
            cut.push_back(Simplex(+1, {incision.entry_node, incision.node}));
        ending.push_back(j);
    }
    if (cut.empty()) return Done{};
    DissectOptions options;
    options.cut_label = m_options.cut_label;
    auto opened = dissect(mesh(), cut, options);
    if (!opened) return opened.refusal().prefixed("delaunaycut: ");
    report.faces_dissected += cut.size();
    if (ending.size() > 1) ++report.annihilations;
    else ++report.exits;
    std::vector<VertexId> ending_nodes(m_state.incisions.size(), invalid_id);
    for (const std::size_t j : ending) ending_nodes[j] = std::exchange(m_state.incisions[j].node, invalid_id);
    // the meeting node, the ended incisions' nodes and the copies the dissection made of them
    std::vector<VertexId> meetings{meeting}, nodes;
    for (const std::size_t j : ending) nodes.push_back(ending_nodes[j]);
    for (const auto& [original, copy] : opened->new_vertices)
        (original == meeting ? meetings : nodes).push_back(copy);
    m_state.forbidden.insert(m_state.forbidden.end(), meetings.begin(), meetings.end());
    m_state.forbidden.insert(m_state.forbidden.end(), nodes.begin(), nodes.end());
    // Fig. 5.7 (d): the short edges from the incisions' nodes to the meeting node are contracted,
    // the nodes onto the meeting node (the boundary there may bend by half an edge's length), where
    // that folds nothing
    CollapseOptions loose;
    loose.boundary_tolerance = 0.5;
    for (const VertexId from : nodes)
        for (const VertexId to : meetings) {
            if (!edge_face(mesh(), from, to) || distance3(mesh().deformed(from), mesh().deformed(to)) > eps_exit())
                continue;
            const std::vector<ElementId> around = star(mesh(), from);
            const std::size_t folds_before = folds_at(mesh(), around);
            EditStep attempt(*EditJournal::of(mesh()));
            if (!collapse_edge(mesh(), from, to, loose)) continue;
            const std::vector<ElementId> after = star(mesh(), to);
            if (folds_at(mesh(), after) > folds_before || !attempt.commit()) continue;  // rolled back
            ++report.collapses;
            break;
        }
    return Done{};
}

}  // namespace sxk::delaunaycut
