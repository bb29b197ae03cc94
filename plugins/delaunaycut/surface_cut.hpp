// Cutting triangulated surfaces in space with a line scalpel (thesis §5.3): the 2D scheme's active
// node, remeshing and incision splits on a curved surface, and several incisions at once.
//
//   blade (handle h, tip t), moving linearly between samples; a movement is cut into pieces in
//   which no end of the blade moves farther than d_max (Fig. 5.11): the blade then cannot meet an
//   edge opposite an active node, so each active node finds the blade again in its own triangles.
//
//   entry (Fig. 5.12)                 the first meeting of the sweep with an edge (eq. 5.1, first in
//     through a boundary edge         time; ties by vertex ids) or of the tip's path with a triangle:
//     through an exposed edge         an entry node there; once the blade's pierce points in its star
//     by the tip through a triangle   are eps_entry away, nodes go there and the incision begins:
//                                     opened at once from a boundary node or from two or more pierce
//                                     points (an exposed edge: the cut branches), else a constrained
//                                     edge from the entry node, opened by the first incision split
//   each piece, for each incision     the blade's pierce points in the active node's triangles:
//                                     none: the blade left it (the incision ends); one: the node goes
//                                     there, interior nodes closer than eps_edge are removed and the
//                                     edges around it flipped by the unfolded empty-circle test
//                                     (§5.3.1), the incision split behind it (Fig. 5.5); several: the
//                                     cut branches (Fig. 5.14): a node at each, the edges from the
//                                     old active node to them dissected
//   exit and annihilation (Fig. 5.13) an active node within eps_exit of a boundary edge of its
//                                     triangles, or of an edge whose other triangle holds another
//                                     active node, ahead of it: a node there, and every edge from
//                                     it to an active node dissected; those incisions end. An active
//                                     node within eps_edge of a node next to another active node
//                                     (which may not be removed) ends both incisions through it.
//
// The restrictions of §5.3.2 keep incisions apart: every triangle holds at most one active node (no
// flip joins two, no removal of a node next to two, no entry in a triangle of an active node).
//
// Each movement is one tool step (sxk/tool_session.hpp): it completes or the mesh and the session
// are as before, and it can be undone. The entries are found through a SpatialIndex of the surface,
// everything else in the stars of the active nodes: a movement costs the same on a large surface as
// on a small one.
//
//     auto session = SurfaceCutSession::make(surface, options);   // triangles in space
//     session->cut(handle, tip);                                  // places the blade
//     session->cut(handle2, tip2);                                // a movement: one undoable step
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "planar_cut.hpp"
#include "scalpel_reach.hpp"

namespace sxk::delaunaycut {

// The blade: a segment from the handle end to the tip.
struct Blade {
    Point handle{}, tip{};
    bool operator==(const Blade&) const = default;
};

// The shortest piece of a movement, in mean edges (the blade's faster end): where d_max is shorter
// the blade may leave an active node's triangles within the piece.
inline constexpr double least_piece = 1e-3;

class SurfaceCutSession final : public ToolSession {
public:
    // A session on a triangle surface in space (topological dimension 2, ambient 3), Delaunay
    // cutting only (options.method). Builds a SpatialIndex over the deformed positions and measures
    // the mean edge length (once), and reserves an eighth more room in the mesh's pools. Refuses other
    // meshes, the subdivision method, and thresholds that are not positive and finite.
    static Outcome<std::unique_ptr<SurfaceCutSession>> make(Mesh& mesh, const Options& options);
    ~SurfaceCutSession() override;

    // One step: the blade moves from its last pose to (handle, tip); the first call only places it.
    // ToolSession::step(pose) does the same with the tip at pose.position and the handle
    // pose.length back along pose.axes[2] (the snap cutter's convention).
    Outcome<StepReport> cut(const Point& handle, const Point& tip);
    const CutStepReport& last_step() const { return m_last; }
    const Options& options() const { return m_options; }
    double mean_edge() const { return m_mean_edge; }
    // The incisions' active nodes (and the entry nodes of incisions not yet begun), in order.
    std::vector<VertexId> active_nodes() const;
    const std::optional<Blade>& blade() const { return m_blade; }
    // Why the blade may not be there (ScalpelReach: its tip or handle too far from the surface to
    // place a movement in doubles); nullopt when it may. apply() refuses the step otherwise.
    std::optional<std::string> too_far(const Blade& blade) const;

private:
    SurfaceCutSession(Mesh& mesh, const Options& options, double mean_edge);
    Outcome<Done> apply(const ToolPose& pose, StepReport& report) override;

    enum class Stage {
        entered,      // `node` is the entry node; the blade's pierce points are still near it
        constrained,  // `node` is active, joined to `entry_node` by a labelled (unflippable) edge
        opened,       // `node` is active at the end of an open incision (its cut edges: its fan's ends)
    };
    struct Incision {
        Stage stage = Stage::entered;
        VertexId node = invalid_id;
        VertexId entry_node = invalid_id;  // constrained: the other end of the constrained edge
        Point entry{};                     // where the blade entered
        std::vector<Point> path;           // the pierce points since the incision's last split
        bool operator==(const Incision&) const = default;
    };
    struct State {
        std::vector<Incision> incisions;
        // nodes where a cut ended (and their copies): no entry through their triangles until the
        // blade is twice eps_exit from them (it touches them as it leaves)
        std::vector<VertexId> forbidden;
        bool operator==(const State&) const = default;
    };

    // surface_cut_session.cpp: the movement in pieces of at most d_max.
    Outcome<Done> move(const Blade& from, const Blade& to, CutStepReport& report);
    double safe_move(const Blade& blade) const;
    // surface_entry.cpp: the first entries of the piece from `from` to `to` (all those at the
    // first time), made; the time of the entry (1: none).
    Outcome<double> enter(const Blade& from, const Blade& to, CutStepReport& report);
    // surface_incision.cpp: where the blade is in each incision, and what follows from it.
    Outcome<Done> follow(const Blade& blade, CutStepReport& report);
    // Nodes at the pierce points in the star of incision i's node, and the cut from that node to
    // them: the incision's beginning (from its entry node) or a branch (Fig. 5.14). Incision i
    // ends; each new node not on the boundary is the active node of an incision of its own.
    Outcome<Done> open_from(std::size_t i, const std::vector<std::pair<ElementId, Point>>& pierces,
                            CutStepReport& report);
    // Incision i is over (its node stays where it is); a constrained edge it leaves uncut loses its label.
    void end_incision(std::size_t i);
    // surface_drag.cpp: the active node to the pierce point, and the remeshing around it.
    Outcome<Done> drag(std::size_t i, const Point& target, CutStepReport& report);
    // The blade is no longer in the node's triangles but in one just beyond (a piece at the floor,
    // longer than d_max): the node goes most of the way to the edge in between, the remeshing runs
    // (it flips that edge, as a rule), and the blade is looked for again; its pierce points, or none.
    Outcome<std::vector<std::pair<ElementId, Point>>> catch_up(std::size_t i, const Blade& blade,
                                                               CutStepReport& report);
    void remesh_around(std::size_t i, CutStepReport& report);
    bool remove_close_node(std::size_t i, CutStepReport& report);
    bool flip_around(std::size_t i, CutStepReport& report);
    // surface_incision_split.cpp (Fig. 5.5).
    void split_incision(std::size_t i, CutStepReport& report);
    // surface_exit.cpp (Figs. 5.7, 5.13): true when incision i ended.
    Outcome<bool> try_exit(std::size_t i, const Point& heading, CutStepReport& report);
    Outcome<Done> annihilate(VertexId meeting, CutStepReport& report);

    // Whether v is an incision's node (its active or entry node).
    bool is_active(VertexId v) const;
    // Whether v is next to the nodes of two incisions, or to one other than incision `except`.
    bool separates(VertexId v, std::size_t except) const;
    double eps_edge() const { return m_options.eps_edge * m_mean_edge; }
    double eps_entry() const { return m_options.eps_entry * m_mean_edge; }
    double eps_exit() const { return m_options.eps_exit * m_mean_edge; }

    Options m_options;
    double m_mean_edge;
    // The blade, the incisions and the longest edge (it grows with the cut's edges), a side log of
    // the session's journal: a refused or undone movement takes them back with the mesh
    // (ToolSession::keep_beside).
    struct Beside {
        std::optional<Blade> blade;
        State state;
        double longest_edge = 0;
        bool operator==(const Beside&) const = default;
    };
    SnapshotLog<Beside> m_beside;
    State& m_state = m_beside.edit().state;
    std::optional<Blade>& m_blade = m_beside.edit().blade;
    double& m_longest_edge = m_beside.edit().longest_edge;
    ScalpelReach m_reach;  // the surface's box when the session began, grown by a mean edge
    SpatialIndex m_index;  // deformed positions: where the blade meets the surface first
    std::optional<Blade> m_exact;  // cut()'s blade, bit for bit (the pose rebuilds the handle in doubles)
    CutStepReport m_last;
};

}  // namespace sxk::delaunaycut
