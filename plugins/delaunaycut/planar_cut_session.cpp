// What both planar cutting methods share (planar_cut.hpp): the scalpel, the undo of the session's
// state, the entry through the boundary, and the report.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>

#include "cut_methods.hpp"
#include "planar_walk.hpp"
#include "sxk/quality.hpp"

namespace sxk::delaunaycut {

std::string_view method_name(Method method) {
    return method == Method::delaunay ? "delaunay" : "subdivision";
}

std::string_view phase_name(Phase phase) {
    switch (phase) {
        case Phase::outside: return "outside";
        case Phase::entering: return "entering";
        case Phase::cutting: return "cutting";
    }
    return "?";
}

Outcome<Done> check_options(const Mesh& mesh, const Options& options) {
    if (mesh.element_count() == 0) return Refusal{RefusalCode::bad_argument, "delaunaycut: the mesh has no triangle"};
    return options.check();
}

void describe(const CutStepReport& step, StepReport& report) {
    const auto say = [&](std::size_t count, const char* what) {
        if (count > 0) report.actions.push_back(std::to_string(count) + " " + what);
    };
    say(step.entries, "entries");
    say(step.fix_ups, "incisions begun");
    say(step.branches, "branches");
    say(step.flips, "flips");
    say(step.nodes_removed, "nodes removed");
    say(step.incision_splits, "incision splits");
    say(step.edges_split, "edges split");
    say(step.faces_dissected, "edges dissected");
    say(step.collapses, "edges contracted");
    say(step.exits, "exits");
    say(step.annihilations, "annihilations");
    if (step.lag > 0) report.actions.push_back("an active node stays behind: " + step.lag_reason);
}

Outcome<std::unique_ptr<PlanarCutSession>> PlanarCutSession::make(Mesh& mesh, const Options& options) {
    if (mesh.topological_dimension() != 2 || mesh.ambient_dimension() != 2)
        return Refusal{RefusalCode::wrong_dimension,
                       "delaunaycut: the planar cutter needs a triangle mesh in the plane (Dimension 2)"};
    if (auto checked = check_options(mesh, options); !checked) return checked.refusal();
    // the walks read corners counter-clockwise: an inverted triangle would send them astray
    for (const ElementId t : elements(mesh))
        if (element_orientation(mesh, t, Positions::deformed) != Sign::positive)
            return Refusal{RefusalCode::would_invert,
                           "delaunaycut: triangle " + std::to_string(t) + " is not counter-clockwise in the "
                           "deformed positions", t};
    const double h = mean_edge_length(mesh, Positions::deformed);
    // Room for the cut's new vertices and triangles: without it the first edit that adds one copies
    // the mesh's pools into larger ones (17 ms at 1M triangles, in the step of the entry).
    mesh.reserve(mesh.vertex_count() + mesh.vertex_count() / 8 + 1024,
                 mesh.element_capacity() + mesh.element_capacity() / 8 + 1024);
    if (options.method == Method::delaunay)
        return std::unique_ptr<PlanarCutSession>(new DelaunayCutSession(mesh, options, h));
    return std::unique_ptr<PlanarCutSession>(new SubdivisionCutSession(mesh, options, h));
}

PlanarCutSession::PlanarCutSession(Mesh& mesh, const Options& options, double mean_edge)
    : ToolSession(mesh), m_options(options), m_mean_edge(mean_edge), m_reach(mesh, mean_edge, 2),
      m_index(mesh, Positions::deformed) {
    (void)keep_beside(m_beside);  // a new log, attached nowhere else
}

PlanarCutSession::~PlanarCutSession() = default;

Outcome<StepReport> PlanarCutSession::cut(const Point& scalpel) {
    ToolPose pose;
    pose.position = scalpel;
    return step(pose);
}

Outcome<Done> PlanarCutSession::apply(const ToolPose& pose, StepReport& report) {
    const auto started = std::chrono::steady_clock::now();
    const Point to{pose.position[0], pose.position[1], 0};
    m_last = {};
    m_last.phase = m_state.phase;
    if (!std::isfinite(to[0]) || !std::isfinite(to[1]))
        return Refusal{RefusalCode::bad_argument, "delaunaycut: the scalpel's position is not finite"};
    if (const std::optional<std::string> far = too_far(to)) return Refusal{RefusalCode::bad_argument, *far};
    if (m_scalpel) {
        // a refusal: the step's rollback takes back the mesh, the scalpel and the state
        if (auto moved = move(*m_scalpel, to, m_last); !moved) return moved.refusal();
        expire_forbidden(to);
    } else {
        report.actions.push_back("placed the scalpel");
    }
    m_scalpel = to;
    m_last.phase = m_state.phase;
    m_last.elements = mesh().element_count();
    m_last.vertices = mesh().vertices_in_elements();
    describe(m_last, report);
    m_last.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    return Done{};
}

std::optional<PlanarCutSession::Entry> PlanarCutSession::first_entry(const Point& from, const Point& to) const {
    if (from == to) return std::nullopt;
    const TriangleHits hits = m_index.elements_hit_by_triangle(from, to, to, TriangleHitsOf::boundary_faces);
    std::optional<Entry> first;
    for (const FaceId f : hits.boundary_faces) {
        // the boundary face of a counter-clockwise triangle runs with the triangle on its left
        const Simplex edge = mesh().face_simplex(f);
        const VertexId u = edge.sign() > 0 ? edge.vertex(0) : edge.vertex(1);
        const VertexId v = edge.sign() > 0 ? edge.vertex(1) : edge.vertex(0);
        if (std::any_of(m_state.forbidden.begin(), m_state.forbidden.end(), [&](const std::array<VertexId, 2>& e) {
                return (e[0] == u && e[1] == v) || (e[0] == v && e[1] == u);
            }))
            continue;
        const Point& pu = at(mesh(), u);
        const Point& pv = at(mesh(), v);
        if (orient2d(pu, pv, from) == Sign::positive || orient2d(pu, pv, to) != Sign::positive) continue;
        // Through an end of the edge (a movement from it or passing it exactly), the movement must go
        // into the edge's own triangle: along the boundary, or into the mesh by another triangle of
        // that corner, is not this edge's entry. (From the end of an incision just cut, the other
        // side of the incision is on the left of its line.)
        const VertexId w = mesh().opposite_vertex(mesh().face_element(f), f);
        const Point& pw = at(mesh(), w);
        const Sign at_u = orient2d(from, to, pu), at_v = orient2d(from, to, pv);
        if (at_u == Sign::zero && orient2d(pw, pu, to) == Sign::negative) continue;
        if (at_v == Sign::zero && orient2d(pv, pw, to) == Sign::negative) continue;
        // where the movement meets the edge's line; the index said the closed segments meet
        const double a_from = area2(pu, pv, from), a_to = area2(pu, pv, to);
        if (!(a_from - a_to < 0)) continue;  // rounding: no crossing to compute
        const double along = std::clamp(a_from / (a_from - a_to), 0.0, 1.0);
        const Point point = lerp(from, to, along);
        const double edge_length = distance(pu, pv);
        const double projected =
            ((point[0] - pu[0]) * (pv[0] - pu[0]) + (point[1] - pu[1]) * (pv[1] - pu[1])) / (edge_length * edge_length);
        const double on_edge = at_u == Sign::zero ? 0 : at_v == Sign::zero ? 1 : std::clamp(projected, 0.0, 1.0);
        if (!first || along < first->along) first = Entry{u, v, along, on_edge, lerp(pu, pv, on_edge)};
    }
    return first;
}

bool PlanarCutSession::in_mesh(const Point& p) const { return m_index.locate(p).found(); }

void PlanarCutSession::expire_forbidden(const Point& scalpel) {
    if (!m_state.forbidden.empty() && distance(scalpel, m_state.exit_point) > 2 * eps_exit()) m_state.forbidden.clear();
}

}  // namespace sxk::delaunaycut
