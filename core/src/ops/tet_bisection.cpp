// TetBisection: Maubach's (1995) newest-vertex bisection in the marked-tetrahedron form of
// Arnold, Mukherjee & Pouly (2000) for Kuhn meshes, and longest-edge bisection (Rivara) for any
// tetrahedral mesh, kept beside the mesh (see the header).
#include "sxk/ops/tet_bisection.hpp"

#include "ops/tet_bisection_plan.hpp"
#include "sxk/detail/large_array.hpp"

#include <algorithm>
#include <cmath>
#include <tuple>
#include <utility>

namespace sxk {

namespace {

using Edge = std::array<VertexId, 2>;

Edge sorted_edge(VertexId u, VertexId v) { return u < v ? Edge{u, v} : Edge{v, u}; }

// A marking from the four vertices, the refinement edge and the mark of every face (face i is
// the face opposite faces_opposite[i], marked marks[i]).
TetMarking marking_from_faces(const std::array<VertexId, 4>& vertices, const Edge& refinement,
                              const std::array<VertexId, 4>& faces_opposite,
                              const std::array<Edge, 4>& marks, bool flagged,
                              std::uint32_t generation) {
    TetMarking result;
    result.vertices[0] = refinement[0];
    result.vertices[1] = refinement[1];
    std::size_t next = 2;
    for (VertexId v : vertices)
        if (v != refinement[0] && v != refinement[1]) result.vertices[next++] = v;
    auto unmarked_of = [&](VertexId opposite) {
        for (std::size_t i = 0; i < 4; ++i)
            if (faces_opposite[i] == opposite)
                for (VertexId v : vertices)
                    if (v != opposite && v != marks[i][0] && v != marks[i][1]) return v;
        return invalid_id;
    };
    result.acd_unmarked = unmarked_of(result.vertices[1]);  // face acd is opposite b
    result.bcd_unmarked = unmarked_of(result.vertices[0]);  // face bcd is opposite a
    result.flagged = flagged;
    result.generation = generation;
    return result;
}

}  // namespace

TetType tet_type(const TetMarking& marking) {
    const VertexId a = marking.vertices[0], b = marking.vertices[1];
    const bool acd_opposite = marking.acd_unmarked == a;  // cd marked
    const bool bcd_opposite = marking.bcd_unmarked == b;
    if (acd_opposite && bcd_opposite) return TetType::opposite;
    if (acd_opposite || bcd_opposite) return TetType::mixed;
    // both marks touch ab: (ac, bc) or (ad, bd) lie in one plane with ab
    if (marking.acd_unmarked == marking.bcd_unmarked)
        return marking.flagged ? TetType::planar_flagged : TetType::planar_unflagged;
    return TetType::adjacent;
}

std::array<VertexId, 2> face_mark(const TetMarking& marking, VertexId opposite) {
    const auto& v = marking.vertices;
    if (opposite == v[2] || opposite == v[3]) return sorted_edge(v[0], v[1]);
    // face acd (opposite b) or bcd (opposite a)
    const VertexId unmarked = opposite == v[1] ? marking.acd_unmarked : marking.bcd_unmarked;
    Edge mark{invalid_id, invalid_id};
    std::size_t next = 0;
    for (VertexId w : v)
        if (w != opposite && w != unmarked && next < 2) mark[next++] = w;
    return sorted_edge(mark[0], mark[1]);
}

std::array<TetMarking, 2> bisected_markings(const TetMarking& parent, VertexId m) {
    const VertexId a = parent.vertices[0], b = parent.vertices[1];
    const VertexId c = parent.vertices[2], d = parent.vertices[3];
    const TetType type = tet_type(parent);
    const Edge acd_mark = face_mark(parent, b);
    const Edge bcd_mark = face_mark(parent, a);
    // AMP: the new face cdm is marked cd, except below a Pf parent, where it is marked m-s with
    // s the vertex both marks of acd and bcd share (this turns the children into type A; on
    // Kuhn meshes it is Maubach's tag 1 -> tag 3 step).
    Edge new_mark = sorted_edge(c, d);
    if (type == TetType::planar_flagged) {
        const VertexId shared = parent.acd_unmarked == c ? d : c;
        new_mark = sorted_edge(m, shared);
    }
    const bool flagged = type == TetType::planar_unflagged;
    const std::uint32_t generation = parent.generation + 1;
    // T1 = {a,c,d,m}: faces opposite m (acd), d (acm), c (adm), a (cdm)
    const TetMarking first = marking_from_faces(
        {a, c, d, m}, acd_mark, {m, d, c, a},
        {acd_mark, sorted_edge(a, c), sorted_edge(a, d), new_mark}, flagged, generation);
    const TetMarking second = marking_from_faces(
        {b, c, d, m}, bcd_mark, {m, d, c, b},
        {bcd_mark, sorted_edge(b, c), sorted_edge(b, d), new_mark}, flagged, generation);
    return {first, second};
}

// ---- construction -------------------------------------------------------------------------------

TetBisection::TetBisection(Mesh& mesh, std::vector<TetMarking> markings, BisectionRule rule)
    : m_mesh(&mesh), m_markings(std::move(markings)), m_rule(rule) {
    // room to double before write_marking grows them: a growth copies them, with the fresh pages
    // it touches, inside the step that bisects (detail::grow_doubling)
    m_markings.reserve(2 * std::max(m_markings.size(), mesh.element_capacity()));
    attach();
}

void TetBisection::attach() {
    // add_watcher calls init at once; that first init is ours, not a foreign edit
    m_own_edit = true;
    m_mesh->add_watcher(*this);
    m_own_edit = false;
}

// A state attached to a journal is not moved (the journal holds its address); the states are
// moved out of the factories' Outcome before a tool attaches them.
TetBisection::TetBisection(TetBisection&& other) noexcept
    : Watcher(),
      SideLog(),
      m_mesh(other.m_mesh),
      m_markings(std::move(other.m_markings)),
      m_rule(other.m_rule),
      m_stale_reason(std::move(other.m_stale_reason)),
      m_last_child(other.m_last_child),
      m_undo(std::move(other.m_undo)),
      m_opened(std::move(other.m_opened)) {
    if (m_mesh) {
        m_mesh->remove_watcher(other);
        other.m_mesh = nullptr;
        attach();
    }
}

TetBisection& TetBisection::operator=(TetBisection&& other) noexcept {
    if (this == &other) return *this;
    if (m_mesh) m_mesh->remove_watcher(*this);
    m_mesh = other.m_mesh;
    m_markings = std::move(other.m_markings);
    m_rule = other.m_rule;
    m_stale_reason = std::move(other.m_stale_reason);
    m_last_child = other.m_last_child;
    m_undo = std::move(other.m_undo);
    m_opened = std::move(other.m_opened);
    if (m_mesh) {
        m_mesh->remove_watcher(other);
        other.m_mesh = nullptr;
        attach();
    }
    return *this;
}

TetBisection::~TetBisection() {
    if (m_mesh) m_mesh->remove_watcher(*this);
}

TetMarking longest_edge_marking(const Mesh& mesh, ElementId t) {
    // refinement edge = the longest edge of the tetrahedron, face marks = the longest edge of
    // each face, under one strict order (so neighbours agree on every face); shared with the
    // bisection plan, which marks tetrahedra before they exist (tet_bisection_plan.hpp)
    return detail::longest_edge_marking_of(
        mesh.simplex(t).vertices(), [&](VertexId v) -> const Point& { return mesh.reference(v); });
}

Outcome<TetBisection> TetBisection::with_initial_marking(Mesh& mesh) {
    if (mesh.topological_dimension() != 3)
        return Refusal{RefusalCode::wrong_dimension,
                       "tet_bisection: the mesh has triangles, not tetrahedra"};
    std::vector<TetMarking> markings(mesh.element_capacity());
    for (ElementId t : elements(mesh)) markings[t] = longest_edge_marking(mesh, t);
    return TetBisection(mesh, std::move(markings), BisectionRule::longest_edge);
}

Outcome<TetBisection> TetBisection::with_amp_marking(Mesh& mesh) {
    if (mesh.topological_dimension() != 3)
        return Refusal{RefusalCode::wrong_dimension,
                       "tet_bisection: the mesh has triangles, not tetrahedra"};
    // AMP's initial marking: the longest edge (one strict order) for the refinement edge and
    // every face mark, so neighbours agree on each shared face; flags unset
    std::vector<TetMarking> markings(mesh.element_capacity());
    for (ElementId t : elements(mesh)) markings[t] = longest_edge_marking(mesh, t);
    return TetBisection(mesh, std::move(markings), BisectionRule::arnold_mukherjee_pouly);
}

Outcome<TetBisection> TetBisection::for_kuhn_mesh(Mesh& mesh) {
    if (mesh.topological_dimension() != 3)
        return Refusal{RefusalCode::wrong_dimension,
                       "tet_bisection: the mesh has triangles, not tetrahedra"};
    std::vector<TetMarking> markings(mesh.element_capacity());
    for (ElementId t : elements(mesh)) {
        // Maubach's tuple: the vertices by increasing coordinate sum; consecutive ones must
        // differ by one positive step along a different axis each, all of the same length
        std::array<VertexId, 4> x{};
        const auto v = mesh.simplex(t).vertices();
        std::copy(v.begin(), v.end(), x.begin());
        auto coordinate_sum = [&](VertexId u) {
            const Point& p = mesh.reference(u);
            return p[0] + p[1] + p[2];
        };
        std::sort(x.begin(), x.end(),
                  [&](VertexId p, VertexId q) { return coordinate_sum(p) < coordinate_sum(q); });
        bool kuhn = true;
        std::array<bool, 3> axis_used{false, false, false};
        double step_length = 0;
        for (std::size_t s = 0; s < 3 && kuhn; ++s) {
            const Point& p = mesh.reference(x[s]);
            const Point& q = mesh.reference(x[s + 1]);
            // the step's main axis, then: positive, unused, the others ~0, same length as step 0
            std::size_t axis = 0;
            for (std::size_t k = 1; k < 3; ++k)
                if (std::abs(q[k] - p[k]) > std::abs(q[axis] - p[axis])) axis = k;
            const double delta = q[axis] - p[axis];
            if (s == 0) step_length = delta;
            const double tolerance = 1e-9 * std::abs(step_length);
            if (!(delta > 0) || axis_used[axis] || std::abs(delta - step_length) > tolerance)
                kuhn = false;
            for (std::size_t k = 0; k < 3; ++k)
                if (k != axis && std::abs(q[k] - p[k]) > tolerance) kuhn = false;
            axis_used[axis] = true;
        }
        if (!kuhn)
            return Refusal{RefusalCode::not_applicable,
                           "tet_bisection: element " + std::to_string(t) +
                               " is not a Kuhn tetrahedron",
                           t};
        // tag 3: refinement edge x0-x3; face x0x1x2 marked x0x2 (unmarked x1), face x1x2x3
        // marked x1x3 (unmarked x2): type A
        TetMarking& marking = markings[t];
        marking.vertices = {x[0], x[3], x[1], x[2]};
        marking.acd_unmarked = x[1];
        marking.bcd_unmarked = x[2];
    }
    TetBisection state(mesh, std::move(markings), BisectionRule::newest_vertex);
    if (auto check = state.check_marking(); !check.ok()) return check.refusal();
    return state;
}

Outcome<Done> TetBisection::check_marking() const {
    const Mesh& mesh = *m_mesh;
    for (ElementId t : elements(mesh)) {
        const TetMarking& marking = m_markings[t];
        auto sorted = marking.vertices;
        std::sort(sorted.begin(), sorted.end());
        const auto v = mesh.simplex(t).vertices();
        if (!std::equal(sorted.begin(), sorted.end(), v.begin()))
            return Refusal{RefusalCode::bad_marking,
                           "tet_bisection: the marking of element " + std::to_string(t) +
                               " names other vertices than the element",
                           t};
        for (int i = 0; i < 4; ++i) {
            const FaceId f = mesh.face(t, i);
            const FaceId other = mesh.mate(f);
            if (other == invalid_id) continue;
            const ElementId u = mesh.face_element(other);
            const Edge mine = face_mark(marking, mesh.simplex(t).vertex(i));
            const Edge theirs = face_mark(m_markings[u], mesh.opposite_vertex(u, other));
            if (mine != theirs)
                return Refusal{RefusalCode::bad_marking,
                               "tet_bisection: elements " + std::to_string(t) + " and " +
                                   std::to_string(u) + " disagree on the marked edge of face " +
                                   to_text(mesh.face_simplex(f)),
                               t};
        }
    }
    return Done{};
}

// ---- watching the mesh ----------------------------------------------------------------------

void TetBisection::write_marking(ElementId t, const TetMarking& marking) {
    if (m_markings.size() <= t)
        detail::grow_doubling(m_markings, std::max<std::size_t>(t + 1, m_mesh->element_capacity()), TetMarking{});
    if (!m_opened.empty()) m_undo.push_back({t, m_markings[t], m_last_child});
    m_markings[t] = marking;
}

// ---- the marks beside the mesh (SideLog) ---------------------------------------------------------
//
// The journal calls these after it has put the mesh back (or forward), and its events have by
// then made the state stale; the mesh is as it was at the mark, so the marks written since are
// taken back and the staleness is what it was then.

struct TetBisection::Record final : SideRecord {
    std::vector<Written> written;  // in the order written; replayed from the back
    std::string stale_there;       // the staleness the replay leaves (the other side of the step)
    std::string stale_here;        // the staleness on this side, for the record that goes back
};

std::size_t TetBisection::mark() {
    m_opened.push_back({m_undo.size(), m_stale_reason});
    return m_opened.size() - 1;
}

void TetBisection::rollback_to(std::size_t mark) {
    while (m_undo.size() > m_opened[mark].written) {
        const Written& written = m_undo.back();
        m_markings[written.element] = written.was;
        m_last_child = written.last_child;
        m_undo.pop_back();
    }
    m_stale_reason = std::move(m_opened[mark].stale_reason);
    m_opened.resize(mark);
}

void TetBisection::keep(std::size_t mark) { m_opened.resize(mark); }

std::unique_ptr<SideRecord> TetBisection::commit(std::size_t mark) {
    const std::size_t begin = m_opened[mark].written;
    auto record = std::make_unique<Record>();
    record->written.assign(m_undo.begin() + static_cast<std::ptrdiff_t>(begin), m_undo.end());
    record->stale_there = std::move(m_opened[mark].stale_reason);
    record->stale_here = m_stale_reason;
    m_undo.resize(begin);
    m_opened.resize(mark);
    if (record->written.empty() && record->stale_there == record->stale_here) return nullptr;
    return record;
}

std::unique_ptr<SideRecord> TetBisection::replay(std::unique_ptr<SideRecord> record) {
    // the writes taken back from the last; each leaves the mark it takes back in the record that
    // goes the other way, which is therefore in the order that replays them from the back again
    auto& writes = static_cast<Record&>(*record);
    auto back = std::make_unique<Record>();
    back->written.reserve(writes.written.size());
    for (auto w = writes.written.rbegin(); w != writes.written.rend(); ++w) {
        if (m_markings.size() <= w->element)
            detail::grow_doubling(m_markings, std::max<std::size_t>(w->element + 1, m_mesh->element_capacity()),
                                  TetMarking{});
        back->written.push_back({w->element, m_markings[w->element], m_last_child});
        m_markings[w->element] = w->was;
        m_last_child = w->last_child;
    }
    // the journal's events made the state stale: it is as it was on the record's side
    back->stale_there = std::move(writes.stale_here);
    back->stale_here = writes.stale_there;
    m_stale_reason = std::move(writes.stale_there);
    return back;
}

void TetBisection::foreign_edit(const std::string& what) {
    if (m_own_edit || !m_stale_reason.empty()) return;
    m_stale_reason = "the mesh was edited outside the bisection (" + what + ")";
}

void TetBisection::init(const Mesh&) { foreign_edit("its elements were assigned anew"); }
void TetBisection::element_removed(const Mesh&, ElementId element, const Simplex&) {
    foreign_edit("element " + std::to_string(element) + " removed");
}
void TetBisection::element_changed(const Mesh&, ElementId element, const Simplex&) {
    foreign_edit("element " + std::to_string(element) + " changed");
}
void TetBisection::element_added(const Mesh&, ElementId element) {
    foreign_edit("element " + std::to_string(element) + " added");
}
void TetBisection::boundary_removed(const Mesh&, FaceId face, const Simplex&) {
    foreign_edit("boundary face " + std::to_string(face) + " removed");
}
void TetBisection::boundary_changed(const Mesh&, FaceId face, const Simplex&) {
    foreign_edit("boundary face " + std::to_string(face) + " changed");
}
void TetBisection::boundary_added(const Mesh&, FaceId face) {
    foreign_edit("boundary face " + std::to_string(face) + " added");
}

}  // namespace sxk
