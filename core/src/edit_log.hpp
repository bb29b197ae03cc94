// Bookkeeping shared by the edit primitives: what watchers must hear once an edit is done.
//
// Watchers are told net changes only (watcher.hpp). The primitives record the state of every
// face they touch *before* touching it, and which faces and elements they freed and created;
// at the end the log compares before and after and reports each difference once. Most edits
// touch a few faces, found by a linear search; an AMP closure replaces tens of elements in one
// edit and touches a thousand faces, found through an index (docs/performance.md "A record per
// element and stretch": the linear search was a tenth of a femur needle's refinement).
#pragma once

#include <cstdint>
#include <vector>

#include "sxk/detail/flat_set.hpp"
#include "sxk/mesh.hpp"

namespace sxk::detail {

class EditLog {
public:
    explicit EditLog(bool active) : m_active(active) {}
    bool active() const { return m_active; }

    // Call before changing f's mate or simplex, or freeing it.
    void touch(const Mesh& mesh, FaceId f) {
        if (!m_active || find(f)) return;
        m_faces.push_back(FaceRecord{f, mesh.mate(f) == invalid_id, mesh.face_simplex(f), false,
                                     false, true});
    }
    void freed(const Mesh& mesh, FaceId f) {
        if (!m_active) return;
        touch(mesh, f);
        find(f)->freed = true;
    }
    void created(FaceId f) {
        if (!m_active) return;
        if (FaceRecord* r = find(f)) {
            r->created = true;
        } else {
            m_faces.push_back(FaceRecord{f, false, Simplex{}, false, true, false});
        }
    }
    void element_removed(ElementId t, const Simplex& was) {
        if (m_active) m_removed.push_back({t, was});
    }
    void element_changed(ElementId t, const Simplex& was) {
        if (m_active) m_changed.push_back({t, was});
    }
    void element_added(ElementId t) {
        if (m_active) m_added.push_back(t);
    }

    // Reports to every watcher: elements removed, changed, added; then boundary removed,
    // changed, added.
    void publish(const Mesh& mesh, const std::vector<Watcher*>& watchers) const {
        if (!m_active) return;
        for (Watcher* w : watchers) {
            for (const auto& [t, was] : m_removed) w->element_removed(mesh, t, was);
            for (const auto& [t, was] : m_changed) w->element_changed(mesh, t, was);
            for (ElementId t : m_added) w->element_added(mesh, t);
            for (const FaceRecord& r : m_faces) {
                const bool existed = r.existed_before;
                const bool old_identity_gone = r.freed;
                if (existed && r.was_boundary &&
                    (old_identity_gone || mesh.mate(r.face) != invalid_id))
                    w->boundary_removed(mesh, r.face, r.was);
            }
            for (const FaceRecord& r : m_faces) {
                if (r.existed_before && !r.freed && r.was_boundary &&
                    mesh.mate(r.face) == invalid_id && !(mesh.face_simplex(r.face) == r.was))
                    w->boundary_changed(mesh, r.face, r.was);
            }
            for (const FaceRecord& r : m_faces) {
                const bool live_now = !r.freed || r.created;
                if (!live_now || mesh.mate(r.face) != invalid_id) continue;
                const bool same_identity = r.existed_before && !r.freed;
                if (!same_identity || !r.was_boundary) w->boundary_added(mesh, r.face);
            }
        }
    }

private:
    struct FaceRecord {
        FaceId face;
        bool was_boundary;
        Simplex was;
        bool freed;
        bool created;
        bool existed_before;
    };
    static constexpr std::size_t linear_search_limit = 32;
    FaceRecord* find(FaceId f) {
        if (m_faces.size() <= linear_search_limit) {
            for (FaceRecord& r : m_faces)
                if (r.face == f) return &r;
            return nullptr;
        }
        for (; m_indexed < m_faces.size(); ++m_indexed)
            m_index.insert(m_faces[m_indexed].face.value(), static_cast<std::uint32_t>(m_indexed));
        const std::uint32_t* at = m_index.find(f.value());
        return at == nullptr ? nullptr : &m_faces[*at];
    }

    bool m_active;
    std::vector<FaceRecord> m_faces;
    FlatMap<std::uint32_t, std::uint32_t> m_index;  // face -> its record, past linear_search_limit
    std::size_t m_indexed = 0;                      // the records in m_index
    std::vector<std::pair<ElementId, Simplex>> m_removed;
    std::vector<std::pair<ElementId, Simplex>> m_changed;
    std::vector<ElementId> m_added;
};

}  // namespace sxk::detail
