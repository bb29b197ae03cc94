// Private: a bisection PLAN for 3D (bisect_tetrahedron, refine_around_tetrahedra), the 3D
// counterpart of bisect_2d_helpers.hpp's BisectionPlan. The recursion of thesis §6.5 bisect(e)
// runs first on a scratch overlay of the mesh; only when every planned split has passed the
// checks split_edge makes are the splits replayed through split_edge (which then cannot
// refuse). So a bisection, or a whole refine-around, either completes or leaves the mesh and the
// bisection state as they were, with no watcher event.
//
// The overlay holds the tetrahedra the plan has created (their vertices numbered
// vertex_count(), vertex_count()+1, ... in plan order, exactly as the replay's split_edge calls
// will number them; midpoints by Mesh::interpolated_positions' formula, so bit for bit the
// replay's) and remembers which original elements it has split. "Tetrahedra around edge ab"
// are the mesh's elements_with_edge (star(a) order) minus the originals split, then the overlay
// tetrahedra containing a and b in creation order. That is not the order star(a) would give on
// the mesh after the splits, so blockers can be met in another order than in a split-by-split
// run: the same edges are split (each split of the recursion is forced, so the refinement is
// the same geometric mesh; checked against the split-by-split code on Kuhn, jittered and
// Delaunay meshes), only new vertices and elements can be numbered differently. Cost:
// O(number of planned splits) memory and hash look-ups per step, as local as the bisections.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <tuple>
#include <unordered_map>
#include <utility>
#include <vector>

#include "ops/edge_star.hpp"
#include "ops/orientation_checks.hpp"
#include "ops/tet_bisection_recursion.hpp"
#include "sxk/mesh.hpp"
#include "sxk/ops/split_edge.hpp"
#include "sxk/ops/tet_bisection.hpp"
#include "sxk/outcome.hpp"
#include "sxk/predicates.hpp"

namespace sxk::detail {

using TetEdge = std::array<VertexId, 2>;

// The strict total order on edges of the longest-edge rule: squared length in the reference
// positions, then the vertex ids. Computed from the sorted pair, so every element sees the same
// value for a shared edge.
struct TetEdgeKey {
    double length_squared;
    VertexId low, high;
    friend bool operator<(const TetEdgeKey& p, const TetEdgeKey& q) {
        return std::tie(p.length_squared, p.low, p.high) <
               std::tie(q.length_squared, q.low, q.high);
    }
};

template <class ReferenceOf>  // const Point& reference_of(VertexId)
TetEdgeKey tet_edge_key(ReferenceOf&& reference_of, VertexId u, VertexId v) {
    const VertexId low = u < v ? u : v, high = u < v ? v : u;
    const Point& p = reference_of(low);
    const Point& q = reference_of(high);
    double sum = 0;
    for (std::size_t k = 0; k < 3; ++k) sum += (q[k] - p[k]) * (q[k] - p[k]);
    return {sum, low, high};
}

// The longest-edge marking of a tetrahedron with the given vertices (sxk::longest_edge_marking,
// for positions that need not be in the mesh yet): refinement edge and face marks the longest
// edges under the strict order above.
template <class ReferenceOf>
TetMarking longest_edge_marking_of(std::span<const VertexId> v, ReferenceOf&& reference_of) {
    auto key = [&](VertexId p, VertexId q) { return tet_edge_key(reference_of, p, q); };
    std::size_t best_i = 0, best_j = 1;
    for (std::size_t i = 0; i < 4; ++i)
        for (std::size_t j = i + 1; j < 4; ++j)
            if (key(v[best_i], v[best_j]) < key(v[i], v[j])) {
                best_i = i;
                best_j = j;
            }
    // the vertex of face {x,y,z} that is not on the face's longest edge
    auto unmarked_of_longest = [&](VertexId x, VertexId y, VertexId z) {
        const TetEdgeKey xy = key(x, y), yz = key(y, z), xz = key(x, z);
        if (yz < xy && xz < xy) return z;
        if (xy < yz && xz < yz) return x;
        return y;
    };
    TetMarking marking;
    marking.vertices[0] = v[best_i];
    marking.vertices[1] = v[best_j];
    std::size_t next = 2;
    for (std::size_t i = 0; i < 4; ++i)
        if (i != best_i && i != best_j) marking.vertices[next++] = v[i];
    const VertexId a = marking.vertices[0], b = marking.vertices[1];
    const VertexId c = marking.vertices[2], d = marking.vertices[3];
    marking.acd_unmarked = unmarked_of_longest(a, c, d);
    marking.bcd_unmarked = unmarked_of_longest(b, c, d);
    return marking;
}

class TetBisectionPlan {
public:
    struct Node {
        Simplex simplex;
        TetMarking marking;
        bool alive = true;
        std::array<int, 2> children{-1, -1};
    };

    // initial_marking(ElementId) gives the marking of an original element; children are marked
    // by `rule` (newest_vertex: bisected_markings; longest_edge: their own longest edge).
    template <class InitialMarking>
    TetBisectionPlan(const Mesh& mesh, BisectionRule rule, InitialMarking&& initial_marking)
        : m_mesh(mesh),
          m_rule(rule),
          m_base(static_cast<VertexId>(mesh.vertex_count())),
          m_initial(std::forward<InitialMarking>(initial_marking)) {}

    const Point& reference(VertexId v) const {
        return v < m_base ? m_mesh.reference(v) : m_reference[v - m_base];
    }
    const Point& position(VertexId v, Positions positions) const {
        if (v < m_base)
            return positions == Positions::reference ? m_mesh.reference(v) : m_mesh.deformed(v);
        return positions == Positions::reference ? m_reference[v - m_base] : m_deformed[v - m_base];
    }
    const Node& node(int n) const { return m_nodes[static_cast<std::size_t>(n)]; }
    // The planned splits in order, each as split_edge(mesh, a, b, 0.5) will get it.
    const std::vector<TetEdge>& splits() const { return m_splits; }
    std::size_t element_count() const { return m_mesh.element_count() + m_added_elements; }

    // The overlay node of an original element (created on first use).
    int node_of(ElementId t) {
        const auto [it, inserted] = m_original.try_emplace(t, static_cast<int>(m_nodes.size()));
        if (inserted) m_nodes.push_back(Node{m_mesh.simplex(t), m_initial(t)});
        return it->second;
    }
    TetEdge refinement_edge(int n) const {
        return {node(n).marking.vertices[0], node(n).marking.vertices[1]};
    }
    // The live tetrahedra (after the planned splits) containing the edge ab.
    std::vector<int> tetrahedra_with_edge(VertexId a, VertexId b) {
        std::vector<int> result;
        if (a < m_base && b < m_base)
            for (ElementId t : elements_with_edge(m_mesh, a, b)) {
                const int n = node_of(t);
                if (node(n).alive) result.push_back(n);
            }
        if (const auto it = m_by_edge.find(key(a, b)); it != m_by_edge.end())
            for (int n : it->second)
                if (node(n).alive) result.push_back(n);
        return result;
    }

    // Plans bisect_tetrahedron of node n: the recursion of tet_bisection_recursion.hpp on the
    // overlay. Returns the number of planned splits; `did_not_end` as bisect_recursively.
    Outcome<std::size_t> bisect(int n, bool& did_not_end) {
        return bisect_recursively(
            element_count(), refinement_edge(n),
            [&](VertexId a, VertexId b) { return tetrahedra_with_edge(a, b); },
            [&](int u) { return refinement_edge(u); },
            [&](VertexId a, VertexId b, const std::vector<int>& ring) -> Outcome<Done> {
                if (auto refused = split(a, b, ring)) return *refused;
                return Done{};
            },
            did_not_end);
    }

    // The live tetrahedron containing x (closed test, reference positions) among n and its
    // descendants; the first child when rounding of a midpoint leaves x in neither.
    int leaf_containing(int n, const Point& x) const {
        while (!node(n).alive) {
            const auto& children = node(n).children;
            n = contains(children[1], x) && !contains(children[0], x) ? children[1] : children[0];
        }
        return n;
    }

    double length(const TetEdge& e) const {
        const Point& p = reference(e[0]);
        const Point& q = reference(e[1]);
        return std::sqrt((q[0] - p[0]) * (q[0] - p[0]) + (q[1] - p[1]) * (q[1] - p[1]) +
                         (q[2] - p[2]) * (q[2] - p[2]));
    }

private:
    static std::uint64_t key(VertexId u, VertexId v) {
        const VertexId low = u < v ? u : v, high = u < v ? v : u;
        return (std::uint64_t(low) << 32) | high;
    }

    // simplex_orientation (orientation_checks.hpp) on the overlay's positions
    Sign orientation(const Simplex& s, Positions positions) const {
        const Sign raw = orient3d(position(s.vertex(0), positions), position(s.vertex(1), positions),
                                  position(s.vertex(2), positions), position(s.vertex(3), positions));
        if (raw == Sign::zero) return raw;
        return static_cast<int>(raw) * s.sign() > 0 ? Sign::positive : Sign::negative;
    }

    bool contains(int n, const Point& x) const {
        const Simplex& s = node(n).simplex;
        for (int i = 0; i < 4; ++i) {
            std::array<Point, 4> p{};
            for (int j = 0; j < 4; ++j)
                p[static_cast<std::size_t>(j)] = j == i ? x : reference(s.vertex(j));
            if (static_cast<int>(orient3d(p[0], p[1], p[2], p[3])) * s.sign() < 0) return false;
        }
        return true;
    }

    // split_edge(mesh, a, b, 0.5) on the overlay: the midpoint by interpolated_positions'
    // arithmetic (weights {0.5, 0.5}: the first term assigned, the second added), the children
    // <a->m>, <b->m> of each parent in ring order, checked as split_parents checks them (all
    // children in the reference positions, then all in the deformed ones; the same reason).
    std::optional<Refusal> split(VertexId a, VertexId b, const std::vector<int>& ring) {
        const auto m = static_cast<VertexId>(m_base + m_reference.size());
        Point reference{}, deformed{};
        for (std::size_t k = 0; k < 3; ++k) {
            reference[k] = 0.5 * position(a, Positions::reference)[k];
            reference[k] = reference[k] + 0.5 * position(b, Positions::reference)[k];
            deformed[k] = 0.5 * position(a, Positions::deformed)[k];
            deformed[k] = deformed[k] + 0.5 * position(b, Positions::deformed)[k];
        }
        m_reference.push_back(reference);
        m_deformed.push_back(deformed);
        std::vector<Simplex> children;
        std::vector<int> parent_of_child;
        for (int parent : ring)
            for (VertexId v : {a, b}) {
                children.push_back(node(parent).simplex.substituted(v, m));
                parent_of_child.push_back(parent);
            }
        for (const Positions positions : {Positions::reference, Positions::deformed})
            for (std::size_t i = 0; i < children.size(); ++i) {
                const Sign before = orientation(node(parent_of_child[i]).simplex, positions);
                const Sign after = orientation(children[i], positions);
                if (after == Sign::zero || after != before) {
                    m_reference.pop_back();
                    m_deformed.pop_back();
                    return Refusal{
                        orientation_code(after),
                        "split_edge: new element " + to_text(children[i]) +
                            (after == Sign::zero ? " would be flat" : " would be inverted") +
                            " in the " + to_string(positions) + " positions",
                        i};
                }
            }
        for (std::size_t i = 0; i < children.size(); ++i) {
            const auto parent = static_cast<std::size_t>(parent_of_child[i]);
            const TetMarking parent_marking = m_nodes[parent].marking;
            // children[2j] replaces a (keeps b), children[2j+1] replaces b (keeps a)
            TetMarking marking;
            if (m_rule == BisectionRule::longest_edge) {
                marking = longest_edge_marking_of(
                    children[i].vertices(),
                    [&](VertexId v) -> const Point& { return this->reference(v); });
            } else {
                const auto halves = bisected_markings(parent_marking, m);
                marking = children[i].contains(parent_marking.vertices[0]) ? halves[0] : halves[1];
            }
            const int child = static_cast<int>(m_nodes.size());
            m_nodes[parent].alive = false;
            m_nodes[parent].children[i % 2] = child;
            m_nodes.push_back(Node{children[i], marking});
            const Simplex& s = children[i];
            for (int j = 0; j < 4; ++j)
                for (int k = j + 1; k < 4; ++k)
                    m_by_edge[key(s.vertex(j), s.vertex(k))].push_back(child);
        }
        m_added_elements += ring.size();
        m_splits.push_back({a, b});
        return std::nullopt;
    }

    const Mesh& m_mesh;
    BisectionRule m_rule;
    VertexId m_base;
    std::function<TetMarking(ElementId)> m_initial;
    std::vector<Point> m_reference, m_deformed;  // of the planned vertices m_base, m_base+1, ...
    std::vector<Node> m_nodes;
    std::unordered_map<ElementId, int> m_original;
    std::unordered_map<std::uint64_t, std::vector<int>> m_by_edge;  // planned tets by edge
    std::vector<TetEdge> m_splits;
    std::size_t m_added_elements = 0;
};

// Plans thesis §6.5 refine-around(x, h) from the original element t containing x: while the
// refinement edge of the (virtual) tetrahedron containing x is longer than h, plan its
// bisection; x is then in one of the children of the tetrahedra split, found by following them
// down. Returns the number of planned splits.
inline Outcome<std::size_t> plan_refine_around(TetBisectionPlan& plan, ElementId t, const Point& x,
                                               double h, bool& did_not_end) {
    did_not_end = false;
    std::size_t bisections = 0;
    for (int n = plan.node_of(t);; n = plan.leaf_containing(n, x)) {
        if (!(plan.length(plan.refinement_edge(n)) > h)) return bisections;
        auto planned = plan.bisect(n, did_not_end);
        if (!planned.ok()) return planned.refusal();
        bisections += *planned;
    }
}

// Refuses, before anything is edited, a plan that splits an edge of the mesh whose tetrahedra are
// several fans joined only at the edge (split_edge refuses such an edge: the midpoint's star
// would be pinched; met half way through a replay, the refusal would leave the splits before it
// done). Splits keep each fan of an edge joined, so the edges the plan makes need no check. The
// reason begins with "<operation>: ", or with "the tetrahedra" when `operation` is empty.
inline std::optional<Refusal> refuse_pinched_edges(const Mesh& mesh, const std::vector<TetEdge>& splits,
                                                   const std::string& operation) {
    const std::size_t base = mesh.vertex_count();
    for (const TetEdge& e : splits) {
        if (e[0] >= base || e[1] >= base) continue;
        if (const int fans = edge_fans(mesh, elements_with_edge(mesh, e[0], e[1]), e[0], e[1]); fans > 1)
            return Refusal{RefusalCode::pinched_star,
                           (operation.empty() ? "" : operation + ": ") + "the tetrahedra around " +
                               to_text(Simplex(+1, {e[0], e[1]})) + " are " +
                               std::to_string(fans) +
                               " fans joined only at the edge: bisecting it would pinch the new vertex's star"};
    }
    return std::nullopt;
}

// The replay of a plan through split_edge on the mesh of a TetBisection, with the children's
// marks recorded as the state's rule gives them. Each split was checked by the plan on the same
// simplexes and bit-identical midpoints, so none refuses (an "internal error" if one did).
struct TetBisectionAccess {
    static void make_stale(TetBisection& state, const std::string& why) {
        state.m_stale_reason = why;
    }
    // for the AMP replay (tet_bisection_amp.cpp), which edits through replace_elements
    static std::vector<TetMarking>& markings(TetBisection& state) { return state.m_markings; }
    static void write_marking(TetBisection& state, ElementId t, const TetMarking& marking) {
        state.write_marking(t, marking);
    }
    static void set_own_edit(TetBisection& state, bool own) { state.m_own_edit = own; }
    static void set_last_child(TetBisection& state, ElementId t) { state.m_last_child = t; }

    static Outcome<Done> replay(TetBisection& state, const std::vector<TetEdge>& splits,
                                const std::string& operation) {
        Mesh& mesh = *state.m_mesh;
        if (auto refused = refuse_pinched_edges(mesh, splits, operation)) return *refused;
        std::vector<TetMarking> parents;
        for (const TetEdge& e : splits) {
            parents.clear();
            for (ElementId u : elements_with_edge(mesh, e[0], e[1]))
                parents.push_back(state.marking(u));
            state.m_own_edit = true;
            auto result = split_edge(mesh, e[0], e[1], 0.5);
            state.m_own_edit = false;
            if (!result.ok())
                return Refusal{RefusalCode::internal_error,
                               operation + ": internal error, a planned bisection was refused: " +
                               result.reason()};
            for (const ElementId child : result->elements) {
                // the parent is the one whose c and d the child has; the child keeps a or b
                const Simplex& simplex = mesh.simplex(child);
                for (const TetMarking& parent : parents) {
                    if (!simplex.contains(parent.vertices[2]) ||
                        !simplex.contains(parent.vertices[3]))
                        continue;
                    if (state.m_rule == BisectionRule::longest_edge) {
                        TetMarking marking = longest_edge_marking(mesh, child);
                        marking.generation = parent.generation + 1;
                        state.write_marking(child, marking);
                    } else {
                        const auto halves = bisected_markings(parent, result->vertex);
                        state.write_marking(child, simplex.contains(parent.vertices[0]) ? halves[0] : halves[1]);
                    }
                    break;
                }
            }
            if (!result->elements.empty()) state.m_last_child = result->elements.back();
        }
        return Done{};
    }
};

}  // namespace sxk::detail
