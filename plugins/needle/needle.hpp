// Needle insertion (thesis chapter 6): a rigid needle moves through an elastic body; the mesh is
// refined by bisection around the tip's path, the nodes of the edges the tip enters become needle
// nodes that move with the needle, and stick-slip friction between needle and tissue is solved
// quasi-statically with the constraints projected out of CG (§6.3, §6.6). One needle movement is
// one tool step (sxk/tool_session.hpp): it completes or the mesh and the session are as before,
// and it can be undone.
//
// The interaction loop of §6.7, one pass per step:
//
//     move needle            needle nodes keep (d_needle, d_perp) relative to the needle: sticking
//                            ones are held where that puts them, slipping ones on the line
//                            parallel to the needle at d_perp (free along it, friction on them)
//     refine around the tip  bisection down to h_ref along the tip's path (reference positions)
//     intercept nodes        of every edge (3D: face) the tip's path crosses, the node closest to
//                            the crossing becomes a needle node (§6.4), sticking
//     solve                  CG with eq. 6.9, warm started (the elasticity plug-in's service)
//     rearrange              sticking nodes whose reaction along the needle exceeds the static
//                            threshold slip; slipping nodes the needle no longer passes stick
//     release                slipping nodes the tip has drawn back past, or beyond the base, free
//
//         base                                            tip
//          o==================================================>      needle, axis a
//                   |d_perp        .           .
//                   x--------------+-----------+----- d_needle < 0 behind the tip
//                 needle node
//
// Without the elasticity plug-in (no simulation given) the session still refines and intercepts,
// and tracks the needle nodes' coordinates, but solves nothing: the tissue does not follow the
// needle (only Options::relocate moves nodes), and geometry_only() says so.
//
//     auto session = NeedleSession::make(mesh, options, simulation);   // simulation may be null
//     session->move({base, tip});                                       // one undoable step
//     session->last_step();                                             // what it did
//     session->undo_step();
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "sxk/plugins/elasticity.hpp"
#include "sxk/plugins/needle.hpp"
#include "sxk/locate.hpp"
#include "sxk/ops/tet_bisection.hpp"
#include "sxk/tool_session.hpp"

namespace sxk::needle {

// Needle, Friction and Options: sxk/plugins/needle.hpp (installed).

enum class Grip : std::uint8_t { stick, slip };

// A node on the needle. `along` is d_needle: its signed distance from the tip along the axis
// (negative behind the tip); `perp` is d_perp: its offset from the axis (perpendicular to it).
struct NeedleNode {
    VertexId vertex = invalid_id;
    double along = 0;
    Point perp{0, 0, 0};
    Grip grip = Grip::stick;
    double sense = 0;      // slipping: +1 when the needle moves forward past the node, -1 back
    double threshold = 0;  // the dynamic friction threshold, N (Friction over the node's share)
    double entered = 0;    // `along` when it was intercepted
    double axial = 0;      // the needle's force on the node along the axis at the last solve, N
    bool operator==(const NeedleNode&) const = default;
};

// What one movement did.
struct NeedleStepReport {
    bool tip_inside = false;       // the tip is in the mesh after the movement
    std::size_t bisections = 0;    // new vertices of the refinement
    std::size_t intercepted = 0;   // new needle nodes
    std::size_t relocated = 0;     // of them, moved onto the needle (Options::relocate)
    std::size_t not_relocated = 0; // of them, left where they were: the move would invert
    std::size_t released = 0;      // needle nodes freed (slid off)
    std::size_t stick = 0, slip = 0;  // needle nodes after the step
    std::size_t loosened = 0;      // stick -> slip
    std::size_t gripped = 0;       // slip -> stick
    std::size_t solves = 0;        // CG runs (1 + rearrangements that changed something)
    std::size_t iterations = 0;    // CG iterations, all solves
    std::size_t solved_vertices = 0;  // the last solve's: the region (Options::local_vertices), else all
    std::size_t far_vertices = 0;     // the far field's block solved after it (Options::far_vertices)
    bool converged = true;         // every solve reached eq. 6.9
    bool shown = true;             // the deformed positions were written (not when they invert)
    double axial_force = 0;        // the needle's force on the tissue along its axis, N
    double lateral_force = 0;      // and across it (magnitude), N
    std::size_t elements = 0, vertices = 0;
    double refine_seconds = 0, intercept_seconds = 0, solve_seconds = 0, seconds = 0;
};

class NeedleSession final : public ToolSession {
public:
    // A session on a planar triangle mesh or a tetrahedral mesh. `simulation` (the elasticity
    // plug-in's or the application's, on this mesh; null: geometry only, and the first step's
    // actions say so) must outlive the session. Refuses
    // another kind of mesh and options out of range, with the reason. A tetrahedral mesh gets its
    // bisection marks here (Maubach's on a Kuhn mesh, else AMP's: O(n), once).
    static Outcome<std::unique_ptr<NeedleSession>> make(Mesh& mesh, const Options& options,
                                                        Simulation* simulation = nullptr);
    ~NeedleSession() override;

    // One movement (a step): the first places the needle. Refuses a needle of zero length or with
    // non-finite coordinates.
    Outcome<NeedleStepReport> move(const Needle& needle);
    // A step at the needle's pose that solves the whole body, at most `iterations` CG iterations:
    // the far field catches up with the local solves of Options::local_vertices (for when the
    // needle rests: its cost is the whole body's). Otherwise as a move to where the needle is.
    // Refuses before the first move (not_applicable).
    Outcome<NeedleStepReport> settle(std::size_t iterations);
    const NeedleStepReport& last_step() const { return m_last; }
    std::span<const NeedleNode> nodes() const { return m_state.nodes; }
    const std::optional<Needle>& needle() const { return m_state.needle; }
    bool geometry_only() const { return m_simulation == nullptr; }
    const Options& options() const { return m_options; }

    // A pose from a needle: position the tip, axes[2] along the needle, length its length.
    static ToolPose pose_of(const Needle& needle);

protected:
    Outcome<Done> apply(const ToolPose& pose, StepReport& report) override;

private:
    NeedleSession(Mesh& mesh, const Options& options, Simulation* simulation);

    // The needle and its nodes, beside the mesh: taken back, undone and redone with it
    // (m_beside, a side log of the session's journal).
    struct State {
        std::optional<Needle> needle;
        std::vector<NeedleNode> nodes;
        ElementId tip_element = invalid_id;  // a hint for locating the tip (deformed positions)
        bool operator==(const State&) const = default;
    };
    Outcome<Done> step_to(const Needle& needle, StepReport& words);
    // After the journal put the state back (a refusal's rollback, an undo, a redo): the body's
    // constraints and tool forces as the state says, the nodes of `replaced` it no longer lists
    // released.
    void follow(const State& replaced);
    Outcome<Done> hold(const NeedleNode& node, const Needle& needle);
    // Options::relocate: moves v by -offset in both position sets; false (nothing moved) when that
    // would invert or flatten an element.
    bool relocate(VertexId v, const Point& offset);

    Options m_options;
    Simulation* m_simulation;
    bool m_say_geometry_only = false;  // the first step tells that there is no body
    std::unique_ptr<SpatialIndex> m_reference_index, m_deformed_index;
    // tetrahedral meshes: the bisection's marks (Maubach's on a Kuhn mesh, AMP's otherwise), a
    // side log of the session's journal like m_beside
    std::unique_ptr<TetBisection> m_bisection;
    SnapshotLog<State> m_beside;
    State& m_state = m_beside.edit();
    bool m_resync = false;         // the body reads its displacements from the mesh first
    std::size_t m_settle = 0;      // settle(): this step solves the whole body, at most so many iterations
    NeedleStepReport m_last;
};

}  // namespace sxk::needle
