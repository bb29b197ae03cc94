// The surface cutter's session (surface_cut.hpp): the blade, the movement in pieces of d_max
// (thesis Fig. 5.11), the undo of the session's state, and the report.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>

#include "scalpel_sweep.hpp"
#include "surface_cut.hpp"
#include "surface_geometry.hpp"
#include "sxk/predicates.hpp"
#include "sxk/quality.hpp"
#include "sxk/traversal.hpp"

namespace sxk::delaunaycut {

namespace {
// The longest edge of triangle t (deformed positions).
double longest_edge(const Mesh& mesh, ElementId t) {
    const Simplex& s = mesh.simplex(t);
    double longest = 0;
    for (int j = 0; j < 3; ++j)
        longest = std::max(longest, distance3(mesh.deformed(s.vertex(j)), mesh.deformed(s.vertex((j + 1) % 3))));
    return longest;
}

// Pieces of one movement at most: past them the rest of the movement is one piece, and an incision
// the blade left behind in it ends.
constexpr int most_pieces = 4096;
}  // namespace

Outcome<std::unique_ptr<SurfaceCutSession>> SurfaceCutSession::make(Mesh& mesh, const Options& options) {
    if (mesh.topological_dimension() != 2 || mesh.ambient_dimension() != 3)
        return Refusal{RefusalCode::wrong_dimension,
                       "delaunaycut: the surface cutter needs a triangle surface in space (triangles, Dimension 3)"};
    if (auto checked = check_options(mesh, options); !checked) return checked.refusal();
    if (options.method != Method::delaunay)
        return Refusal{RefusalCode::bad_argument,
                       "delaunaycut: the subdivision method cuts planar meshes only; surfaces are cut by the "
                       "delaunay method"};
    // a flat triangle has no plane for the blade to pierce
    for (const ElementId t : elements(mesh))
        if (element_orientation(mesh, t, Positions::deformed) != Sign::positive)
            return Refusal{RefusalCode::would_invert,
                           "delaunaycut: triangle " + std::to_string(t) + " is flat (collinear corners) in the "
                           "deformed positions", t};
    const double h = mean_edge_length(mesh, Positions::deformed);
    mesh.reserve(mesh.vertex_count() + mesh.vertex_count() / 8 + 1024,
                 mesh.element_capacity() + mesh.element_capacity() / 8 + 1024);
    return std::unique_ptr<SurfaceCutSession>(new SurfaceCutSession(mesh, options, h));
}

SurfaceCutSession::SurfaceCutSession(Mesh& mesh, const Options& options, double mean_edge)
    : ToolSession(mesh), m_options(options), m_mean_edge(mean_edge), m_reach(mesh, mean_edge, 3),
      m_index(mesh, Positions::deformed) {
    for (const ElementId t : elements(mesh)) m_longest_edge = std::max(m_longest_edge, longest_edge(mesh, t));
    (void)keep_beside(m_beside);  // a new log, attached nowhere else
}

SurfaceCutSession::~SurfaceCutSession() = default;

std::optional<std::string> SurfaceCutSession::too_far(const Blade& blade) const {
    if (auto far = m_reach.too_far(blade.tip, "the blade's tip")) return far;
    return m_reach.too_far(blade.handle, "the blade's handle");
}

std::vector<VertexId> SurfaceCutSession::active_nodes() const {
    std::vector<VertexId> nodes;
    for (const Incision& incision : m_state.incisions) nodes.push_back(incision.node);
    return nodes;
}

bool SurfaceCutSession::is_active(VertexId v) const {
    return std::any_of(m_state.incisions.begin(), m_state.incisions.end(), [&](const Incision& incision) {
        return incision.node == v || incision.entry_node == v;
    });
}

bool SurfaceCutSession::separates(VertexId v, std::size_t except) const {
    const VertexFan fan = fan_around(mesh(), v);
    for (std::size_t i = 0; i < m_state.incisions.size(); ++i) {
        if (i == except) continue;
        const Incision& other = m_state.incisions[i];
        if (std::find(fan.ring.begin(), fan.ring.end(), other.node) != fan.ring.end()) return true;
    }
    return false;
}

Outcome<StepReport> SurfaceCutSession::cut(const Point& handle, const Point& tip) {
    ToolPose pose;
    pose.position = tip;
    const Point along = minus(tip, handle);
    pose.length = length3(along);
    if (pose.length > 0)
        for (std::size_t k = 0; k < 3; ++k) pose.axes[2][k] = along[k] / pose.length;
    m_exact = Blade{handle, tip};
    auto result = step(pose);
    m_exact.reset();
    return result;
}

Outcome<Done> SurfaceCutSession::apply(const ToolPose& pose, StepReport& report) {
    const auto started = std::chrono::steady_clock::now();
    Blade to{pose.position, pose.position};
    if (m_exact) {
        to = *m_exact;
    } else {
        for (std::size_t k = 0; k < 3; ++k) to.handle[k] -= pose.length * pose.axes[2][k];
    }
    m_last = {};
    m_last.phase = m_state.incisions.empty() ? Phase::outside : Phase::cutting;
    for (const Point& p : {to.handle, to.tip})
        for (const double x : p)
            if (!std::isfinite(x))
                return Refusal{RefusalCode::bad_argument, "delaunaycut: the blade's position is not finite"};
    if (const std::optional<std::string> far = too_far(to)) return Refusal{RefusalCode::bad_argument, *far};
    if (m_blade) {
        // a refusal: the step's rollback takes back the mesh, the blade and the incisions
        if (auto moved = move(*m_blade, to, m_last); !moved) return moved.refusal();
        // the cut's ends accept entries again once the blade is away from them
        std::erase_if(m_state.forbidden,
                      [&](VertexId v) { return distance_to_blade(to, mesh().deformed(v)) > 2 * eps_exit(); });
    } else {
        report.actions.push_back("placed the blade");
    }
    m_blade = to;
    for (const ElementId t : elements_edited_in_step())
        if (mesh().is_element(t)) m_longest_edge = std::max(m_longest_edge, longest_edge(mesh(), t));
    m_last.phase = m_state.incisions.empty() ? Phase::outside : Phase::cutting;
    m_last.incisions = m_state.incisions.size();
    m_last.elements = mesh().element_count();
    m_last.vertices = mesh().vertices_in_elements();
    describe(m_last, report);
    if (m_last.retractions > 0)
        report.actions.push_back(std::to_string(m_last.retractions) + " incisions left by the blade");
    m_last.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    return Done{};
}

double SurfaceCutSession::safe_move(const Blade& blade) const {
    double least = std::numeric_limits<double>::infinity();
    for (const Incision& incision : m_state.incisions) {
        const std::vector<std::array<Point, 2>> edges = far_edges(mesh(), incision.node);
        least = std::min(least, largest_safe_move(blade.handle, blade.tip, edges));
    }
    return least;
}

Outcome<Done> SurfaceCutSession::move(const Blade& from, const Blade& to, CutStepReport& report) {
    const double fastest = std::max(distance3(from.handle, to.handle), distance3(from.tip, to.tip));
    if (fastest == 0) return Done{};
    double s = 0;
    Blade at = from;
    for (int piece = 0; s < 1; ++piece) {
        // Fig. 5.11: while incisions are under way no end of the blade moves farther than d_max of
        // their active nodes, so the blade stays in their triangles; and no farther than a quarter of
        // the mean edge, so that the incisions are split behind the nodes as they go
        double step = 1 - s;
        if (!m_state.incisions.empty() && piece < most_pieces) {
            const double limit = std::clamp(0.9 * safe_move(at), least_piece * m_mean_edge, 0.25 * m_mean_edge);
            step = std::min(step, limit / fastest);
        }
        Blade next = s + step >= 1 ? to : lerp(from, to, s + step);
        auto entered = enter(at, next, report);
        if (!entered) return entered.refusal();
        if (*entered < 1) {
            // the piece ends at the entry: what follows is handled with the new incision's d_max
            next = lerp(at, next, *entered);
            s += step * *entered;
        } else {
            s = s + step >= 1 ? 1 : s + step;
        }
        if (auto followed = follow(next, report); !followed) return followed;
        at = next;
        if (piece > 4 * most_pieces) break;  // entries at one instant over and over: give up the rest
    }
    return Done{};
}

}  // namespace sxk::delaunaycut
