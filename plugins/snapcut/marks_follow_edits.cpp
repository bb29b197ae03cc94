// Cut marks that follow the mesh's edits (face_selection.hpp, CutMarks; thesis §3.4).
#include <algorithm>
#include <unordered_map>
#include <unordered_set>

#include "face_selection.hpp"
#include "sxk/predicates.hpp"
#include "sxk/traversal.hpp"

namespace sxk::snapcut {

void CutMarks::mark_outside_selection(const Mesh& mesh, std::span<const ElementId> star_u, VertexId u, VertexId v,
                                      const Mark& mark) {
    if (m_marks.contains(key(u, v))) return;
    add_mark(u, v, mark);
    before_lists_change();
    for (const ElementId t : star_u)
        if (mesh.simplex(t).contains(v)) m_lists.pending.push_back(t);
}

void CutMarks::settle_pending() {
    before_lists_change();
    std::vector<ElementId>& pending = m_lists.pending;
    std::sort(pending.begin(), pending.end());
    pending.erase(std::unique(pending.begin(), pending.end()), pending.end());
}

void CutMarks::carry_to_copies(const Mesh& mesh, std::span<const std::pair<VertexId, VertexId>> copies) {
    if (copies.empty() || m_marks.empty()) return;
    std::unordered_map<VertexId, VertexId> original_of;
    for (const auto& [original, copy] : copies) original_of.emplace(copy, original);
    const auto original = [&](VertexId v) {
        const auto found = original_of.find(v);
        return found == original_of.end() ? v : found->second;
    };
    std::vector<ElementId> around;
    std::vector<VertexId> neighbours;
    for (const auto& [o, c] : copies) {
        if (!has_marked_edge(o) || mesh.vertex_element(c) == invalid_id) continue;
        around.clear();
        collect_star(mesh, c, mesh.vertex_element(c), around);
        neighbours.clear();
        for (const ElementId t : around)
            for (const VertexId x : mesh.simplex(t).vertices())
                if (x != c) neighbours.push_back(x);
        std::sort(neighbours.begin(), neighbours.end());
        neighbours.erase(std::unique(neighbours.begin(), neighbours.end()), neighbours.end());
        for (const VertexId x : neighbours) {
            const VertexId x0 = original(x);
            if (x0 == o) continue;  // another copy of o
            const std::optional<Mark> was = mark(o, x0);
            if (!was) continue;
            mark_outside_selection(mesh, around, c, x, Mark{was->node == o ? c : x, was->sweep});
        }
    }
    settle_pending();
}

void CutMarks::mark_from_earlier_sweeps(const Mesh& mesh, std::span<const ElementId> elements,
                                        const SweptSurface* swept) {
    std::unordered_set<std::uint64_t> tested;
    std::vector<ElementId> around;
    for (const ElementId t : elements) {
        if (!mesh.is_element(t)) continue;
        const Simplex s = mesh.simplex(t);
        for (int i = 0; i < s.count(); ++i)
            for (int j = i + 1; j < s.count(); ++j) {
                const VertexId u = s.vertex(i), v = s.vertex(j);
                if (!tested.insert(key(u, v)).second) continue;
                if (mark(u, v)) continue;
                const Point& p = mesh.deformed(u);
                const Point& q = mesh.deformed(v);
                Point low{}, high{};
                for (std::size_t k = 0; k < 3; ++k) low[k] = std::min(p[k], q[k]), high[k] = std::max(p[k], q[k]);
                for (const std::uint32_t index : sweeps_meeting_box(low, high)) {
                    const Sweep& sweep = m_sweeps[index];
                    if (!segment_meets_triangle(p, q, sweep.a, sweep.b, sweep.c)) continue;
                    const Sign side = compare_distances_to_plane(p, q, sweep.a, sweep.b, sweep.c);
                    const VertexId nearer = side == Sign::negative ? u : side == Sign::positive ? v : std::min(u, v);
                    // the first sweep it crosses would pull a node far from the cut onto it
                    if (!snapped(nearer) && (swept == nullptr || !swept->near(mesh.deformed(nearer)))) break;
                    around.clear();
                    collect_star(mesh, u, mesh.vertex_element(u), around);
                    mark_outside_selection(mesh, around, u, v, Mark{nearer, index});
                    break;
                }
            }
    }
    settle_pending();
}

}  // namespace sxk::snapcut
