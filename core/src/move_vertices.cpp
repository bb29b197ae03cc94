// Mesh::move_vertices: new positions as one observed, recorded and optionally checked event.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
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

constexpr std::uint32_t no_slot = ~std::uint32_t{0};  // m_move_slot of a vertex not being moved

}  // namespace

std::span<const ElementId> Mesh::elements_around_moved() const {
    if (m_moving.empty()) return {};  // outside a move: nothing written (a const mesh read by threads)
    if (!m_around_moved_found) {
        // each star appended, then what an earlier star listed dropped by the elements' marks (a sort
        // of the stars' union was a tenth of a femur needle step, docs/performance.md "needle")
        m_around_seen.new_round(m_elements.size());
        m_around_moved.clear();
        for (const VertexId v : m_moving) {
            if (m_vertex_element[v] == invalid_id) continue;
            const std::size_t from = m_around_moved.size();
            std::size_t kept = from;
            collect_star(*this, v, m_vertex_element[v], m_around_moved);
            for (std::size_t i = from; i < m_around_moved.size(); ++i)
                if (m_around_seen.mark(m_around_moved[i])) m_around_moved[kept++] = m_around_moved[i];
            m_around_moved.resize(kept);
        }
        m_around_moved_found = true;
    }
    return m_around_moved;
}

// move_vertices' checks, before anything is written: no vertex listed twice, and, as asked, no
// element around the moved vertices inverted or flat at the positions it would have. Each
// vertex's index in the call is kept per vertex (m_move_slot) while checking, and forgotten before
// the watchers hear of the move (one of them may move vertices in turn).
Outcome<Done> Mesh::check_move(std::span<const VertexId> vertices, std::span<const Point> points,
                               PositionSet which, const MoveCheck& check) {
    detail::grow_doubling(m_move_slot, vertex_count(), no_slot);
    struct Forget {
        detail::LargeVector<std::uint32_t>& slot;
        std::span<const VertexId> vertices;
        std::size_t set = 0;
        ~Forget() {
            for (std::size_t i = 0; i < set; ++i) slot[vertices[i]] = no_slot;
        }
    } slots{m_move_slot, vertices};
    for (std::size_t i = 0; i < vertices.size(); ++i) {
        if (m_move_slot[vertices[i]] != no_slot)
            return Refusal{RefusalCode::bad_argument,
                           "move_vertices: vertex " + std::to_string(vertices[i]) + " is listed twice", i};
        m_move_slot[vertices[i]] = static_cast<std::uint32_t>(i);
        slots.set = i + 1;
    }
    // the stars a caller walked for this move (walk_star), while the mesh is as they found it
    if (walked_exactly(vertices)) {
        m_around_moved.assign(m_walks.around.begin(), m_walks.around.end());
        m_around_moved_found = true;
    }
    if (!check.refuse_inverted && !check.refuse_flat) return Done{};
    // every element around a moved vertex, once, at the positions it would have
    const std::span<const ElementId> around = elements_around_moved();
    auto after = [&](VertexId w, bool reference) -> const Point* {
        if (m_move_slot[w] != no_slot) return &points[m_move_slot[w]];
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
                               "element " + std::to_string(t) + " would be flat in the " + set_name(reference) +
                                   " positions",
                               t};
        }
    }
    return Done{};
}

void Mesh::size_move_scratch() {
    detail::grow_doubling(m_move_slot, vertex_count(), no_slot);
    m_around_seen.grow(m_elements.size());
    m_walks.vertices.grow(vertex_count());
    m_walks.elements.grow(m_elements.size());
}

void Mesh::begin_star_walks() const {
    m_walks.open = true;
    m_walks.revision = m_revision;
    m_walks.walked = 0;
    m_walks.around.clear();
    m_walks.vertices.new_round(vertex_count());
    m_walks.elements.new_round(m_elements.size());
}

std::span<const ElementId> Mesh::walk_star(VertexId v) const {
    m_walks.last.clear();
    if (v >= vertex_count() || m_vertex_element[v] == invalid_id) return {};
    collect_star(*this, v, m_vertex_element[v], m_walks.last);
    // remembered only for the mesh the walks began on: after a change they can no longer be taken
    if (!m_walks.open || m_walks.revision != m_revision) return m_walks.last;
    // (room made when the walks began; grown here for a walk from inside an edit, before its revision)
    m_walks.vertices.grow(vertex_count());
    m_walks.elements.grow(m_elements.size());
    if (m_walks.vertices.mark(v)) ++m_walks.walked;
    for (const ElementId t : m_walks.last)
        if (m_walks.elements.mark(t)) m_walks.around.push_back(t);
    return m_walks.last;
}

bool Mesh::walked_exactly(std::span<const VertexId> vertices) const {
    if (!m_walks.open || m_walks.revision != m_revision || vertices.size() != m_walks.walked) return false;
    // as many vertices as were walked, each walked and none twice (move_vertices refuses repeats
    // before it asks): the same set
    return std::all_of(vertices.begin(), vertices.end(), [&](VertexId v) { return m_walks.vertices.marked(v); });
}

void Mesh::count_move() {
    const bool walks_current = m_walks.revision == m_revision;
    ++m_revision;
    if (walks_current) m_walks.revision = m_revision;
}

Outcome<Done> Mesh::move_vertices(std::span<const VertexId> vertices, std::span<const Point> points,
                                  PositionSet which, const MoveCheck& check) {
    if (vertices.size() != points.size())
        return Refusal{RefusalCode::bad_argument,
                       "move_vertices: " + std::to_string(vertices.size()) + " vertices but " +
                           std::to_string(points.size()) + " points"};
    if (vertices.empty()) return Done{};
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
    }
    const MovingVertices moving(*this, vertices);
    if (auto checked = check_move(vertices, points, which, check); !checked) return checked;

    count_move();
    for (std::size_t i = 0; i < vertices.size(); ++i) {
        if (m_undo != nullptr) m_undo->position(*this, vertices[i]);
        if (writes_reference(which)) m_reference[vertices[i]] = points[i];
        if (writes_deformed(which)) m_deformed[vertices[i]] = points[i];
    }
    for (Watcher* w : m_watchers) w->vertices_moved(*this, vertices, which);
    return Done{};
}

void Mesh::set_position(VertexId v, const Point& p, PositionSet which) {
    count_move();
    if (m_undo != nullptr) m_undo->position(*this, v);
    if (writes_reference(which)) m_reference[v] = p;
    if (writes_deformed(which)) m_deformed[v] = p;
    const VertexId one[] = {v};
    const MovingVertices moving(*this, one);
    for (Watcher* w : m_watchers) w->vertices_moved(*this, one, which);
}

}  // namespace sxk
