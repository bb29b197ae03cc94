// Snap cutting (thesis chapter 3, §3.2): a scalpel cuts a tetrahedral mesh along existing faces.
// Each movement of the scalpel is one tool step (sxk/tool_session.hpp), one transaction:
//
//   scalpel (h, t) -> (h', t')                 the movement sweeps two triangles (h t t'), (h t' h')
//        |
//   1. select faces (§3.2.1)                   every mesh edge the sweep crosses marks its end
//        |  face_selection.hpp                 nearer the crossing; a tetrahedron whose marked ends
//        |                                     (or nodes on the cut already) are three of its
//        |                                     corners has that face selected
//        |  split_far_crossings.hpp            (first, a crossed edge whose nearer end is far from
//        |                                     the sweep's plane is split where it is crossed)
//   2. snap nodes (§3.2.2)                     the selected faces' corners move onto the sweep
//        |  node_snapping.hpp                  (boundary nodes within their boundary faces), in
//        |                                     the deformed positions, mapped back to the reference
//   3. dissect (§7.3)                          the selected faces open (sxk/ops/dissect.hpp), each
//        |                                     carrying the cut label, but for one face per crumb
//        |                                     they would cut loose; the copies take over their
//        |                                     originals' marks
//   4. remove degeneracies (§3.2.3)            among the elements around the snapped nodes, by the
//        |                                     degeneracy plug-in's service when it is loaded; the
//        |                                     edges it makes take the marks of the sweeps they
//        |                                     cross (§3.4), and what that completes is selected
//        |                                     in another round
//   5. loose pieces (once per step)            a piece the cut separated is found by a search from
//           loose_pieces.hpp                   both sides of the new cut faces that stops at the
//                                              smaller side: its cost is that side's, not the mesh's;
//                                              crumbs of almost no material are cut free
//
// The sweep meets the deformed shape (the positions a simulation shows); the reference shape is
// kept consistent through the element that holds each snapped position. Nothing in a step scans
// the whole mesh: the sweep's elements come from a SpatialIndex over the deformed positions.
//
//     SnapCutSession session(mesh, {.degeneracy = service});
//     session.cut({handle, tip});              // places the scalpel
//     auto step = session.cut({handle2, tip2}); // a movement: one undoable step
//     session.last_step();                     // what it did (CutStepReport)
//     session.undo_step();
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "face_selection.hpp"
#include "sxk/plugins/snapcut.hpp"
#include "sxk/simulation.hpp"
#include "sxk/locate.hpp"
#include "sxk/quality.hpp"
#include "sxk/tool_session.hpp"

namespace sxk::degeneracy {
struct DegeneracyService;
}

namespace sxk::snapcut {

// The scalpel, its pose and the options: sxk/plugins/snapcut.hpp (installed).
// The same handle and tip, exactly.
bool same_blade(const Scalpel& a, const Scalpel& b);
// The pose a fraction s of the way from `from` to `to` (handle and tip interpolated linearly;
// s = 1 gives `to` exactly): a recorded path's movement replayed in smaller steps.
Scalpel between(const Scalpel& from, const Scalpel& to, double s);

// What one step did (thesis §3.3's figures, per step).
struct CutStepReport {
    std::size_t sweeps = 0;            // sweep triangles processed (0 for the first pose)
    std::size_t repeats = 0;           // sweeps processed again after the removal edited the mesh
    std::size_t elements_searched = 0; // elements the sweeps met (followed or from the index), and
                                       // those carried marks may have completed
    std::size_t edges_hit = 0;         // edges the sweeps crossed for the first time
    std::size_t edges_split = 0;       // of those, split where crossed (Options::split_beyond)
    std::size_t splits_refused = 0;    // far crossings split_edge refused (left as they were)
    std::size_t faces_selected = 0;    // interior faces selected (§3.2.1)
    std::size_t faces_dissected = 0;   // of those, faces that opened
    // How closely the incision follows the scalpel: the farthest corner of a face the step
    // selected from the surface swept so far, in the deformed positions right after the snapping
    // (placement), and of a face the step opened, right after the dissection (incision: a face
    // opens once the faces around its corners close up, which may take a few steps after the
    // sweep that selected it), and again of the cut faces the degeneracy removal remade, after
    // it (a collapse may move a corner of the cut). On a deforming body each sweep is where the
    // blade went in the shape of its time: the relaxations since have moved the material a
    // little. Each also relative to the corner's own mesh size: the distance over the mean length
    // of the edges at the corner (the femur's interior edges are up to 7 times its mean).
    double placement_error = 0, placement_error_local = 0;
    double incision_error = 0, incision_error_local = 0;
    std::size_t nodes_snapped = 0;
    std::size_t nodes_partly_snapped = 0;  // of the snapped, moved only part of the way to the sweep
    std::size_t nodes_refused = 0;     // listed with reasons in `refusals`
    std::vector<std::pair<VertexId, std::string>> refusals;
    std::size_t incomplete = 0;        // tetrahedra left with an incomplete cut (1 or 2 marked nodes)
    // degeneracy removal (all 0 when it did not run)
    bool degeneracy_removal_ran = false;
    std::size_t degenerates_found = 0;
    std::size_t collapses = 0, splits = 0, flips = 0, peeled = 0;
    std::size_t cut_free = 0;          // elements cut free and removed: cracks, and crumbs that
                                       // came loose (Options::largest_crumb)
    std::size_t degenerates_remaining = 0;
    // loose pieces the step made: element count of each (sorted, smallest first)
    std::vector<std::size_t> loose_pieces;
    // the simulation's relaxation after the step (with CutServices::simulation)
    bool relaxed = false;
    std::size_t relax_iterations = 0, pieces_held = 0;
    // with Options::local_vertices: the vertices the step's relaxation solved for (0: the whole
    // body), and the far-field block's
    std::size_t relax_region_vertices = 0, relax_far_vertices = 0;
    bool relax_converged = false, relax_shown = false;
    double relax_residual = 0;
    std::string relax_refusal;  // why it could not relax (the cut stands)
    std::string relax_not_shown;  // why its shape was not written (relax_shown false; the cut stands)
    std::size_t elements = 0, vertices = 0;  // the mesh's after the step (vertices: in some element)
    // seconds per phase, and in all
    double seconds_select = 0, seconds_snap = 0, seconds_dissect = 0, seconds_degeneracy = 0,
           seconds_pieces = 0, seconds_relax = 0, seconds = 0;
};

// What the session offers besides the kernel: other plug-ins' services (nullptr: not loaded).
struct CutServices {
    const degeneracy::DegeneracyService* degeneracy = nullptr;
    // A running simulation of the mesh (sxk/simulation.hpp: the elasticity plug-in's, or the application's), owned
    // by the caller: after each step the session holds the pieces that came loose and relaxes
    // it (Options::relax_iterations), so the next sweep meets the new deformed shape.
    Simulation* simulation = nullptr;
};

class BladeTrack;  // blade_track.hpp
class MovedNodes;  // moved_nodes.hpp

// A sweep's blade before and after it (the movement's: the tip moves, then the handle).
struct BladeMove {
    Scalpel from, to;
};

class SnapCutSession final : public ToolSession {
public:
    // Tetrahedral meshes in space only (refused by make otherwise). Builds a SpatialIndex over the
    // deformed positions (O(n log n), once).
    static Outcome<std::unique_ptr<SnapCutSession>> make(Mesh& mesh, const Options& options,
                                                         const CutServices& services = {});

    // One step: the scalpel moves from its last pose to `scalpel` (the first call only places
    // it). ToolSession::step(pose) does the same with scalpel_of(pose).
    Outcome<StepReport> cut(const Scalpel& scalpel);
    // One step that sweeps exactly the triangle (a, b, c), as a scalpel turning about its handle
    // a from tip b to tip c would (a path given as swept triangles, docs/formats.md); the scalpel
    // is at (a, c) afterwards, wherever it was before.
    Outcome<StepReport> sweep(const Point& a, const Point& b, const Point& c);
    // The report of the last step taken (refused steps included: it says how far they got).
    const CutStepReport& last_step() const { return m_last; }
    const Options& options() const { return m_options; }
    bool has_degeneracy_service() const { return m_services.degeneracy != nullptr; }
    // The scalpel's pose after the last kept step, if placed.
    const std::optional<Scalpel>& scalpel() const { return m_scalpel; }
    // What the cut keeps between sweeps: the sweeps so far, the marks, the snapped nodes.
    const CutMarks& marks() const { return m_marks; }

    SnapCutSession(Mesh& mesh, const Options& options, const CutServices& services);
    ~SnapCutSession() override;

protected:
    Outcome<Done> apply(const ToolPose& pose, StepReport& report) override;

private:
    // `ahead`: the sweeps of the same movement that come after this one; `blade`: the blade
    // before and after the sweep (none for sweep()'s triangle).
    Outcome<Done> cut_sweep(const Sweep& sweep, std::span<const Sweep> ahead, const BladeMove* blade,
                            StepReport& report);
    // One selection, snap, dissection and removal of sweep `sweep_index`, among the elements the
    // sweep meets and those carried marks may have completed (CutMarks::pending), or among the
    // latter only (whole_sweep false); `edited`: the removal changed the mesh.
    Outcome<Done> cut_round(std::uint32_t sweep_index, std::span<const Sweep> ahead, const BladeMove* blade,
                            bool whole_sweep, StepReport& report, bool& edited);
    // The elements sweep `sweep_index` meets (a round over the whole sweep): followed from the
    // blade's (blade_track.hpp) when the track follows it, else asked of the index; with the
    // edges the following found it does not cross.
    SweptElements elements_met(std::uint32_t sweep_index, const BladeMove* blade);
    // The distance from p to the surface the blade swept: the sweeps up to sweep_index and
    // `ahead` (the rest of this movement).
    double distance_to_swept_surface(const Point& p, std::uint32_t sweep_index, std::span<const Sweep> ahead) const;
    // Raises `farthest` to the largest distance_to_swept_surface of `corners` and `farthest_local`
    // to the largest such distance over the mean length of the corner's edges
    // (CutStepReport::placement_error, incision_error).
    void note_distances(std::vector<VertexId> corners, std::uint32_t sweep_index, std::span<const Sweep> ahead,
                        double& farthest, double& farthest_local) const;
    // Whether a loose piece is a crumb: no more material than Options::largest_crumb elements of
    // the mean volume (reference positions), and less than a hundredth of the mesh's elements.
    bool crumb(std::span<const ElementId> piece) const;
    // Finds the pieces the step's cut separated (from m_seeds) and keeps or removes them.
    Outcome<Done> settle_loose_pieces();
    // With a simulation: hold the step's loose pieces and relax.
    void relax(StepReport& report);
    // Options::local_vertices: the simulation's relax_near around what the step changed.
    Outcome<RelaxReport> relax_near_step();

    Options m_options;
    CutServices m_services;
    SpatialIndex m_index;  // deformed positions: where the scalpel meets the mesh
    std::unique_ptr<BladeTrack> m_track;  // the elements the blade lies in
    std::unique_ptr<MovedNodes> m_moves;  // moved since the selection last looked (CutMarks::radius)
    double m_element_volume = 0;  // the mean element volume when the session began (reference)
    double m_split_beyond = 0;    // Options::split_beyond in lengths (0: never split)
    CutMarks m_marks;  // a side log of the session's journal, as m_beside
    // The scalpel beside the mesh, and the number of steps taken: every step changes it, so that
    // its rollback, undo or redo makes the blade track start over (m_beside.on_restore), and the
    // removal's inner steps, which change neither, leave the track alone.
    struct Beside {
        std::optional<Scalpel> scalpel;
        std::uint64_t steps = 0;
        bool operator==(const Beside&) const = default;
    };
    SnapshotLog<Beside> m_beside;
    std::optional<Scalpel>& m_scalpel = m_beside.edit().scalpel;
    std::optional<Scalpel> m_exact;  // cut()'s scalpel, used by apply instead of the pose's
    std::optional<Sweep> m_swept;    // sweep()'s triangle, swept by apply instead of a movement
    CutStepReport m_last;
    std::vector<std::vector<ElementId>> m_loose;  // the step's loose pieces (kept ones)
    std::vector<ElementId> m_seeds;                // the step's elements on both sides of its cut faces
    // the step's dissections' (original, copy) nodes: which seeds were one body (find_loose_pieces)
    std::vector<std::pair<VertexId, VertexId>> m_cut_pairs;
};

}  // namespace sxk::snapcut
