// Following the blade (blade_track.hpp).
#include "blade_track.hpp"

#include <algorithm>
#include <iterator>

#include "sxk/predicates.hpp"
#include "sxk/traversal.hpp"

namespace sxk::snapcut {

namespace {

// More vertices than this moved at once (a simulation's frame) and the track is forgotten: the
// stars of a frame's vertices are the mesh.
constexpr std::size_t largest_move_followed = 256;

void sort_unique(std::vector<ElementId>& ids) {
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
}

// Appends the live elements of `fresh` that the sweep meets (an edit far from the sweep makes
// elements it must not select among) and empties it.
void take_met(const Mesh& mesh, const CutMarks& marks, const Sweep& sweep, std::vector<ElementId>& fresh,
              std::vector<ElementId>& out) {
    sort_unique(fresh);
    for (const ElementId t : fresh)
        if (mesh.is_element(t) && meets_as_selected(mesh, marks, t, sweep.a, sweep.b, sweep.c)) out.push_back(t);
    fresh.clear();
}

}  // namespace

BladeTrack::BladeTrack(Mesh& mesh) : m_mesh(mesh) { mesh.add_watcher(*this); }

BladeTrack::~BladeTrack() { m_mesh.remove_watcher(*this); }

bool BladeTrack::follows(const Scalpel& blade) const { return m_following && same_blade(blade, m_blade); }

void BladeTrack::forget() {
    m_following = false;
    m_inside.clear();
    m_fresh.clear();
    m_met.clear();
}

void BladeTrack::start(const Scalpel& blade) {
    forget();
    m_following = true;
    m_blade = blade;
}

std::vector<ElementId> BladeTrack::roots(const SpatialIndex& index, const CutMarks& marks, const Scalpel& from,
                                         const Scalpel& to, const Sweep& sweep) {
    std::vector<ElementId> roots = std::move(m_inside);
    m_inside.clear();
    take_met(index.mesh(), marks, sweep, m_fresh, roots);
    // where the blade's ends go (an end that stays passes through nothing new)
    for (const auto& [was, is] : {std::pair{from.handle, to.handle}, std::pair{from.tip, to.tip}}) {
        if (was == is) continue;
        const std::vector<ElementId> crossed = index.elements_crossed(was, is);
        roots.insert(roots.end(), crossed.begin(), crossed.end());
    }
    // where the sweep meets the boundary: the blade may come into the mesh there from outside
    for (const FaceId f : index.elements_hit_by_triangle(sweep.a, sweep.b, sweep.c, TriangleHitsOf::boundary_faces)
                              .boundary_faces)
        roots.push_back(index.mesh().face_element(f));
    m_blade = to;
    sort_unique(roots);
    return roots;
}

std::vector<ElementId> BladeTrack::roots_again(const Mesh& mesh, const CutMarks& marks, const Sweep& sweep) {
    std::vector<ElementId> roots = m_met;
    take_met(mesh, marks, sweep, m_fresh, roots);
    return roots;
}

void BladeTrack::settle(const Mesh& mesh, const CutMarks& marks) {
    if (!m_following) return;
    std::vector<ElementId> inside;
    for (const ElementId t : m_met)
        if (mesh.is_element(t) && meets_as_selected(mesh, marks, t, m_blade.handle, m_blade.tip))
            inside.push_back(t);
    std::vector<ElementId> merged;
    merged.reserve(m_inside.size() + inside.size());
    std::set_union(m_inside.begin(), m_inside.end(), inside.begin(), inside.end(), std::back_inserter(merged));
    m_inside = std::move(merged);
}

void BladeTrack::init(const Mesh& /*mesh*/) { forget(); }

void BladeTrack::element_added(const Mesh& /*mesh*/, ElementId element) {
    if (m_following) m_fresh.push_back(element);
}

void BladeTrack::element_changed(const Mesh& /*mesh*/, ElementId element, const Simplex& /*was*/) {
    if (m_following) m_fresh.push_back(element);
}

void BladeTrack::vertices_moved(const Mesh& mesh, std::span<const VertexId> vertices, PositionSet which) {
    if (!m_following || !m_watch_moves || which == PositionSet::reference) return;
    if (vertices.size() > largest_move_followed) return forget();
    const std::span<const ElementId> around = mesh.elements_around_moved();
    m_fresh.insert(m_fresh.end(), around.begin(), around.end());
}

}  // namespace sxk::snapcut
