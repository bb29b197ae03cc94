// cycle_around and star (thesis §7.2).
#include "sxk/traversal.hpp"

#include <algorithm>
#include <array>
#include <utility>

#include "cycle_around.hpp"
#include "star_walk.hpp"

namespace sxk {

std::vector<ElementId> cycle_around(const Mesh& mesh, FaceId entry, int j) {
    std::vector<ElementId> ring;
    detail::cycle_around_into(mesh, entry, j, ring);
    return ring;
}

void collect_star(const Mesh& mesh, VertexId v, ElementId start, std::vector<ElementId>& out) {
    detail::StarList around;
    detail::list_star(mesh, v, start, around);
    out.insert(out.end(), around.begin(), around.end());
}

std::vector<ElementId> star(const Mesh& mesh, VertexId v) {
    std::vector<ElementId> out;
    collect_star(mesh, v, mesh.vertex_element(v), out);
    return out;
}

VertexFan fan_around(const Mesh& mesh, VertexId v) {
    VertexFan fan;
    if (mesh.topological_dimension() != 2 || v >= mesh.vertex_count()) return fan;
    const std::vector<ElementId> around = star(mesh, v);
    if (around.empty()) return fan;
    // each triangle in its positive vertex order, rotated to start at v: <v, x, y>
    std::vector<std::pair<VertexId, VertexId>> sides;
    sides.reserve(around.size());
    for (const ElementId t : around) {
        const Simplex& s = mesh.simplex(t);
        std::array<VertexId, 3> order = s.sign() > 0 ? std::array<VertexId, 3>{s.vertex(0), s.vertex(1), s.vertex(2)}
                                                     : std::array<VertexId, 3>{s.vertex(1), s.vertex(0), s.vertex(2)};
        while (order[0] != v) std::rotate(order.begin(), order.begin() + 1, order.end());
        sides.emplace_back(order[1], order[2]);
    }
    // an open fan starts at the triangle whose x no triangle ends at; a closed one anywhere
    std::size_t i = 0;
    for (std::size_t k = 0; k < sides.size(); ++k)
        if (std::none_of(sides.begin(), sides.end(), [&](const auto& e) { return e.second == sides[k].first; })) {
            i = k;
            break;
        }
    fan.ring.push_back(sides[i].first);
    for (std::size_t k = 0; k < sides.size(); ++k) {
        fan.triangles.push_back(around[i]);
        const VertexId next = sides[i].second;
        const auto found = std::find_if(sides.begin(), sides.end(), [&](const auto& e) { return e.first == next; });
        if (next == fan.ring.front() || found == sides.end()) {
            fan.closed = next == fan.ring.front();
            if (!fan.closed) fan.ring.push_back(next);
            break;
        }
        fan.ring.push_back(next);
        i = static_cast<std::size_t>(found - sides.begin());
    }
    return fan;
}

std::vector<ElementId> stars_of(const Mesh& mesh, std::span<const VertexId> vertices) {
    std::vector<ElementId> found;
    for (const VertexId v : vertices)
        if (v < mesh.vertex_count() && mesh.vertex_element(v) != invalid_id)
            collect_star(mesh, v, mesh.vertex_element(v), found);
    std::sort(found.begin(), found.end());
    found.erase(std::unique(found.begin(), found.end()), found.end());
    return found;
}

}  // namespace sxk
