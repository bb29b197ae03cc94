// Following the blade: the elements a scalpel's blade lies in, kept from one sweep to the next
// (docs/snapcut.md "Following the blade").
//
// The elements a segment meets change only where the segment passes over an edge of the mesh or
// one of its ends passes through a face. So the elements a sweep from blade B to blade B' meets,
// as the selection sees them (CutMarks::selection_position), are found without asking the
// spatial index along the blade's whole length:
//
//        the elements B lies in (kept here)                    ─┐
//        those the blade's ends pass through (two short        │ roots
//          segment queries) and those behind the boundary      │
//          faces the sweep meets (where it enters the mesh)    │
//        those an edit made or changed, or whose corners moved, ─┘
//          since, that the sweep meets (Watcher events)
//        then, until nothing is added, the elements around every edge the sweep crosses
//          (close_over_crossed_edges, face_selection.hpp)
//
// and of those, the ones B' lies in are kept for the next sweep. The elements with a corner the
// cut snapped (seen where they were before the snap) that the sweep meets are roots too: the
// session finds them among CutMarks::elements_near's every sweep. The index is asked along the
// whole blade only when there is nothing to follow: the first movement, a movement that does not
// start where the last ended (a path of swept triangles), after a step was taken back or
// refused, after the blade slid along itself, or after more than a few hundred vertices moved (a
// simulation's frame). On the 1.2M femur at 1 kHz the index's query was about a third of the
// selection's time (docs/performance.md "Following the blade"). A round of the same sweep after
// the removal edited the mesh selects among what the first round met and what the edits made.
#pragma once

#include <cstddef>
#include <span>
#include <utility>
#include <vector>

#include "face_selection.hpp"
#include "snap_cut.hpp"
#include "sxk/locate.hpp"
#include "sxk/watcher.hpp"

namespace sxk::snapcut {

class BladeTrack final : public Watcher {
public:
    explicit BladeTrack(Mesh& mesh);
    ~BladeTrack() override;
    BladeTrack(const BladeTrack&) = delete;
    BladeTrack& operator=(const BladeTrack&) = delete;

    // Whether the track holds the elements `blade` lies in.
    bool follows(const Scalpel& blade) const;
    // Forgets the blade: the next sweep asks the index.
    void forget();
    // Starts following at `blade` (settle then keeps those of the sweep's elements it lies in).
    void start(const Scalpel& blade);
    // The roots of a sweep that moves the blade from where it is followed (follows(from)) to
    // `to`: see above (of the elements edits made, those the sweep meets). `to` is then the
    // blade followed.
    std::vector<ElementId> roots(const SpatialIndex& index, const CutMarks& marks, const Scalpel& from,
                                 const Scalpel& to, const Sweep& sweep);
    // The roots of a later round of the sweep the last roots were for: what that sweep met
    // (set_met), and the elements edits made or changed since that it meets (a round over the
    // whole sweep again, after the removal edited the mesh).
    std::vector<ElementId> roots_again(const Mesh& mesh, const CutMarks& marks, const Sweep& sweep);
    // The elements the followed blade lies in as the selection sees them (sorted; some may be
    // dead or remade since): the next `roots` hands every live one over as a root.
    const std::vector<ElementId>& inside() const { return m_inside; }
    // What the sweep met, as the session found it.
    void set_met(std::vector<ElementId> met) { m_met = std::move(met); }
    // Keeps the live elements the sweep met (set_met) that the followed blade meets as the
    // selection sees them.
    void settle(const Mesh& mesh, const CutMarks& marks);
    // While false, moves of vertices are the cut's own snaps: the selection sees snapped nodes
    // where they were, so nothing it follows moved.
    void watch_moves(bool watch) { m_watch_moves = watch; }

    // ---- Watcher ------------------------------------------------------------------------------
    void init(const Mesh& mesh) override;
    void element_added(const Mesh& mesh, ElementId element) override;
    void element_changed(const Mesh& mesh, ElementId element, const Simplex& was) override;
    void vertices_moved(const Mesh& mesh, std::span<const VertexId> vertices, PositionSet which) override;

private:
    Mesh& m_mesh;
    bool m_following = false;
    bool m_watch_moves = true;
    Scalpel m_blade;
    std::vector<ElementId> m_inside;  // the elements the blade lies in (sorted; some may be dead)
    std::vector<ElementId> m_fresh;   // made, changed or moved by edits since the last roots
    std::vector<ElementId> m_met;     // what the last sweep met (set_met)
};

}  // namespace sxk::snapcut
