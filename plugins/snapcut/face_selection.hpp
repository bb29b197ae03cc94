// Face selection of the snap cut (thesis §3.2.1, Figs. 3.1-3.4).
//
// A sweep triangle is tested against the edges of the tetrahedra it meets (exact segment/triangle
// test, deformed positions). Each edge crossed marks the end nearer the crossing (the exact
// comparison of the ends' distances to the sweep's plane, which is the comparison along the edge;
// an exact half marks the lower vertex id, as the thesis does). A tetrahedron's marked ends are a
// vertex, an edge, a face or all four corners:
//
//        one           two: an edge      three: that face      four (all edges halved, or
//        marked        (incomplete)      is selected           marks of different sweeps): the
//        (incomplete)                                          face without the highest vertex id
//
// The selection sees the mesh as it was before the cut snapped anything (CutMarks::
// selection_position). Snapping a node onto one sweep would otherwise change which end of its
// edges a later sweep marks (a node on the sweep is always the nearer end), and the tetrahedra
// selected by the earlier sweep and by the later one would no longer agree on where the surface
// runs: the incision gets holes (a through cut of the thesis' cube in 2 to 64 steps left the
// cube in one piece). Seen in the positions before snapping, the selection of consecutive sweeps
// is the selection of one piecewise flat surface, which closes up.
//
// Corners snapped elsewhere. A corner counts as marked in a tetrahedron when one of the
// tetrahedron's own edges marks it (the thesis' rule), and that alone can leave a hole. Take a face
// F = (u, v, w) between tetrahedra (x, F) and (y, F), x and y off the cut on either side of it:
// where u, v and w all end up on the cut, F is the cut between x and y. But F is selected only if
// one of its tetrahedra sees all three marked by its own edges, and x's may see u and v only (w
// was marked and snapped from an edge of another tetrahedron), y's w only (u and v lie on x's
// side before the snap): neither selects F, and x and y stay joined. So a tetrahedron the sweep
// crosses (a corner marked by its own edges) whose snapped corners make three with its own marked
// ones selects their face; the fourth is off the cut. And so does a tetrahedron with no marked
// corner at all whose corners are snapped but one: the selection sees the snapped corners where
// they were, on the side of the fourth corners, and then neither x's edges nor y's cross a sweep
// (a through cut of the 1.2M femur stayed joined across such an F, y a sliver along the cut
// with its fourth corner 0.02 h off it; the rule is looked at only in the elements the selection
// is handed, those around nodes snapped since the last selection among them).
//
//        x                 marked by x's tetrahedron's edges: u, v (o)
//       /|\                snapped, marked elsewhere: w (*)
//      o-+-*   F = u v w   the face F is selected from x's tetrahedron
//       \|/
//        y
//
// Where y's tetrahedron is flat along the cut (all four corners on it), it is then cut off on
// both sides, with other flat ones next to it: a layer of little material the faces close off,
// which the step keeps attached by one face (loose_pieces.hpp, "Layers") or, should it come loose
// all the same, cuts free as a crumb (Options::largest_crumb). Leaving F closed there instead left
// bridges (1 in 10 random through cuts of the 1.2M femur). Counting the nodes marked by other
// edges but not snapped yet as on the cut too separates as well, but opened faces that left the
// thesis' cube cut (docs/snapcut.md) with an element CG could not settle (20000 iterations, 380
// without). A haptic device's steps met the holes first: the femur cut at 1 kHz stayed in one
// piece, as did 9 of 20 random through cuts of the shaft at 1 to 50 steps per movement; all of
// them come apart now (docs/snapcut.md, "At a haptic device's rate").
//
// Marks are kept from sweep to sweep (CutMarks), so a later sweep completes the tetrahedra an
// earlier one left incomplete (Fig. 3.4: selected faces lag behind the scalpel), and an edge is
// marked by the first sweep that crosses it only (an edge crossed twice by sweeps of different
// orientations would otherwise mark both its ends). Faces on the boundary are never selected:
// there is nothing to open.
//
// Where the sweep is searched. The thesis tests the whole boundary for collisions and walks from
// those and from the incomplete tetrahedra. Here the candidates are the elements whose closed
// simplex meets the sweep triangle: followed from those the blade lay in before the sweep
// through the edges it crosses (blade_track.hpp, close_over_crossed_edges below), or asked of the
// spatial index (SpatialIndex::elements_hit_by_triangle: an R-tree query and an exact test each)
// when there is nothing to follow. Every tetrahedron with an edge the sweep crosses is among
// them, the incomplete ones it completes included (a tetrahedron gains a mark only through an
// edge the sweep crosses), and besides them only the elements whose count of corners on the cut
// changed since the last selection: the "corners snapped elsewhere" rule may complete those
// wherever the sweep is (CutMarks::pending and look_again). The incomplete tetrahedra are those of
// the last sweep's candidates with one or two marked corners, kept for the report.
#pragma once

#include <cstddef>
#include <algorithm>
#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <unordered_map>
#include <utility>
#include <vector>

#include "sxk/detail/flat_set.hpp"
#include "sxk/mesh.hpp"
#include "sxk/side_log.hpp"

namespace sxk::snapcut {

struct SweptSurface;

// A sweep triangle, in the deformed positions.
struct Sweep {
    Point a{}, b{}, c{};
};

// The distance from p to the nearest point of the sweep triangle, and its square (double
// precision: quantities, not decisions).
double distance_to_sweep(const Sweep& sweep, const Point& p);
double squared_distance_to_sweep(const Sweep& sweep, const Point& p);

// What the cut keeps between sweeps. A side log of the session's journal (sxk/side_log.hpp): a
// step's marks, snapped nodes and sweeps, and the lists the next selection reads, are taken back,
// undone and redone with the mesh. (The snapped nodes' radii only grow, and are not taken back: a
// larger one finds more elements, never fewer.)
class CutMarks final : public SideLog {
public:
    CutMarks();
    ~CutMarks();
    CutMarks(const CutMarks&) = delete;
    CutMarks& operator=(const CutMarks&) = delete;

    struct Mark {
        VertexId node = invalid_id;  // the end of the edge nearer the crossing
        std::uint32_t sweep = 0;     // the sweep that crossed the edge (index into sweeps())
    };

    // The mark of edge {a, b}, if a sweep crossed it. Most edges along the blade have an end with
    // no marked edge at all: those are answered from a per-vertex count, without a hash lookup.
    std::optional<Mark> mark(VertexId a, VertexId b) const {
        if (!has_marked_edge(a) || !has_marked_edge(b)) return std::nullopt;
        return find_mark(a, b);
    }
    // Whether some marked edge ends at v.
    bool has_marked_edge(VertexId v) const { return v < m_marks_at.size() && m_marks_at[v] > 0; }
    void add_mark(VertexId a, VertexId b, const Mark& mark);
    std::size_t mark_count() const { return m_marks.size(); }

    const std::vector<Sweep>& sweeps() const { return m_sweeps; }
    std::uint32_t add_sweep(const Sweep& sweep);
    // Whether p is within `distance` of a sweep so far (the sweeps' tree, then the triangles whose
    // boxes come that near).
    bool near_sweeps(const Point& p, double distance) const;
    // The distance from p to the nearest sweep so far, if less than `at_most`; else `at_most`
    // (the sweeps whose boxes come that near are measured).
    double distance_to_sweeps(const Point& p, double at_most) const;

    // Marks follow the mesh's edits (thesis §3.4: every change of the mesh must also be applied to
    // the cutting module's references). Marks live on vertex pairs, and an edit that renames or
    // makes vertices makes edges no sweep has seen: the tetrahedra at the incision's rim that hold
    // them could never be completed, and the incision would stop there.
    //
    // A dissection's copy takes over some of its original's edges: edge {copy, x} takes the mark
    // of {original, x0} (x0: x's original when x is a copy of the same dissection, else x), the
    // marked end mapped along. The copy sits where its original is, as the selection sees it, so
    // this is the mark a sweep would have given.
    void carry_to_copies(const Mesh& mesh, std::span<const std::pair<VertexId, VertexId>> copies);
    // The degeneracy removal's edits (a split's new vertex, a collapse's or a flip's new edges):
    // each unmarked edge of `elements` (dead ids skipped) is tested against the sweeps so far,
    // oldest first, and the first it crosses marks it if its nearer end is a node on the cut
    // already (snapped) or, with `swept`, near the swept surface (SweptSurface::near). The edges
    // are seen where they are, not where the selection sees the mesh: a split's vertex has no
    // place from before the snapping, and an edge from a node that never moved to where a
    // snapped one was can cross a sweep the edge as it lies does not (tried: the cube cut through
    // in 16 steps then lost a small piece). A mark that would pull a node far from the cut onto it
    // is left out: the new marks join the incision's rim to the surface already cut, they do not
    // move it. But a node the removal made after the blade passed, 0.03 h from the cut, is on it
    // in all but name: left unmarked, its edges across the cut held the femur cut at 1 kHz
    // together.
    void mark_from_earlier_sweeps(const Mesh& mesh, std::span<const ElementId> elements,
                                  const SweptSurface* swept = nullptr);
    // Elements that gained a marked edge outside a selection (the two calls above), sorted: they
    // may now be complete, so the next selection looks at them (take_pending empties the list).
    const std::vector<ElementId>& pending() const { return m_lists.pending; }
    std::vector<ElementId> take_pending() {
        before_lists_change();
        return std::exchange(m_lists.pending, {});
    }

    // Elements the "corners snapped elsewhere" rule (select_faces) may have completed wherever the
    // sweep is: those around nodes snapped since the last selection and those edits made. A
    // tetrahedron a sweep does not meet gains no mark from it, so the count of its corners on the
    // cut changes only when a corner is snapped, a mark is carried over (pending) or the element
    // is remade: the next selection looks at these once, and at no other element the sweep does
    // not meet (take_look_again empties the list).
    void look_again(std::span<const ElementId> elements) {
        before_lists_change();
        m_lists.look_again.insert(m_lists.look_again.end(), elements.begin(), elements.end());
    }
    std::vector<ElementId> take_look_again() {
        before_lists_change();
        return std::exchange(m_lists.look_again, {});
    }

    // The last sweep's candidates with one or two marked corners (sorted).
    const std::vector<ElementId>& incomplete() const { return m_lists.incomplete; }
    void set_incomplete(std::vector<ElementId> incomplete) {
        before_lists_change();
        m_lists.incomplete = std::move(incomplete);
    }

    // Nodes moved onto the sweep once already: they stay where the cut put them.
    bool snapped(VertexId v) const { return v < m_nodes.size() && m_nodes[v].snapped; }
    // Records that v was snapped from deformed position `was` (a copy of a snapped node made by
    // dissection is recorded with its original's), and covers its star (radius). `was` by value:
    // a copy's is its original's selection_position, a reference into the table this may grow.
    void add_snapped(const Mesh& mesh, VertexId v, Point was);
    // Every element with a snapped corner that meets the sweep as the selection sees it
    // (selection_position), sorted, each once: in the stars of the snapped nodes whose own reach
    // (radius) comes as near as the sweep, the elements that reach from the node as far as the
    // sweep is (an element lies in the ball about any of its corners through its farthest
    // corner), not parted from it by its planes in doubles, and met in meets_as_selected's test. Those in
    // `known` (sorted: elements the caller has already, such as the ones the blade the sweep
    // starts from lies in) are left out untested.
    std::vector<ElementId> elements_near(const Mesh& mesh, const Sweep& sweep,
                                         std::span<const ElementId> known = {}) const;
    // How far a snapped node's star reaches from the node, as the selection sees both; it only
    // grows, and must grow whenever the star comes to reach farther (elements_near misses the
    // star otherwise): widened to the whole star when the node is snapped (add_snapped), to the
    // elements each edit makes or changes (cover_elements), to every star when the simulation
    // moves the nodes (cover_all).
    double radius(VertexId v) const { return v < m_nodes.size() ? m_nodes[v].radius : 0.0; }
    // cover_star: the elements around v; cover_elements: every snapped corner of `elements`.
    void cover_star(const Mesh& mesh, VertexId v);
    void cover_elements(const Mesh& mesh, std::span<const ElementId> elements);
    void cover_all(const Mesh& mesh);
    // Where the selection sees v: where it was before this cut snapped it, else where it is.
    const Point& selection_position(const Mesh& mesh, VertexId v) const {
        return snapped(v) ? m_nodes[v].was : mesh.deformed(v);
    }
    // The corners of element t where the selection sees them.
    std::array<Point, 4> selection_corners(const Mesh& mesh, ElementId t) const {
        const Simplex& s = mesh.simplex(t);
        return {selection_position(mesh, s.vertex(0)), selection_position(mesh, s.vertex(1)),
                selection_position(mesh, s.vertex(2)), selection_position(mesh, s.vertex(3))};
    }

    // SideLog
    std::size_t mark() override;
    void rollback_to(std::size_t mark) override;
    void keep(std::size_t mark) override;
    std::unique_ptr<SideRecord> commit(std::size_t mark) override;
    std::unique_ptr<SideRecord> replay(std::unique_ptr<SideRecord> record) override;

private:
    static std::uint64_t key(VertexId a, VertexId b);
    std::optional<Mark> find_mark(VertexId a, VertexId b) const;  // the hash lookup of mark()
    std::unordered_map<std::uint64_t, Mark> m_marks;
    std::vector<std::uint64_t> m_mark_order;  // keys by insertion: restore erases the newest
    std::vector<std::uint32_t> m_marks_at;    // per vertex id, the marked edges ending there
    void count_marks_at(std::uint64_t key, int change);
    // Per vertex id, up to the highest one snapped: whether the cut snapped it, where
    // from, and its radius. The elements around snapped nodes near a sweep ask for about 2000
    // corners on the 1.2M femur at 1 kHz; a hash map of the snapped ones' places cost 5 % of the
    // step in its lookups (docs/performance.md "Proven dissection and each node's own reach").
    struct Node {
        Point was{};
        double radius = 0;
        bool snapped = false;
    };
    std::vector<Node> m_nodes;
    std::vector<VertexId> m_snapped_order;
    struct SnappedTree;  // the snapped nodes by position before snapping (Boost.Geometry rtree)
    std::unique_ptr<SnappedTree> m_tree;
    double m_reach = 0;            // the largest radius: how far from the sweep the tree is asked
    Node& node(VertexId v);  // grows m_nodes to hold v
    std::vector<Sweep> m_sweeps;
    struct SweepTree;  // the sweeps by their boxes (Boost.Geometry rtree)
    std::unique_ptr<SweepTree> m_sweep_tree;
    // Calls visit(the distance from p) for each sweep whose box comes within `distance` of p, until
    // one returns true; whether one did.
    template <class Visit>
    bool for_sweeps_near(const Point& p, double distance, Visit visit) const;
    // The sweeps whose boxes meet the box [low, high], oldest first.
    std::vector<std::uint32_t> sweeps_meeting_box(const Point& low, const Point& high) const;
    // Marks {u, v} (when it has no mark) and puts the elements around the edge (those of u's star
    // `star_u` that hold v) in pending; settle_pending sorts pending and drops repeats.
    void mark_outside_selection(const Mesh& mesh, std::span<const ElementId> star_u, VertexId u, VertexId v,
                                const Mark& mark);
    void settle_pending();
    // What the next selection reads besides the marks.
    struct Lists {
        std::vector<ElementId> incomplete, pending, look_again;
    };
    Lists m_lists;
    // The open steps (mark()): how many marks, snapped nodes and sweeps there were, and the lists
    // as they were, copied when they first change inside the step (the degeneracy removal's
    // many inner steps change none of them, and copy nothing).
    struct Opened {
        std::size_t marks = 0, snapped = 0, sweeps = 0;
        std::shared_ptr<const Lists> lists;  // null while unchanged since the mark
    };
    std::vector<Opened> m_opened;
    void before_lists_change();
    // Forgets the marks, snapped nodes and sweeps after the first so many (the newest).
    void trim(std::size_t marks, std::size_t snapped, std::size_t sweeps);
    struct Record;
};

// Where the blade has swept: the sweeps so far (those of `marks`) and the rest of the movement
// being cut (`ahead`). A node farther than `beyond` from it is far from the cut: snapped onto a
// sweep's plane it may land beyond where the blade went (ahead of it, where it turned), and a long
// move is often refused or cut short (node_snapping.hpp). So its crossed edges are split where
// crossed (split_far_crossings.hpp), and an edge whose other end is a node on the cut marks that
// end (select_faces).
struct SweptSurface {
    const CutMarks& marks;
    std::span<const Sweep> ahead;
    double beyond = 0;
    // p is within `beyond` of the swept surface.
    bool near(const Point& p) const;
};

// A face chosen for the cut, with the nodes to snap and the sweep whose plane each goes to.
struct SelectedFace {
    Simplex face;                           // sorted vertices, sign +1
    std::array<std::uint32_t, 3> sweep{};   // per face vertex (face.vertex(j)): the first sweep
                                            // that marked it from this tetrahedron's edges
};

struct Selection {
    std::vector<SelectedFace> faces;  // interior faces, each once, by face vertices
    std::size_t edges_hit = 0;        // edges this sweep marked
    std::size_t elements_searched = 0;
};

// Live element t meets the closed triangle (a, b, c) (collinear corners: the segment between the
// two farthest) as the selection sees the mesh (CutMarks::selection_position), exactly; an element
// flat as the selection sees it (a dissection's copy where its original was) meets it where one of
// its edges crosses it.
bool meets_as_selected(const Mesh& mesh, const CutMarks& marks, ElementId t, const Point& a, const Point& b,
                       const Point& c);
// Live element t meets the closed segment [a, b] (a blade) as the selection sees the mesh, exactly.
bool meets_as_selected(const Mesh& mesh, const CutMarks& marks, ElementId t, const Point& a, const Point& b);

// Edges by their ends (lower id in the high half) that a sweep does not cross as the selection
// sees the mesh.
using MissedEdges = detail::FlatSet<std::uint64_t>;

struct SweptElements {
    std::vector<ElementId> elements;  // sorted, each once
    MissedEdges missed;               // the edges of `elements` the sweep does not cross
};

// The live elements of `roots` and, until none is added, those around every edge of one of them
// that the sweep crosses (as the selection sees the mesh, marked or not), each edge tested once.
// From the elements a blade lay in before the sweep, where its ends went and where the sweep
// meets the boundary, these are the elements the sweep meets (blade_track.hpp).
SweptElements close_over_crossed_edges(const Mesh& mesh, const CutMarks& marks, const Sweep& sweep,
                                       std::span<const ElementId> roots);

// Processes sweep `sweep_index` of `marks` against the tetrahedra `candidates` (what the sweep
// meets; dead ids are skipped): marks the edges it crosses, selects the
// faces completed, and leaves the incomplete tetrahedra in `marks`. Deformed positions.
//
// With `swept` (the cut snaps and splits far crossings), an edge from a node on the cut (snapped)
// whose nearer end is far from the swept surface marks the snapped end: the selection sees the
// snapped node where it was, and the edge it sees crosses the sweep where the edge as it lies
// does not, so the far end cannot be split out (split_far_crossings.hpp) and, snapped onto the
// sweep's plane, it would sit beyond where the blade went (on the deforming femur 1.44 h off, where
// the blade turned).
//
// `missed`: edges known not to cross the sweep as the selection sees the mesh (those
// close_over_crossed_edges tested), not tested again.
Selection select_faces(const Mesh& mesh, CutMarks& marks, std::uint32_t sweep_index,
                       std::span<const ElementId> candidates, const SweptSurface* swept = nullptr,
                       MissedEdges missed = {});

}  // namespace sxk::snapcut
