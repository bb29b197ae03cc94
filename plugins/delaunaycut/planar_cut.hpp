// Cutting planar triangle meshes with a point scalpel (thesis chapter 5, §5.2), by two methods
// that share a session, a report and the scalpel's bookkeeping:
//
//   Delaunay cutting (§5.2.2)                     subdivision (§5.4's baseline)
//   the scalpel drags an active node through      every edge the scalpel's path crosses is split
//   the mesh; around it edges flip by the         where it is crossed, and the chord from the last
//   empty-circle test, interior nodes closer      crossing to the new one is dissected: each sliced
//   than eps_edge are removed, and the incision   triangle becomes three, the cut follows the path
//   behind it is split where it fails that test   through every crossing, and the triangles it
//   (Fig. 5.5): few new triangles, round ones     leaves behind are as thin as the path makes them
//
//   scalpel outside ──entry (a boundary edge crossed inwards)──► entering (Delaunay: a dent, the
//   incision postponed, Fig. 5.6) ──fix-up (the active node eps_entry from the entry)──► cutting
//   ──exit (predicted by extrapolation, Fig. 5.7; subdivision: the path crosses the boundary)──►
//   outside again, the cut dissected through
//
// Each movement of the scalpel is one tool step (sxk/tool_session.hpp): it completes or the mesh
// and the session are as before, and it can be undone. A movement's work is local: the entry is
// found through a SpatialIndex of the boundary, and everything after it walks the triangles around
// the scalpel, so a movement costs the same on a mesh of a million triangles as on a small one
// (docs/delaunaycut.md "Performance").
//
//     auto session = PlanarCutSession::make(mesh, options);   // a planar triangle mesh
//     session->cut({x0, y0, 0});                              // places the scalpel
//     session->cut({x1, y1, 0});                              // a movement: one undoable step
//     session->last_step();                                   // what it did
//     session->undo_step();
#pragma once

#include <array>
#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "scalpel_reach.hpp"
#include "sxk/plugins/delaunaycut.hpp"
#include "sxk/locate.hpp"
#include "sxk/side_log.hpp"
#include "sxk/tool_session.hpp"

namespace sxk::delaunaycut {

// Method and Options: sxk/plugins/delaunaycut.hpp (installed).
std::string_view method_name(Method method);


// Options::check and a mesh with no triangle: what both sessions' make() check first.
Outcome<Done> check_options(const Mesh& mesh, const Options& options);

// Where the scalpel is, as far as the session knows.
enum class Phase { outside, entering, cutting };
std::string_view phase_name(Phase phase);

// What one movement did.
struct CutStepReport {
    Phase phase = Phase::outside;      // after the movement
    std::size_t entries = 0;           // times the scalpel entered the mesh
    std::size_t fix_ups = 0;           // incisions begun at an entry (Fig. 5.6)
    std::size_t exits = 0;             // cuts finished at the boundary (Fig. 5.7)
    std::size_t retractions = 0;       // entries left as dents (the scalpel went back out)
    std::size_t moves = 0;             // moves of the active node (a movement may take several)
    std::size_t flips = 0;             // Delaunay flips around the active node
    std::size_t nodes_removed = 0;     // interior nodes removed near the active node
    std::size_t incision_splits = 0;   // incision splits (Fig. 5.5)
    std::size_t edges_split = 0;       // edges split (entries, exits; subdivision: every crossing)
    std::size_t faces_dissected = 0;   // edges opened
    std::size_t collapses = 0;         // short edges contracted after an exit
    // surfaces (surface_cut.hpp): incisions branched, pairs of incisions that met and ended, and
    // the incisions under way after the movement
    std::size_t branches = 0;
    std::size_t annihilations = 0;
    std::size_t incisions = 0;
    // The active node could not go where the scalpel is (a flip or removal it needed was refused):
    // how far it stayed behind, in the mesh's units (0: it is at the scalpel).
    double lag = 0;
    std::string lag_reason;
    std::size_t elements = 0, vertices = 0;  // the mesh's after the movement (vertices: in some element)
    double seconds = 0;
};

// The step's report in words, for StepReport::actions ("3 flips", ...): what both sessions say.
void describe(const CutStepReport& step, StepReport& report);

class PlanarCutSession : public ToolSession {
public:
    // A session of options.method on a planar triangle mesh (topological and ambient dimension
    // 2) with triangles, every one counter-clockwise in the deformed positions. Builds a
    // SpatialIndex over the deformed positions (O(n log n), once), measures the mean edge length
    // (O(n), once) and reserves an eighth more room in the mesh's pools (so that no step copies
    // them). Refuses other meshes and thresholds that are not positive and finite.
    static Outcome<std::unique_ptr<PlanarCutSession>> make(Mesh& mesh, const Options& options);
    ~PlanarCutSession() override;

    // One step: the scalpel moves from its last position to `scalpel` (z ignored); the first call
    // only places it. ToolSession::step(pose) does the same with pose.position.
    Outcome<StepReport> cut(const Point& scalpel);
    // The report of the last step taken (a refused step's says how far it got).
    const CutStepReport& last_step() const { return m_last; }
    const Options& options() const { return m_options; }
    // The mean edge length the thresholds are measured in.
    double mean_edge() const { return m_mean_edge; }
    Phase phase() const { return m_state.phase; }
    // The node the scalpel drags (Delaunay) or the cut's last node (subdivision); invalid_id outside.
    VertexId active_node() const { return m_state.active; }
    const std::optional<Point>& scalpel() const { return m_scalpel; }
    // Why the scalpel may not be at p (ScalpelReach): nullopt when p is near enough; apply()
    // refuses the step otherwise (bad_argument).
    std::optional<std::string> too_far(const Point& p) const { return m_reach.too_far(p, "the scalpel"); }

protected:
    PlanarCutSession(Mesh& mesh, const Options& options, double mean_edge);
    Outcome<Done> apply(const ToolPose& pose, StepReport& report) override;

    // What a method keeps between movements (restored when a movement is refused or undone).
    struct State {
        Phase phase = Phase::outside;
        VertexId active = invalid_id;
        // entering (Delaunay): where the scalpel entered (deformed and reference positions)
        Point entry{}, entry_reference{};
        // cutting (Delaunay): the scalpel's path since the incision's last split, first point first
        std::vector<Point> path;
        // after an exit: boundary edges (vertex pairs) no entry may cross until the scalpel is
        // farther than twice eps_exit from the exit point
        std::vector<std::array<VertexId, 2>> forbidden;
        Point exit_point{};
        bool operator==(const State&) const = default;
    };

    // The method: the scalpel moves from `from` to `to` (z = 0); edits through the mesh's
    // operations, state changes in m_state. A refusal takes everything back.
    virtual Outcome<Done> move(const Point& from, const Point& to, CutStepReport& report) = 0;

    // Where a movement from `from` to `to` first crosses a boundary edge inwards (the mesh on the
    // edge's left, `from` not on its left and `to` strictly on it), skipping m_state.forbidden;
    // none when it does not. Asks the spatial index for the boundary edges the segment meets.
    struct Entry {
        VertexId u = invalid_id, v = invalid_id;  // the edge, the mesh on its left
        double along = 0;                         // where on the movement, 0 at `from`, 1 at `to`
        double on_edge = 0;                       // where on the edge, 0 at u, 1 at v
        Point at{};
    };
    std::optional<Entry> first_entry(const Point& from, const Point& to) const;
    // Whether p lies in a triangle of the mesh (closed), by the spatial index.
    bool in_mesh(const Point& p) const;
    // Forgets the forbidden edges once `scalpel` is far enough from the exit.
    void expire_forbidden(const Point& scalpel);
    // In mesh units.
    double eps_edge() const { return m_options.eps_edge * m_mean_edge; }
    double eps_entry() const { return m_options.eps_entry * m_mean_edge; }
    double eps_exit() const { return m_options.eps_exit * m_mean_edge; }

    Options m_options;
    double m_mean_edge;
    // the mesh's bounding box when the session began, grown by a mean edge: the cuts stay in it
    ScalpelReach m_reach;
    // The scalpel and the method's state, a side log of the session's journal: a refused or
    // undone movement takes them back with the mesh (ToolSession::keep_beside).
    struct Beside {
        std::optional<Point> scalpel;
        State state;
        bool operator==(const Beside&) const = default;
    };
    SnapshotLog<Beside> m_beside;
    State& m_state = m_beside.edit().state;

private:
    SpatialIndex m_index;  // deformed positions: where the scalpel meets the boundary
    std::optional<Point>& m_scalpel = m_beside.edit().scalpel;
    CutStepReport m_last;
};

}  // namespace sxk::delaunaycut
