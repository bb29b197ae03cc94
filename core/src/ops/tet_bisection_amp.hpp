// Private: Arnold-Mukherjee-Pouly refinement to conformity (SIAM J. Sci. Comput. 22, 2000, §3:
// "bisect the marked tetrahedra, then bisect every tetrahedron with a hanging node at its own
// refinement edge until none is left") on a PLAN overlay of the mesh, for the rule
// BisectionRule::arnold_mukherjee_pouly of TetBisection.
//
// Unlike TetBisectionPlan (one split_edge per step, which halves every tetrahedron around the
// edge, so the mesh is conforming after every step), a step here bisects ONE tetrahedron at its
// refinement edge; the overlay is non-conforming in between. The midpoint of an edge is one
// vertex, shared by every tetrahedron that bisects that edge later. A leaf of the overlay "has a
// hanging node" when the midpoint of one of its six edges exists; the closure bisects such
// leaves (AMP prove it ends, and that the result is conforming with a conforming marking).
//
// Locality: the overlay keeps, per vertex it has touched, the leaves containing it (for a mesh
// vertex initialised from the mesh's star on first use, descending into the overlay's children
// of elements already bisected); the leaves around edge uv are those of u's list containing v.
// Nothing walks the whole mesh.
//
// New vertices are numbered vertex_count(), vertex_count()+1, ... in plan order with positions
// by Mesh::interpolated_positions' arithmetic for ({a, b}, {0.5, 0.5}) (first term assigned,
// second added), so the replay's add_interpolated_vertex gives the same ids and bit-identical
// positions; every child is checked to keep its parent's exact orientation, nonzero, in the
// reference and deformed positions (split_edge's rule) before it enters the overlay.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "sxk/mesh.hpp"
#include "sxk/ops/tet_bisection.hpp"
#include "sxk/outcome.hpp"
#include "sxk/predicates.hpp"

namespace sxk::detail {

class AmpClosurePlan {
public:
    struct Node {
        Simplex simplex;
        TetMarking marking;
        ElementId root = invalid_id;  // the original element this node descends from
        bool alive = true;
        std::array<int, 2> children{-1, -1};
    };
    // A planned vertex: the midpoint of the edge ab (as add_interpolated_vertex({a, b}, ...)).
    struct NewVertex {
        VertexId a = invalid_id, b = invalid_id;
        Point reference{}, deformed{};
    };

    // `markings` are the state's marks of the mesh's elements (indexed by ElementId).
    AmpClosurePlan(const Mesh& mesh, const std::vector<TetMarking>& markings);

    // The overlay node of an original element (created on first use).
    int node_of(ElementId t);
    const Node& node(int n) const { return m_nodes[static_cast<std::size_t>(n)]; }
    std::size_t node_count() const { return m_nodes.size(); }

    // Bisects leaf n at its refinement edge, then closes to conformity. Nothing on success;
    // after a refusal the overlay must be dropped. `did_not_end` is set when the closure
    // passed its bound (64 + 8 * leaves when it started), which turns a marking whose closure
    // does not end into a refusal; AMP's marks never reach it.
    std::optional<Refusal> bisect_and_close(int n, bool& did_not_end);

    // The leaf containing x (closed test, reference positions) among n and its descendants; the
    // first child when rounding of a midpoint leaves x in neither.
    int leaf_containing(int n, const Point& x) const;
    // Length of the refinement edge of node n in the reference positions.
    double refinement_length(int n) const;

    VertexId base() const { return m_base; }
    const std::vector<NewVertex>& new_vertices() const { return m_new_vertices; }
    // The original elements bisected, sorted by id.
    std::vector<ElementId> refined_originals() const;
    // The leaves below original element t (depth first, first child first).
    void append_leaves(ElementId t, std::vector<int>& leaves) const;
    // True when planned or mesh vertex v lies on the triangle `face` (mesh vertices): v is one
    // of its corners or the midpoint of two vertices that lie on it.
    bool lies_on(VertexId v, const Simplex& face) const;

private:
    static std::uint64_t key(VertexId u, VertexId v) {
        const VertexId low = u < v ? u : v, high = u < v ? v : u;
        return (std::uint64_t(low) << 32) | high;
    }
    const Point& position(VertexId v, Positions positions) const;
    Sign orientation(const Simplex& s, Positions positions) const;
    bool contains(int n, const Point& x) const;
    bool has_hanging_node(int n) const;
    // The leaves containing v (initialised from the mesh's star on first use).
    std::vector<int>& leaves_with(VertexId v);
    void append_leaves_with(int n, VertexId v, std::vector<int>& out) const;
    // One bisection of leaf n; the leaves that may now have a hanging node go to `work`.
    std::optional<Refusal> bisect(int n, std::vector<int>& work);

    const Mesh& m_mesh;
    const std::vector<TetMarking>& m_markings;
    VertexId m_base;
    std::vector<Node> m_nodes;
    std::vector<NewVertex> m_new_vertices;
    std::unordered_map<ElementId, int> m_original;
    std::unordered_map<std::uint64_t, VertexId> m_midpoint;  // edge -> its planned midpoint
    std::unordered_map<VertexId, std::vector<int>> m_leaves_with;
};

// bisect_tetrahedron(state, t) and refine_around_tetrahedra(state, x, h) for the AMP rule, after
// their argument checks (t an element, the state not stale, t the element containing x): plan on
// the overlay, then replay as one transaction (amp_replay). Refusal reasons come without the
// operation's prefix ("new element -<12,13,27,29> would be flat in the deformed positions").
Outcome<std::size_t> amp_bisect(TetBisection& state, ElementId t);
Outcome<std::size_t> amp_refine_around(TetBisection& state, ElementId t, const Point& x, double h);

}  // namespace sxk::detail
