// Mesh::move_vertices: new positions as one observed, recorded and optionally checked event.
#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "sxk/mesh.hpp"
#include "sxk/predicates.hpp"
#include "sxk/traversal.hpp"
#include "moving_vertices.hpp"
#include "undo_log.hpp"

namespace sxk {

namespace {

const char* set_name(bool reference) { return reference ? "reference" : "deformed"; }

}  // namespace

std::span<const ElementId> Mesh::elements_around_moved() const {
    if (m_moving.empty()) return {};  // outside a move: nothing written (a const mesh read by threads)
    if (!m_around_moved_found) {
        m_around_moved.clear();
        for (const VertexId v : m_moving)
            if (m_vertex_element[v] != invalid_id) collect_star(*this, v, m_vertex_element[v], m_around_moved);
        std::sort(m_around_moved.begin(), m_around_moved.end());
        m_around_moved.erase(std::unique(m_around_moved.begin(), m_around_moved.end()), m_around_moved.end());
        m_around_moved_found = true;
    }
    return m_around_moved;
}

Outcome<Done> Mesh::move_vertices(std::span<const VertexId> vertices, std::span<const Point> points,
                                  PositionSet which, const MoveCheck& check) {
    if (vertices.size() != points.size())
        return Refusal{RefusalCode::bad_argument,
                       "move_vertices: " + std::to_string(vertices.size()) + " vertices but " +
                           std::to_string(points.size()) + " points"};
    if (vertices.empty()) return Done{};
    // (vertex, its index in the call), sorted by vertex: repeats, and the lookup of the checks
    std::vector<std::pair<VertexId, std::size_t>> moved(vertices.size());
    for (std::size_t i = 0; i < vertices.size(); ++i) {
        if (vertices[i] >= vertex_count())
            return Refusal{RefusalCode::not_found,
                           "move_vertices: vertex " + std::to_string(vertices[i]) +
                               " does not exist",
                           i};
        const Point& p = points[i];
        if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
            return Refusal{RefusalCode::bad_argument,
                           "move_vertices: the point of vertex " + std::to_string(vertices[i]) +
                               " is not finite",
                           i};
        if (m_ambient == 2 && p[2] != 0.0)
            return Refusal{RefusalCode::bad_argument,
                           "move_vertices: the point of vertex " + std::to_string(vertices[i]) +
                               " has z != 0 in a planar mesh",
                           i};
        moved[i] = {vertices[i], i};
    }
    std::sort(moved.begin(), moved.end());
    for (std::size_t i = 1; i < moved.size(); ++i)
        if (moved[i].first == moved[i - 1].first)
            return Refusal{RefusalCode::bad_argument,
                           "move_vertices: vertex " + std::to_string(moved[i].first) +
                               " is listed twice",
                           std::max(moved[i].second, moved[i - 1].second)};

    const MovingVertices moving(*this, vertices);
    if (check.refuse_inverted || check.refuse_flat) {
        // every element around a moved vertex, once, at the positions it would have
        const std::span<const ElementId> around = elements_around_moved();
        auto after = [&](VertexId w, bool reference) -> const Point* {
            const auto it = std::lower_bound(moved.begin(), moved.end(), std::pair<VertexId, std::size_t>{w, 0});
            if (it != moved.end() && it->first == w) return &points[it->second];
            return reference ? &m_reference[w] : &m_deformed[w];
        };
        for (const bool reference : {true, false}) {
            if (reference ? !writes_reference(which) : !writes_deformed(which)) continue;
            for (const ElementId t : around) {
                const Simplex& s = m_elements[t].simplex;
                std::array<const Point*, 4> at{};
                for (int j = 0; j < s.count(); ++j) at[static_cast<std::size_t>(j)] = after(s.vertex(j), reference);
                const Sign sign = simplex_orientation(s, m_ambient, {at.data(), static_cast<std::size_t>(s.count())});
                if (sign == Sign::negative && check.refuse_inverted)
                    return Refusal{RefusalCode::would_invert,
                                   "element " + std::to_string(t) + " would be inverted in the " +
                                       set_name(reference) + " positions",
                                   t};
                if (sign == Sign::zero && check.refuse_flat)
                    return Refusal{RefusalCode::would_flatten,
                                   "element " + std::to_string(t) + " would be flat in the " +
                                       set_name(reference) + " positions",
                                   t};
            }
        }
    }

    ++m_revision;
    for (std::size_t i = 0; i < vertices.size(); ++i) {
        if (m_undo != nullptr) m_undo->position(*this, vertices[i]);
        if (writes_reference(which)) m_reference[vertices[i]] = points[i];
        if (writes_deformed(which)) m_deformed[vertices[i]] = points[i];
    }
    for (Watcher* w : m_watchers) w->vertices_moved(*this, vertices, which);
    return Done{};
}

void Mesh::set_position(VertexId v, const Point& p, PositionSet which) {
    ++m_revision;
    if (m_undo != nullptr) m_undo->position(*this, v);
    if (writes_reference(which)) m_reference[v] = p;
    if (writes_deformed(which)) m_deformed[v] = p;
    const VertexId one[] = {v};
    const MovingVertices moving(*this, one);
    for (Watcher* w : m_watchers) w->vertices_moved(*this, one, which);
}

}  // namespace sxk
