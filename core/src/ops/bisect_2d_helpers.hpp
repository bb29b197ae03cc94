// Private helpers of simple_bisect.cpp, bisect_edge.cpp and refine_around.cpp (thesis §6.5):
// the hypotenuse rule, and a bisection PLAN that runs the recursive bisect(e) on a scratch
// overlay of the mesh before anything is edited, so that a multi-split operation either
// replays completely or refuses with the mesh untouched.
//
// The overlay holds the triangles the plan has created (with their vertices, at ids
// vertex_count(), vertex_count()+1, ... exactly as the replay through split_edge will number
// them) and remembers which original elements it has split. A query "triangles containing edge
// ab" looks in the mesh (original elements not yet split) and in the overlay, so the plan sees
// the mesh as it will be after the planned splits. Cost: O(number of planned splits) memory,
// hash look-ups per step: the plan is as local as the bisections themselves.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "ops/edge_star.hpp"
#include "ops/orientation_checks.hpp"
#include "sxk/mesh.hpp"
#include "sxk/ops/split_edge.hpp"
#include "sxk/outcome.hpp"
#include "sxk/predicates.hpp"

namespace sxk::detail {

// An undirected edge, a < b.
struct Edge {
    VertexId a = invalid_id;
    VertexId b = invalid_id;
    friend bool operator==(const Edge&, const Edge&) = default;
};

inline Edge make_edge(VertexId u, VertexId w) {
    return u < w ? Edge{u, w} : Edge{w, u};
}

inline std::string edge_text(const Edge& e) {
    return to_text(Simplex(+1, {e.a, e.b}));
}

inline double squared_length(const Point& p, const Point& q) {
    const double dx = p[0] - q[0], dy = p[1] - q[1], dz = p[2] - q[2];
    return dx * dx + dy * dy + dz * dz;
}

// The hypotenuse of a triangle (thesis §6.5): its longest edge in the REFERENCE positions, ties
// broken towards the edge with the smaller (a, b) id pair. The squared length of an edge is a
// function of its two end points only (computed from the sorted pair), and the tie-break
// depends on the ids only, so the rule is a strict total order on edges: "e is the hypotenuse
// of t" is decided the same way by both triangles sharing e, and in bisect(e) every hypotenuse
// looked at next is strictly greater than e in that order (termination of the recursion).
// On right-angled meshes the longest edge is the hypotenuse and the vertex opposite it the
// newest one (newest-vertex bisection); on general meshes this is Rivara's longest-edge
// bisection, as the thesis remarks.
template <class ReferenceOf>  // const Point& reference_of(VertexId)
Edge hypotenuse_of(const Simplex& triangle, ReferenceOf&& reference_of) {
    const std::array<Edge, 3> edges{make_edge(triangle.vertex(0), triangle.vertex(1)),
                                    make_edge(triangle.vertex(0), triangle.vertex(2)),
                                    make_edge(triangle.vertex(1), triangle.vertex(2))};
    Edge best = edges[0];
    double best_length = squared_length(reference_of(best.a), reference_of(best.b));
    for (std::size_t i = 1; i < edges.size(); ++i) {
        const double length = squared_length(reference_of(edges[i].a), reference_of(edges[i].b));
        const bool smaller_ids =
            edges[i].a < best.a || (edges[i].a == best.a && edges[i].b < best.b);
        if (length > best_length || (length == best_length && smaller_ids)) {
            best = edges[i];
            best_length = length;
        }
    }
    return best;
}

inline Edge hypotenuse_in_mesh(const Mesh& mesh, ElementId t) {
    return hypotenuse_of(mesh.simplex(t),
                         [&](VertexId v) -> const Point& { return mesh.reference(v); });
}

class BisectionPlan {
public:
    struct Node {
        Simplex simplex;
        ElementId original = invalid_id;  // the mesh element this node stands for, if any
        bool alive = true;
        std::array<int, 2> children{-1, -1};
    };

    explicit BisectionPlan(const Mesh& mesh)
        : m_mesh(mesh), m_base(static_cast<VertexId>(mesh.vertex_count())) {}

    const Point& reference(VertexId v) const {
        return v < m_base ? m_mesh.reference(v) : m_reference[v - m_base];
    }
    const Point& deformed(VertexId v) const {
        return v < m_base ? m_mesh.deformed(v) : m_deformed[v - m_base];
    }
    const Point& position(VertexId v, Positions positions) const {
        return positions == Positions::reference ? reference(v) : deformed(v);
    }
    const Node& node(int n) const { return m_nodes[static_cast<std::size_t>(n)]; }
    // The edges to split, in order (each as split_edge(mesh, a, b, 0.5) will get it).
    const std::vector<Edge>& splits() const { return m_splits; }

    // The overlay node of an original element (created on first use).
    int node_of(ElementId t) {
        const auto [it, inserted] = m_original.try_emplace(t, static_cast<int>(m_nodes.size()));
        if (inserted)
            m_nodes.push_back(Node{m_mesh.simplex(t), t});
        return it->second;
    }

    Edge hypotenuse(int n) const {
        return hypotenuse_of(node(n).simplex,
                             [&](VertexId v) -> const Point& { return reference(v); });
    }
    double length(const Edge& e) const {
        return std::sqrt(squared_length(reference(e.a), reference(e.b)));
    }

    // The live triangles (after the planned splits) containing edge e.
    std::vector<int> triangles_with_edge(const Edge& e) {
        std::vector<int> result;
        if (e.b < m_base)
            for (ElementId t : elements_with_edge(m_mesh, e.a, e.b)) {
                const int n = node_of(t);
                if (node(n).alive)
                    result.push_back(n);
            }
        if (const auto it = m_by_edge.find(key(e)); it != m_by_edge.end())
            for (int n : it->second)
                if (node(n).alive)
                    result.push_back(n);
        return result;
    }

    // Thesis §6.5 bisect(e), with an explicit stack instead of recursion: while a triangle at
    // the top edge has another hypotenuse, that hypotenuse is bisected first; then the top edge
    // is the hypotenuse of all its triangles and gets a simple bisection. Refuses only when a
    // child would be flat or of the other orientation than its parent (see split_edge); the
    // plan is then discarded and the mesh was never touched.
    std::optional<Refusal> bisect(const Edge& e, const std::string& operation) {
        std::vector<Edge> stack{e};
        while (!stack.empty()) {
            const Edge top = stack.back();
            const std::vector<int> around = triangles_with_edge(top);
            bool deeper = false;
            for (int n : around) {
                const Edge h = hypotenuse(n);
                if (h == top)
                    continue;
                // h is strictly greater than top in the hypotenuse order (hypotenuse_of), and
                // only the top of the stack is ever split: the stack is a strictly increasing
                // chain of existing edges, so it cannot cycle
                stack.push_back(h);
                deeper = true;
                break;
            }
            if (deeper)
                continue;
            if (auto refused = simple_bisect(top, around, operation))
                return refused;
            stack.pop_back();
        }
        return std::nullopt;
    }

    // The live triangle containing x (closed test, reference positions) among n and its
    // descendants; the first child when rounding of a midpoint leaves x in neither.
    int leaf_containing(int n, const Point& x) const {
        while (!node(n).alive) {
            const auto& children = node(n).children;
            n = contains(children[1], x) && !contains(children[0], x) ? children[1] : children[0];
        }
        return n;
    }

    bool contains(int n, const Point& x) const {
        const Simplex& s = node(n).simplex;
        std::array<Point, 3> p{reference(s.vertex(0)), reference(s.vertex(1)),
                               reference(s.vertex(2))};
        const Sign o = orient2d(p[0], p[1], p[2]);
        if (o == Sign::zero)
            return false;
        for (std::size_t i = 0; i < 3; ++i) {
            std::array<Point, 3> q = p;
            q[i] = x;
            if (static_cast<int>(orient2d(q[0], q[1], q[2])) * static_cast<int>(o) < 0)
                return false;
        }
        return true;
    }

    // Replays the plan: one split_edge per planned split. Every check split_edge makes was made
    // by the plan on the same simplexes and the same (bit-identical) midpoints, so no replayed
    // split refuses; the new vertex ids are those the plan used.
    Outcome<std::vector<SplitResult>> apply(Mesh& mesh, const std::string& operation) const {
        std::vector<SplitResult> results;
        for (const Edge& e : m_splits) {
            auto split = split_edge(mesh, e.a, e.b, 0.5);
            if (!split)
                return Refusal{RefusalCode::internal_error,
                               operation + ": internal error, a planned bisection was refused: " +
                               split.reason()};
            results.push_back(std::move(*split));
        }
        return results;
    }

private:
    static std::uint64_t key(const Edge& e) { return (std::uint64_t(e.a) << 32) | e.b; }

    Sign orientation(const Simplex& s, Positions positions) const {
        const Point& p0 = position(s.vertex(0), positions);
        const Point& p1 = position(s.vertex(1), positions);
        const Point& p2 = position(s.vertex(2), positions);
        if (m_mesh.ambient_dimension() == 3)
            return collinear(p0, p1, p2) ? Sign::zero : Sign::positive;
        const Sign raw = orient2d(p0, p1, p2);
        if (raw == Sign::zero)
            return raw;
        return static_cast<int>(raw) * s.sign() > 0 ? Sign::positive : Sign::negative;
    }

    // Thesis simple-bisect on the overlay: the midpoint m of e, and each triangle around e
    // replaced by its two halves <a->m> and <b->m>, with the checks and the arithmetic of
    // split_edge (m = 0.5 a + 0.5 b summed in that order, as Mesh::interpolated_positions does,
    // so the replay checks the same numbers).
    std::optional<Refusal> simple_bisect(const Edge& e, const std::vector<int>& parents,
                                         const std::string& operation) {
        const auto m = static_cast<VertexId>(m_base + m_reference.size());
        // Mesh::interpolated_positions' order: weights[0] * p[0] first, then + weights[1] * p[1]
        Point reference{}, deformed{};
        for (std::size_t k = 0; k < 3; ++k) {
            reference[k] = 0.5 * this->reference(e.a)[k];
            reference[k] += 0.5 * this->reference(e.b)[k];
            deformed[k] = 0.5 * this->deformed(e.a)[k];
            deformed[k] += 0.5 * this->deformed(e.b)[k];
        }
        m_reference.push_back(reference);
        m_deformed.push_back(deformed);
        std::vector<std::array<Simplex, 2>> children;
        for (int parent : parents) {
            const Simplex& s = node(parent).simplex;
            children.push_back({s.substituted(e.a, m), s.substituted(e.b, m)});
            for (Positions positions : {Positions::reference, Positions::deformed}) {
                const Sign before = orientation(s, positions);
                for (const Simplex& child : children.back()) {
                    const Sign after = orientation(child, positions);
                    if (after == Sign::zero || after != before) {
                        m_reference.pop_back();
                        m_deformed.pop_back();
                        return Refusal{orientation_code(after),
                                       operation + ": new element " + to_text(child) +
                                           (after == Sign::zero ? " would be flat"
                                                                : " would be inverted") +
                                           " in the " + to_string(positions) + " positions"};
                    }
                }
            }
        }
        for (std::size_t i = 0; i < parents.size(); ++i) {
            m_nodes[static_cast<std::size_t>(parents[i])].alive = false;
            for (std::size_t c = 0; c < 2; ++c) {
                const int child = static_cast<int>(m_nodes.size());
                m_nodes[static_cast<std::size_t>(parents[i])].children[c] = child;
                m_nodes.push_back(Node{children[i][c]});
                const Simplex& s = children[i][c];
                for (auto [j, k] : {std::pair{0, 1}, std::pair{0, 2}, std::pair{1, 2}})
                    m_by_edge[key(make_edge(s.vertex(j), s.vertex(k)))].push_back(child);
            }
        }
        m_splits.push_back(e);
        return std::nullopt;
    }

    const Mesh& m_mesh;
    VertexId m_base;
    std::vector<Point> m_reference, m_deformed;  // of the planned vertices m_base, m_base+1, ...
    std::vector<Node> m_nodes;
    std::unordered_map<ElementId, int> m_original;
    std::unordered_map<std::uint64_t, std::vector<int>> m_by_edge;  // planned triangles by edge
    std::vector<Edge> m_splits;
};

}  // namespace sxk::detail
