// The two planar cutting methods behind PlanarCutSession (planar_cut.hpp). Private to the plug-in:
// applications make sessions through PlanarCutSession::make or the plug-in's ToolFactory.
#pragma once

#include <optional>

#include "planar_cut.hpp"
#include "planar_walk.hpp"

namespace sxk::delaunaycut {

// Thesis §5.2.2: the scalpel drags an active node; the mesh is remeshed around it.
//
//   delaunay_cut_session.cpp   the movement: entry, dent, fix-up, cutting, exit, in pieces of at
//                              most a quarter of the mean edge (a mouse's samples, §5.4)
//   drag_active_node.cpp       the node follows the scalpel as far as its triangles stay well
//                              above flat; around it close interior nodes go and edges flip
//   entry_fix_up.cpp           the incision begins at the entry point (Fig. 5.6)
//   incision_split.cpp         nodes behind the scalpel where the incision fails the
//                              empty-circle test (Fig. 5.5)
//   predicted_exit.cpp         the extrapolated movement meets the boundary: finish (Fig. 5.7)
class DelaunayCutSession final : public PlanarCutSession {
public:
    DelaunayCutSession(Mesh& mesh, const Options& options, double mean_edge)
        : PlanarCutSession(mesh, options, mean_edge) {}

protected:
    Outcome<Done> move(const Point& from, const Point& to, CutStepReport& report) override;

private:
    // One piece of a movement (at most a quarter of the mean edge).
    Outcome<Done> move_piece(const Point& from, const Point& to, CutStepReport& report);
    // The scalpel crossed the boundary at `entry`: the nearer end of the edge becomes the active
    // node when it is within eps_entry, else a new node there.
    Outcome<Done> enter(const Entry& entry, CutStepReport& report);

    enum class DragEnd { reached, behind, fix_up_due, exited };
    // Moves the active node towards `target`; `heading`: the scalpel's movement, extrapolated for
    // the exit; `fix_up_waits`: the fix-up was refused in this piece (the node does not stop for it).
    Outcome<DragEnd> drag(const Point& target, const Point& heading, bool fix_up_waits, CutStepReport& report);
    // Removes the interior nodes nearer the active node than eps_edge and flips the edges of its
    // triangles that fail the empty-circle test, until neither happens.
    void remesh_around_active(CutStepReport& report);
    bool remove_close_node(CutStepReport& report);
    bool flip_around_active(CutStepReport& report);

    // Begins the incision at the entry point; false when that would invert a triangle (tried
    // again after the next piece of movement).
    Outcome<bool> fix_up(CutStepReport& report);
    // Splits the incision behind the active node while its cut edges fail the empty-circle test.
    void split_incision(CutStepReport& report);
    // The boundary ahead of the active node within eps_exit, along the scalpel's `heading` or
    // towards `target` (where the scalpel is, when the node lags behind it), and when the node is
    // `stuck` also towards the boundary nodes of its ring, in a triangle of its own (flipping the
    // edge in between when it is one triangle further): the cut is finished there (true), or not
    // yet (false).
    Outcome<bool> try_exit(const Point& heading, const Point& target, CutStepReport& report, bool stuck);
};

// Thesis §5.4's baseline: every sliced triangle becomes three, the cut through the crossings.
class SubdivisionCutSession final : public PlanarCutSession {
public:
    SubdivisionCutSession(Mesh& mesh, const Options& options, double mean_edge)
        : PlanarCutSession(mesh, options, mean_edge) {}

protected:
    Outcome<Done> move(const Point& from, const Point& to, CutStepReport& report) override;

private:
    // The node where the path crosses edge (u, v) at `on_edge`: a corner when the crossing is one
    // (or so near one that the split is refused), else a new node.
    Outcome<VertexId> node_on_edge(VertexId u, VertexId v, double on_edge, CutStepReport& report);
    // Opens the edge from the cut's last node to `node`, which becomes the last node.
    Outcome<Done> cut_to(VertexId node, CutStepReport& report);
};

}  // namespace sxk::delaunaycut
