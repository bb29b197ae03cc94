// Where the blade enters the surface (thesis §5.3.2, Fig. 5.12): "the scalpel hits a boundary edge
// of the mesh, the scalpel tip enters through the surface, or the scalpel hits an internal edge".
//
// The candidates come from the SpatialIndex: the triangles with a vertex in the box of a part of
// the sweep (the blade cut in parts of four mean edges, so that a long blade held across the
// surface asks only about the triangles near it), grown by the longest edge. Each of their edges
// meets the moving blade first at the time eq. 5.1 gives (first_sweep_hit), and the tip's path
// crosses their planes inside them or not. The triangles of the incisions' nodes are not
// candidates: the blade in them is the incisions' business (§5.3.2: "incisions in edges or
// triangles that are already active are rejected"). The first event in time is made, with every
// other at the same time, in the order of the edges' vertex ids; one that the blade only grazes
// (a moment later it pierces none of the triangles around the edge) is no entry. The piece of the
// movement then ends there: what follows is handled with the new incision's d_max.
#include <algorithm>
#include <cmath>
#include <tuple>

#include "planar_walk.hpp"
#include "scalpel_sweep.hpp"
#include "surface_cut.hpp"
#include "surface_geometry.hpp"
#include "sxk/ops/split_edge.hpp"
#include "sxk/predicates.hpp"
#include "sxk/traversal.hpp"

namespace sxk::delaunaycut {

namespace {

// Entries of one movement at most (a movement of the thesis' mouse makes one or two).
constexpr std::size_t most_entries = 64;

struct Event {
    double time = 0;
    VertexId u = invalid_id, v = invalid_id;  // an edge (u < v), or invalid_id for the tip
    ElementId triangle = invalid_id;          // the tip's triangle
    double along_edge = 0;
    Point point{};
    bool operator<(const Event& other) const {
        return std::tie(time, u, v, triangle) < std::tie(other.time, other.u, other.v, other.triangle);
    }
};

}  // namespace

Outcome<double> SurfaceCutSession::enter(const Blade& from, const Blade& to, CutStepReport& report) {
    const double fastest = std::max(distance3(from.handle, to.handle), distance3(from.tip, to.tip));
    if (fastest == 0) return 1.0;
    // a safety net: a blade that keeps meeting the surface at one place would add an entry per piece
    if (report.entries >= most_entries) return 1.0;
    const double blade_length = std::max(distance3(from.handle, from.tip), distance3(to.handle, to.tip));
    const int parts = static_cast<int>(std::clamp(std::ceil(blade_length / (4 * m_mean_edge)), 1.0, 64.0));
    std::vector<ElementId> candidates;
    for (int k = 0; k < parts; ++k) {
        const double l0 = static_cast<double>(k) / parts, l1 = static_cast<double>(k + 1) / parts;
        Point low{}, high{};
        for (std::size_t c = 0; c < 3; ++c) {
            const double x[4] = {lerp3(from.handle, from.tip, l0)[c], lerp3(from.handle, from.tip, l1)[c],
                                 lerp3(to.handle, to.tip, l0)[c], lerp3(to.handle, to.tip, l1)[c]};
            low[c] = *std::min_element(x, x + 4) - m_longest_edge;
            high[c] = *std::max_element(x, x + 4) + m_longest_edge;
        }
        const std::vector<ElementId> found = m_index.elements_with_vertex_in_box(low, high);
        candidates.insert(candidates.end(), found.begin(), found.end());
    }
    std::sort(candidates.begin(), candidates.end());
    candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());

    auto busy = [&](ElementId t) {
        for (const VertexId w : mesh().simplex(t).vertices())
            if (is_active(w)) return true;
        return false;
    };
    // where a cut ended the blade still touches the triangles around its last node as it leaves
    auto near_an_end = [&](ElementId t) {
        const std::vector<VertexId>& ends = m_state.forbidden;
        for (const VertexId w : mesh().simplex(t).vertices())
            if (std::find(ends.begin(), ends.end(), w) != ends.end()) return true;
        return false;
    };
    std::vector<Event> events;
    std::vector<std::array<VertexId, 2>> seen;
    for (const ElementId t : candidates) {
        if (busy(t) || near_an_end(t)) continue;
        const Simplex s = mesh().simplex(t);
        for (int i = 0; i < 3; ++i) {
            const ElementId other = mesh().neighbor(t, i);
            if (other != invalid_id && (busy(other) || near_an_end(other))) continue;
            VertexId u = s.vertex((i + 1) % 3), v = s.vertex((i + 2) % 3);
            if (v < u) std::swap(u, v);
            seen.push_back({u, v});
        }
        // the tip through the triangle
        const Point& p = mesh().deformed(s.vertex(0));
        const Point n = cross(minus(mesh().deformed(s.vertex(1)), p), minus(mesh().deformed(s.vertex(2)), p));
        const double d0 = dot(n, minus(from.tip, p)), d1 = dot(n, minus(to.tip, p));
        if (d0 == d1 || !segment_meets_triangle(from.tip, to.tip, p, mesh().deformed(s.vertex(1)),
                                                 mesh().deformed(s.vertex(2))))
            continue;
        const double time = std::clamp(d0 / (d0 - d1), 0.0, 1.0);
        events.push_back({time, invalid_id, invalid_id, t, 0, lerp3(from.tip, to.tip, time)});
    }
    std::sort(seen.begin(), seen.end());
    seen.erase(std::unique(seen.begin(), seen.end()), seen.end());
    for (const auto& [u, v] : seen) {
        const std::optional<SweepHit> hit = first_sweep_hit(from.handle, from.tip, to.handle, to.tip,
                                                            mesh().deformed(u), mesh().deformed(v));
        if (hit) events.push_back({hit->time, u, v, invalid_id, hit->along_edge, hit->point});
    }
    std::sort(events.begin(), events.end());

    // a moment after the event (the faster end a tenth of a mean edge on): the blade pierces a
    // triangle around it, or it only touched the surface there
    auto pierces_after = [&](const Event& event, std::span<const VertexId> corners) {
        const double later = std::min(1.0, event.time + 0.1 * m_mean_edge / fastest);
        const Blade blade = lerp(from, to, later);
        std::vector<ElementId> around;
        for (const VertexId w : corners) {
            const std::vector<ElementId> more = star(mesh(), w);
            around.insert(around.end(), more.begin(), more.end());
        }
        std::sort(around.begin(), around.end());
        around.erase(std::unique(around.begin(), around.end()), around.end());
        return !pierce_points(mesh(), around, blade, 0).empty();
    };
    for (std::size_t first = 0; first < events.size();) {
        std::size_t last = first;
        while (last < events.size() && events[last].time <= events[first].time + 1e-12) ++last;
        std::size_t made = 0;
        for (std::size_t e = first; e < last; ++e) {
            const Event& event = events[e];
            VertexId node = invalid_id;
            if (event.u != invalid_id) {
                const std::optional<FaceId> edge = edge_face(mesh(), event.u, event.v);
                if (!edge) continue;  // split by an entry at the same time
                const ElementId t = mesh().face_element(*edge);
                const ElementId other = mesh().neighbor(t, mesh().face_slot(*edge));
                if (busy(t) || (other != invalid_id && busy(other))) continue;
                const std::array<VertexId, 2> corners{event.u, event.v};
                if (!pierces_after(event, corners)) continue;
                // within eps_entry of an end of the edge, that node; else a new node on the edge
                const Point& pu = mesh().deformed(event.u);
                const Point& pv = mesh().deformed(event.v);
                const Point on = lerp3(pu, pv, event.along_edge);
                if (distance3(on, pu) <= eps_entry() && distance3(on, pu) <= distance3(on, pv)) {
                    node = event.u;
                } else if (distance3(on, pv) <= eps_entry()) {
                    node = event.v;
                } else if (auto split = split_edge(mesh(), event.u, event.v, event.along_edge)) {
                    ++report.edges_split;
                    node = split->vertex;
                } else {
                    node = distance3(on, pu) <= distance3(on, pv) ? event.u : event.v;
                }
            } else {
                if (!mesh().is_element(event.triangle) || busy(event.triangle)) continue;
                const std::array<VertexId, 3> corners{mesh().simplex(event.triangle).vertex(0),
                                                      mesh().simplex(event.triangle).vertex(1),
                                                      mesh().simplex(event.triangle).vertex(2)};
                if (!pierces_after(event, corners)) continue;
                auto placed = node_on_triangle(mesh(), event.triangle, event.point, eps_entry());
                if (!placed) continue;  // a split refused by rounding: no entry there
                node = *placed;
            }
            if (is_active(node)) continue;
            Incision incision;
            incision.stage = Stage::entered;
            incision.node = node;
            incision.entry = mesh().deformed(node);
            m_state.incisions.push_back(std::move(incision));
            ++report.entries;
            ++made;
        }
        if (made > 0) return events[first].time;
        first = last;
    }
    return 1.0;
}

}  // namespace sxk::delaunaycut
