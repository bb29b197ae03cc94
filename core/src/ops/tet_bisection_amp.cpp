// Arnold-Mukherjee-Pouly refinement to conformity for TetBisection's AMP rule: the closure is
// planned on an overlay (tet_bisection_amp.hpp), then replayed as one transaction: the new
// vertices by add_interpolated_vertex, then ONE replace_elements of the original elements that
// were bisected by the leaves below them.
#include "ops/tet_bisection_amp.hpp"

#include <algorithm>
#include <cmath>
#include <span>
#include <utility>

#include "mesh_checks.hpp"
#include "ops/orientation_checks.hpp"
#include "ops/tet_bisection_plan.hpp"
#include "sxk/traversal.hpp"

namespace sxk::detail {

AmpClosurePlan::AmpClosurePlan(const Mesh& mesh, const std::vector<TetMarking>& markings)
    : m_mesh(mesh), m_markings(markings), m_base(static_cast<VertexId>(mesh.vertex_count())) {}

int AmpClosurePlan::node_of(ElementId t) {
    const auto [it, inserted] = m_original.try_emplace(t, static_cast<int>(m_nodes.size()));
    if (inserted) m_nodes.push_back(Node{m_mesh.simplex(t), m_markings[t], t});
    return it->second;
}

const Point& AmpClosurePlan::position(VertexId v, Positions positions) const {
    if (v < m_base)
        return positions == Positions::reference ? m_mesh.reference(v) : m_mesh.deformed(v);
    const NewVertex& planned = m_new_vertices[v - m_base];
    return positions == Positions::reference ? planned.reference : planned.deformed;
}

// simplex_orientation (orientation_checks.hpp) on the overlay's positions
Sign AmpClosurePlan::orientation(const Simplex& s, Positions positions) const {
    const Sign raw = orient3d(position(s.vertex(0), positions), position(s.vertex(1), positions),
                              position(s.vertex(2), positions), position(s.vertex(3), positions));
    if (raw == Sign::zero) return raw;
    return static_cast<int>(raw) * s.sign() > 0 ? Sign::positive : Sign::negative;
}

bool AmpClosurePlan::contains(int n, const Point& x) const {
    const Simplex& s = node(n).simplex;
    for (int i = 0; i < 4; ++i) {
        std::array<Point, 4> p{};
        for (int j = 0; j < 4; ++j)
            p[static_cast<std::size_t>(j)] =
                j == i ? x : position(s.vertex(j), Positions::reference);
        if (static_cast<int>(orient3d(p[0], p[1], p[2], p[3])) * s.sign() < 0) return false;
    }
    return true;
}

int AmpClosurePlan::leaf_containing(int n, const Point& x) const {
    while (!node(n).alive) {
        const auto& children = node(n).children;
        n = contains(children[1], x) && !contains(children[0], x) ? children[1] : children[0];
    }
    return n;
}

double AmpClosurePlan::refinement_length(int n) const {
    const Point& p = position(node(n).marking.vertices[0], Positions::reference);
    const Point& q = position(node(n).marking.vertices[1], Positions::reference);
    return std::sqrt((q[0] - p[0]) * (q[0] - p[0]) + (q[1] - p[1]) * (q[1] - p[1]) +
                     (q[2] - p[2]) * (q[2] - p[2]));
}

bool AmpClosurePlan::has_hanging_node(int n) const {
    const Simplex& s = node(n).simplex;
    for (int j = 0; j < 4; ++j)
        for (int k = j + 1; k < 4; ++k)
            if (m_midpoint.contains(key(s.vertex(j), s.vertex(k)))) return true;
    return false;
}

void AmpClosurePlan::append_leaves_with(int n, VertexId v, std::vector<int>& out) const {
    if (!node(n).simplex.contains(v)) return;
    if (node(n).alive) {
        out.push_back(n);
        return;
    }
    for (int child : node(n).children) append_leaves_with(child, v, out);
}

std::vector<int>& AmpClosurePlan::leaves_with(VertexId v) {
    auto it = m_leaves_with.find(v);
    if (it != m_leaves_with.end()) return it->second;
    // first use of a mesh vertex (planned vertices get their list when they are made): its star
    // in the mesh, each element replaced by its leaves containing v if the plan bisected it
    std::vector<int> leaves;
    for (ElementId t : star(m_mesh, v)) append_leaves_with(node_of(t), v, leaves);
    return m_leaves_with.emplace(v, std::move(leaves)).first->second;
}

std::optional<Refusal> AmpClosurePlan::bisect(int n, std::vector<int>& work) {
    const TetMarking parent_marking = node(n).marking;
    const Simplex parent = node(n).simplex;
    const VertexId a = parent_marking.vertices[0], b = parent_marking.vertices[1];
    VertexId m = invalid_id;
    bool created = false;
    if (const auto found = m_midpoint.find(key(a, b)); found != m_midpoint.end()) {
        m = found->second;
    } else {
        // Mesh::interpolated_positions({a, b}, {0.5, 0.5}): the first term assigned, the second
        // added, so the replay's vertex is bit for bit this one
        NewVertex planned{a, b, {}, {}};
        for (std::size_t k = 0; k < 3; ++k) {
            planned.reference[k] = 0.5 * position(a, Positions::reference)[k];
            planned.reference[k] = planned.reference[k] + 0.5 * position(b, Positions::reference)[k];
            planned.deformed[k] = 0.5 * position(a, Positions::deformed)[k];
            planned.deformed[k] = planned.deformed[k] + 0.5 * position(b, Positions::deformed)[k];
        }
        m = static_cast<VertexId>(m_base + m_new_vertices.size());
        m_new_vertices.push_back(planned);
        created = true;
    }
    // T1 = {a,c,d,m} keeps a (b replaced), T2 = {b,c,d,m} keeps b: bisected_markings' order
    const std::array<Simplex, 2> children{parent.substituted(b, m), parent.substituted(a, m)};
    for (const Positions positions : {Positions::reference, Positions::deformed}) {
        const Sign before = orientation(parent, positions);
        for (std::size_t i = 0; i < 2; ++i) {
            const Sign after = orientation(children[i], positions);
            if (after == Sign::zero || after != before) {
                if (created) m_new_vertices.pop_back();
                return Refusal{orientation_code(after),
                               "new element " + to_text(children[i]) +
                                   (after == Sign::zero ? " would be flat" : " would be inverted") +
                                   " in the " + to_string(positions) + " positions",
                               i};
            }
        }
    }
    if (created) {
        // every other leaf around ab has a hanging node now
        for (int u : leaves_with(a))
            if (u != n && node(u).simplex.contains(b)) work.push_back(u);
        m_midpoint.emplace(key(a, b), m);
        m_leaves_with.emplace(m, std::vector<int>{});
    }
    // n leaves the vertex lists that exist (lists made later descend to its children)
    for (VertexId v : parent.vertices())
        if (auto it = m_leaves_with.find(v); it != m_leaves_with.end()) std::erase(it->second, n);
    const auto markings = bisected_markings(parent_marking, m);
    for (std::size_t i = 0; i < 2; ++i) {
        const int child = static_cast<int>(m_nodes.size());
        m_nodes[static_cast<std::size_t>(n)].alive = false;
        m_nodes[static_cast<std::size_t>(n)].children[i] = child;
        m_nodes.push_back(Node{children[i], markings[i], node(n).root});
        for (VertexId v : children[i].vertices())
            if (auto it = m_leaves_with.find(v); it != m_leaves_with.end())
                it->second.push_back(child);
        work.push_back(child);
    }
    return std::nullopt;
}

std::optional<Refusal> AmpClosurePlan::bisect_and_close(int n, bool& did_not_end) {
    did_not_end = false;
    // AMP bound the extra refinement of a closure; this guard only turns a closure that does
    // not end (a marking that is not AMP's) into a refusal
    const std::size_t limit = 64 + 8 * (m_mesh.element_count() + m_nodes.size());
    std::vector<int> work;
    if (auto refused = bisect(n, work)) return refused;
    std::size_t bisections = 0;
    while (!work.empty()) {
        const int u = work.back();
        work.pop_back();
        if (!node(u).alive || !has_hanging_node(u)) continue;
        if (++bisections > limit) {
            did_not_end = true;
            return Refusal{RefusalCode::bad_marking,
                           "the marking is not conforming: the closure to conformity did not end"};
        }
        if (auto refused = bisect(u, work)) return refused;
    }
    return std::nullopt;
}

std::vector<ElementId> AmpClosurePlan::refined_originals() const {
    std::vector<ElementId> result;
    for (const auto& [t, n] : m_original)
        if (!node(n).alive) result.push_back(t);
    std::sort(result.begin(), result.end());
    return result;
}

void AmpClosurePlan::append_leaves(ElementId t, std::vector<int>& leaves) const {
    std::vector<int> stack{m_original.at(t)};
    while (!stack.empty()) {
        const int n = stack.back();
        stack.pop_back();
        if (node(n).alive) {
            leaves.push_back(n);
            continue;
        }
        stack.push_back(node(n).children[1]);
        stack.push_back(node(n).children[0]);
    }
}

bool AmpClosurePlan::lies_on(VertexId v, const Simplex& face) const {
    if (v < m_base) return face.contains(v);
    const NewVertex& planned = m_new_vertices[v - m_base];
    return lies_on(planned.a, face) && lies_on(planned.b, face);
}

namespace {

// The replay: the planned vertices, ONE replace_elements, face labels, the leaves' marks. The
// plan checked every child, so the only refusals left are internal errors, undone completely.
Outcome<Done> amp_replay(TetBisection& state, const AmpClosurePlan& plan) {
    Mesh& mesh = state.mesh();
    const std::vector<ElementId> originals = plan.refined_originals();
    std::vector<int> leaves;
    std::vector<std::uint32_t> origins;  // a leaf is its original's: label and element attributes
    for (std::uint32_t r = 0; r < originals.size(); ++r) {
        plan.append_leaves(originals[r], leaves);
        origins.resize(leaves.size(), r);
    }
    std::vector<Simplex> simplexes;
    simplexes.reserve(leaves.size());
    for (int n : leaves) simplexes.push_back(plan.node(n).simplex);
    // Face labels: a labelled face of a bisected original that is no face of a leaf passes its
    // label to the leaf faces lying on it (all their vertices on it, by the midpoints' lineage).
    std::vector<Simplex> split_faces;
    std::vector<std::pair<Simplex, int>> moved_labels;
    if (!mesh.face_labels().empty()) {
        std::vector<Simplex> all_leaf_faces;
        for (const Simplex& s : simplexes)
            for (int i = 0; i < 4; ++i) all_leaf_faces.emplace_back(+1, s.subn(i).vertices());
        std::sort(all_leaf_faces.begin(), all_leaf_faces.end());
        for (ElementId t : originals)
            for (int i = 0; i < 4; ++i) {
                const Simplex face(+1, mesh.simplex(t).subn(i).vertices());
                const auto label = mesh.face_labels().find(face);
                if (label == mesh.face_labels().end()) continue;
                if (std::binary_search(all_leaf_faces.begin(), all_leaf_faces.end(), face)) continue;
                if (std::find(split_faces.begin(), split_faces.end(), face) == split_faces.end())
                    split_faces.push_back(face);
            }
        for (std::size_t i = 0; i < leaves.size(); ++i) {
            const Simplex& root = mesh.simplex(plan.node(leaves[i]).root);
            for (const Simplex& face : split_faces) {
                if (!std::all_of(face.vertices().begin(), face.vertices().end(),
                                 [&](VertexId v) { return root.contains(v); }))
                    continue;
                for (int j = 0; j < 4; ++j) {
                    const Simplex piece(+1, simplexes[i].subn(j).vertices());
                    if (std::all_of(piece.vertices().begin(), piece.vertices().end(),
                                    [&](VertexId v) { return plan.lies_on(v, face); }))
                        moved_labels.emplace_back(piece, mesh.face_labels().at(face));
                }
            }
        }
    }

    // An edge of the mesh whose tetrahedra are several fans joined only at the edge cannot be bisected:
    // the midpoint's star would be pinched (as split_edge refuses it). Checked before anything is
    // added; the edges the plan makes lie inside the originals' faces and tetrahedra, one fan each.
    std::vector<TetEdge> split_edges;
    for (const auto& planned : plan.new_vertices()) split_edges.push_back({planned.a, planned.b});
    if (auto refused = refuse_pinched_edges(mesh, split_edges, "")) return *refused;

    auto undo_vertices = [&] {
        while (mesh.vertex_count() > plan.base()) (void)mesh.remove_last_vertex();
    };
    for (const auto& planned : plan.new_vertices()) {
        const std::array<VertexId, 2> parents{planned.a, planned.b};
        const std::array<double, 2> weights{0.5, 0.5};
        auto added = mesh.add_interpolated_vertex(parents, weights);
        if (!added.ok() || mesh.reference(*added) != planned.reference ||
            mesh.deformed(*added) != planned.deformed) {
            undo_vertices();
            return Refusal{RefusalCode::internal_error,
                           "internal error, a planned vertex differs from the one added" +
                           (added.ok() ? std::string() : ": " + added.reason())};
        }
    }
    // The star checks of replace_elements are proven (mesh_checks.hpp, ProvenEdit). (a) A leaf, and a
    // face of a leaf that is no face of an original, has a new vertex: three old vertices of a leaf
    // are corners of its original, and span one of its faces. (b) Within an original the leaves
    // around a vertex v are face-connected through faces holding v (the two children of a bisection
    // share the face through the midpoint and the two corners off the bisected edge), the plan is
    // conforming (AMP's closure), so a face between two originals, or between an original and an
    // element that stays, is split the same way on both sides, and each piece holding v joins
    // them; a new vertex lies inside an original tetrahedron, inside a face, or on an edge of one
    // fan (checked above), where a conforming subdivision leaves it a face-connected star.
    TetBisectionAccess::set_own_edit(state, true);
    auto replaced = ProvenEdit::replace(mesh, originals, simplexes, {}, origins);
    TetBisectionAccess::set_own_edit(state, false);
    if (!replaced.ok()) {
        undo_vertices();
        return Refusal{RefusalCode::internal_error,
                       "internal error, the planned refinement was refused: " + replaced.reason()};
    }
    for (const Simplex& face : split_faces) mesh.erase_face_label(face);
    for (const auto& [face, label] : moved_labels) mesh.set_face_label(face, label);
    for (std::size_t i = 0; i < leaves.size(); ++i)
        TetBisectionAccess::write_marking(state, (*replaced)[i], plan.node(leaves[i]).marking);
    if (!replaced->empty()) TetBisectionAccess::set_last_child(state, replaced->back());
    return Done{};
}

}  // namespace

Outcome<std::size_t> amp_bisect(TetBisection& state, ElementId t) {
    AmpClosurePlan plan(state.mesh(), TetBisectionAccess::markings(state));
    bool did_not_end = false;
    if (auto refused = plan.bisect_and_close(plan.node_of(t), did_not_end)) {
        if (did_not_end) TetBisectionAccess::make_stale(state, refused->reason);
        return *refused;
    }
    if (auto replayed = amp_replay(state, plan); !replayed.ok()) return replayed.refusal();
    return plan.new_vertices().size();
}

Outcome<std::size_t> amp_refine_around(TetBisection& state, ElementId t, const Point& x, double h) {
    AmpClosurePlan plan(state.mesh(), TetBisectionAccess::markings(state));
    bool did_not_end = false;
    for (int n = plan.node_of(t);; n = plan.leaf_containing(n, x)) {
        if (!(plan.refinement_length(n) > h)) break;
        if (auto refused = plan.bisect_and_close(n, did_not_end)) {
            if (did_not_end) TetBisectionAccess::make_stale(state, refused->reason);
            return *refused;
        }
    }
    if (plan.new_vertices().empty()) return std::size_t{0};
    if (auto replayed = amp_replay(state, plan); !replayed.ok()) return replayed.refusal();
    return plan.new_vertices().size();
}

}  // namespace sxk::detail
