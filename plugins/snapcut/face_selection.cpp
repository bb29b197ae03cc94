// Face selection (face_selection.hpp, thesis §3.2.1).
#include "face_selection.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <limits>

#include "sxk/locate.hpp"
#include "sxk/predicates.hpp"
#include "sxk/traversal.hpp"

// Boost 1.74's rtree includes headers Boost itself marks deprecated (a #pragma message per
// translation unit, not a defect of ours): silenced so that the build stays quiet.
#ifndef BOOST_ALLOW_DEPRECATED_HEADERS
#define BOOST_ALLOW_DEPRECATED_HEADERS
#endif
#include <boost/geometry.hpp>
#include <boost/geometry/index/rtree.hpp>

namespace sxk::snapcut {

namespace bg = boost::geometry;
namespace bgi = boost::geometry::index;

struct CutMarks::SnappedTree {
    using Position = bg::model::point<double, 3, bg::cs::cartesian>;
    using Value = std::pair<Position, VertexId>;
    bgi::rtree<Value, bgi::quadratic<16>> tree;
    static Value value(const Point& p, VertexId v) { return {Position(p[0], p[1], p[2]), v}; }
};

struct CutMarks::SweepTree {
    using Position = SnappedTree::Position;
    using Box = bg::model::box<Position>;
    using Value = std::pair<Box, std::uint32_t>;
    bgi::rtree<Value, bgi::quadratic<16>> tree;
    static Box box(const Point& low, const Point& high) {
        return {Position(low[0], low[1], low[2]), Position(high[0], high[1], high[2])};
    }
    static Value value(const Sweep& sweep, std::uint32_t index) {
        Point low{}, high{};
        for (std::size_t k = 0; k < 3; ++k) {
            low[k] = std::min({sweep.a[k], sweep.b[k], sweep.c[k]});
            high[k] = std::max({sweep.a[k], sweep.b[k], sweep.c[k]});
        }
        return {box(low, high), index};
    }
};

double squared_distance_to_sweep(const Sweep& sweep, const Point& p) {
    const auto w = nearest_on_triangle(sweep.a, sweep.b, sweep.c, p);
    double d2 = 0;
    for (std::size_t k = 0; k < 3; ++k) {
        const double q = w[0] * sweep.a[k] + w[1] * sweep.b[k] + w[2] * sweep.c[k];
        d2 += (p[k] - q) * (p[k] - q);
    }
    return d2;
}

double distance_to_sweep(const Sweep& sweep, const Point& p) { return std::sqrt(squared_distance_to_sweep(sweep, p)); }

namespace {

// A tetrahedron's corners as the selection sees them meet the sweep triangle (a, b, c), exactly.
// The selection sees a dissection's copy of a snapped node where its original was, so there a
// tetrahedron may be flat (two corners at one point, or four in a plane) while it is proper where
// it lies. triangle_meets_tetrahedron lets a flat one meet nothing, but its edges are edges of the
// mesh, and the selection marks every edge the sweep crosses whatever the shape of the elements
// around it (as close_over_crossed_edges finds them): a flat one meets the sweep where one of its
// edges crosses it. Without this, asking the index missed an edge that following the blade marked
// (an edge whose only element was flat as the selection saw it; tests/plugins/snapcut_track_test).
bool corners_meet_sweep(const std::array<Point, 4>& p, const Point& a, const Point& b, const Point& c) {
    if (triangle_meets_tetrahedron(a, b, c, p[0], p[1], p[2], p[3])) return true;
    if (orient3d(p[0], p[1], p[2], p[3]) != Sign::zero) return false;
    for (std::size_t i = 0; i < 4; ++i)
        for (std::size_t j = i + 1; j < 4; ++j)
            if (segment_meets_triangle(p[i], p[j], a, b, c)) return true;
    return false;
}

// The squared distance from p to the farthest of `corners`: an element lies in the ball about p
// through its farthest corner when p is one of its corners.
double squared_farthest_corner(const std::array<Point, 4>& corners, const Point& p) {
    double farthest2 = 0;
    for (const Point& q : corners)
        farthest2 = std::max(farthest2, (p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) +
                                            (p[2] - q[2]) * (p[2] - q[2]));
    return farthest2;
}

// Planes that certainly part a tetrahedron from a sweep triangle, in doubles: the triangle's own
// plane and, square to it, one through each edge with the third corner on the inner side. A
// tetrahedron whose corners all lie beyond one of them by more than `margin` (a billionth of the
// plane's scale, a million times the rounding of a dot product) is apart from the triangle; any
// other goes on to the exact test (triangle_meets_tetrahedron, which tries the same planes with
// exact signs). Most elements around the snapped nodes near a sweep lie behind its old blade:
// told apart here by four dot products instead of up to twenty orientation signs.
class SweepPlanes {
public:
    SweepPlanes(const Sweep& sweep, double reach) : m_origin{sweep.a, sweep.a, sweep.b, sweep.c} {
        const Point& a = sweep.a;
        const Point& b = sweep.b;
        const Point& c = sweep.c;
        const auto minus = [](const Point& x, const Point& y) { return Point{x[0] - y[0], x[1] - y[1], x[2] - y[2]}; };
        const auto cross = [](const Point& x, const Point& y) {
            return Point{x[1] * y[2] - x[2] * y[1], x[2] * y[0] - x[0] * y[2], x[0] * y[1] - x[1] * y[0]};
        };
        const Point normal = cross(minus(b, a), minus(c, a));
        m_normal = {normal, cross(normal, minus(b, a)), cross(normal, minus(c, b)), cross(normal, minus(a, c))};
        double extent = reach;
        for (const Point* x : {&b, &c})
            for (std::size_t k = 0; k < 3; ++k) extent = std::max(extent, std::abs((*x)[k] - a[k]) + reach);
        for (std::size_t i = 0; i < 4; ++i) {
            const Point& m = m_normal[i];
            m_margin[i] = 1e-9 * (std::abs(m[0]) + std::abs(m[1]) + std::abs(m[2])) * 3 * extent;
        }
        // the edge planes' inner side holds the third corner (a, b and c turn counter-clockwise
        // about the normal); a sweep so thin that rounding could put it outside (its angles near
        // 1e-16) keeps no edge plane
        const std::array<const Point*, 4> third{nullptr, &c, &a, &b};
        for (std::size_t i = 1; i < 4; ++i)
            if (!(height(i, *third[i]) > m_margin[i])) m_margin[i] = std::numeric_limits<double>::infinity();
    }
    // The tetrahedron with these corners lies certainly apart from the triangle.
    bool apart(const std::array<Point, 4>& corners) const {
        for (std::size_t i = 0; i < 4; ++i) {
            int below = 0, above = 0;
            for (const Point& x : corners) {
                const double f = height(i, x);
                below += f < -m_margin[i];
                above += f > m_margin[i];
            }
            if (below == 4 || (i == 0 && above == 4)) return true;
        }
        return false;
    }

private:
    double height(std::size_t i, const Point& x) const {
        const Point& o = m_origin[i];
        const Point& m = m_normal[i];
        return m[0] * (x[0] - o[0]) + m[1] * (x[1] - o[1]) + m[2] * (x[2] - o[2]);
    }
    std::array<Point, 4> m_origin;  // a point of each plane
    std::array<Point, 4> m_normal{};
    std::array<double, 4> m_margin{};
};

}  // namespace

CutMarks::CutMarks() : m_tree(std::make_unique<SnappedTree>()), m_sweep_tree(std::make_unique<SweepTree>()) {}
CutMarks::~CutMarks() = default;

std::vector<ElementId> CutMarks::elements_near(const Mesh& mesh, const Sweep& sweep,
                                               std::span<const ElementId> known) const {
    using Position = SnappedTree::Position;
    Position low(std::min({sweep.a[0], sweep.b[0], sweep.c[0]}) - m_reach,
                 std::min({sweep.a[1], sweep.b[1], sweep.c[1]}) - m_reach,
                 std::min({sweep.a[2], sweep.b[2], sweep.c[2]}) - m_reach);
    Position high(std::max({sweep.a[0], sweep.b[0], sweep.c[0]}) + m_reach,
                  std::max({sweep.a[1], sweep.b[1], sweep.c[1]}) + m_reach,
                  std::max({sweep.a[2], sweep.b[2], sweep.c[2]}) + m_reach);
    // The box around the sweep holds the snapped nodes of a slab as tall as the blade is tilted
    // (the whole incision's rim on the femur, docs/performance.md "snapcut"); the distance to the
    // triangle keeps those whose stars reach as far (their own radius: 0.6 of the nodes the largest
    // radius would keep on the 1.2M femur at 1 kHz), and of their stars the elements that reach as
    // far (816 elements searched per step on the 213k femur before, 403 after), each with a
    // margin for the rounding. Those are mostly the elements along the incision just cut, behind the
    // blade: on the 1.2M femur at 1 kHz about 470 a sweep, of which about 32 meet it (the sweep
    // itself meets about 70 elements): the planes part most of the others, the exact test the
    // rest (the selection looks at those it does not meet only when they change:
    // CutMarks::look_again).
    constexpr double margin = 1 + 1e-9;
    const SweepPlanes planes(sweep, m_reach);
    std::vector<ElementId> near, around;
    for (auto it = m_tree->tree.qbegin(bgi::intersects(bg::model::box<Position>(low, high)));
         it != m_tree->tree.qend(); ++it) {
        const Point p{bg::get<0>(it->first), bg::get<1>(it->first), bg::get<2>(it->first)};
        const VertexId v = it->second;
        const double d2 = squared_distance_to_sweep(sweep, p);
        const double radius = m_nodes[v].radius;  // add_snapped sized m_nodes
        if (!(d2 <= radius * radius * margin)) continue;
        around.clear();
        collect_star(mesh, v, mesh.vertex_element(v), around);
        for (const ElementId t : around) {
            const std::array<Point, 4> corners = selection_corners(mesh, t);
            if (d2 <= squared_farthest_corner(corners, p) * margin && !planes.apart(corners)) near.push_back(t);
        }
    }
    // an element with several snapped corners is in several stars: tested once, and not at all
    // when the caller has it (the elements the blade lies in, along the sweep's edge: about half
    // of those that meet the sweep on the 1.2M femur at 1 kHz)
    std::sort(near.begin(), near.end());
    near.erase(std::unique(near.begin(), near.end()), near.end());
    std::erase_if(near, [&](ElementId t) {
        if (std::binary_search(known.begin(), known.end(), t)) return true;
        return !corners_meet_sweep(selection_corners(mesh, t), sweep.a, sweep.b, sweep.c);
    });
    return near;
}

std::uint64_t CutMarks::key(VertexId a, VertexId b) {
    if (a > b) std::swap(a, b);
    return (std::uint64_t{a} << 32) | b;
}

std::optional<CutMarks::Mark> CutMarks::find_mark(VertexId a, VertexId b) const {
    const auto found = m_marks.find(key(a, b));
    if (found == m_marks.end()) return std::nullopt;
    return found->second;
}

void CutMarks::add_mark(VertexId a, VertexId b, const Mark& mark) {
    if (!m_marks.emplace(key(a, b), mark).second) return;
    m_mark_order.push_back(key(a, b));
    count_marks_at(key(a, b), +1);
}

void CutMarks::count_marks_at(std::uint64_t key, int change) {
    for (const auto v : {static_cast<VertexId>(key >> 32), static_cast<VertexId>(key & 0xffffffffu)}) {
        if (v >= m_marks_at.size()) m_marks_at.resize(std::size_t{v} + 1, 0);
        m_marks_at[v] = static_cast<std::uint32_t>(static_cast<std::int64_t>(m_marks_at[v]) + change);
    }
}

std::uint32_t CutMarks::add_sweep(const Sweep& sweep) {
    m_sweeps.push_back(sweep);
    const auto index = static_cast<std::uint32_t>(m_sweeps.size() - 1);
    m_sweep_tree->tree.insert(SweepTree::value(sweep, index));
    return index;
}

template <class Visit>
bool CutMarks::for_sweeps_near(const Point& p, double distance, Visit visit) const {
    const Point low{p[0] - distance, p[1] - distance, p[2] - distance};
    const Point high{p[0] + distance, p[1] + distance, p[2] + distance};
    for (auto it = m_sweep_tree->tree.qbegin(bgi::intersects(SweepTree::box(low, high)));
         it != m_sweep_tree->tree.qend(); ++it)
        if (visit(distance_to_sweep(m_sweeps[it->second], p))) return true;
    return false;
}

bool CutMarks::near_sweeps(const Point& p, double distance) const {
    return for_sweeps_near(p, distance, [distance](double d) { return d <= distance; });
}

double CutMarks::distance_to_sweeps(const Point& p, double at_most) const {
    double nearest = at_most;
    for_sweeps_near(p, at_most, [&nearest](double d) {
        nearest = std::min(nearest, d);
        return false;
    });
    return nearest;
}

bool SweptSurface::near(const Point& p) const {
    for (const Sweep& next : ahead)
        if (distance_to_sweep(next, p) <= beyond) return true;
    return marks.near_sweeps(p, beyond);
}

std::vector<std::uint32_t> CutMarks::sweeps_meeting_box(const Point& low, const Point& high) const {
    std::vector<SweepTree::Value> values;
    m_sweep_tree->tree.query(bgi::intersects(SweepTree::box(low, high)), std::back_inserter(values));
    std::vector<std::uint32_t> found;
    found.reserve(values.size());
    for (const auto& value : values) found.push_back(value.second);
    std::sort(found.begin(), found.end());
    return found;
}

CutMarks::Node& CutMarks::node(VertexId v) {
    if (v >= m_nodes.size()) m_nodes.resize(std::size_t{v} + 1);
    return m_nodes[v];
}

void CutMarks::cover_star(const Mesh& mesh, VertexId v) {
    std::vector<ElementId> around;
    collect_star(mesh, v, mesh.vertex_element(v), around);
    cover_elements(mesh, around);
}

void CutMarks::cover_elements(const Mesh& mesh, std::span<const ElementId> elements) {
    for (const ElementId t : elements) {
        if (!mesh.is_element(t)) continue;
        const std::array<Point, 4> corners = selection_corners(mesh, t);
        for (int i = 0; i < 4; ++i)
            if (const VertexId v = mesh.simplex(t).vertex(i); snapped(v)) {
                const double radius = std::sqrt(squared_farthest_corner(corners, corners[static_cast<std::size_t>(i)]));
                m_nodes[v].radius = std::max(m_nodes[v].radius, radius);
                m_reach = std::max(m_reach, radius);
            }
    }
}

void CutMarks::cover_all(const Mesh& mesh) {
    for (const VertexId v : m_snapped_order)
        if (mesh.vertex_element(v) != invalid_id) cover_star(mesh, v);
}

void CutMarks::add_snapped(const Mesh& mesh, VertexId v, Point was) {
    if (snapped(v)) return;
    node(v).was = was;
    m_nodes[v].snapped = true;
    m_snapped_order.push_back(v);
    m_tree->tree.insert(SnappedTree::value(was, v));
    cover_star(mesh, v);
}

void CutMarks::trim(std::size_t marks, std::size_t snapped, std::size_t sweeps) {
    while (m_mark_order.size() > marks) {
        count_marks_at(m_mark_order.back(), -1);
        m_marks.erase(m_mark_order.back());
        m_mark_order.pop_back();
    }
    while (m_snapped_order.size() > snapped) {
        Node& node = m_nodes[m_snapped_order.back()];
        node.snapped = false;  // its radius stays: a larger one finds more, never less
        m_tree->tree.remove(SnappedTree::value(node.was, m_snapped_order.back()));
        m_snapped_order.pop_back();
    }
    while (m_sweeps.size() > sweeps) {
        m_sweep_tree->tree.remove(SweepTree::value(m_sweeps.back(), static_cast<std::uint32_t>(m_sweeps.size() - 1)));
        m_sweeps.pop_back();
    }
}

// ---- beside the mesh (SideLog) -----------------------------------------------------------------
//
// Marks, snapped nodes and sweeps are only ever added, so a step's are the newest: a mark is
// their counts, a rollback or an undo forgets what came after them, and a redo adds the step's
// again (the record keeps them). The lists are copied when they first change inside a step.

struct CutMarks::Record final : SideRecord {
    std::vector<std::pair<std::uint64_t, Mark>> marks;   // the step's, by key, in order
    std::vector<std::pair<VertexId, Point>> snapped;     // the step's snapped nodes, with `was`
    std::vector<Sweep> sweeps;                           // the step's sweeps
    std::shared_ptr<const Lists> before, after;          // null: the step left the lists alone
    bool applied = true;                                 // the state holds the step
};

void CutMarks::before_lists_change() {
    if (m_opened.empty() || m_opened.back().lists) return;
    // every open step the lists have not changed in yet sees them as they are now
    const auto now = std::make_shared<const Lists>(m_lists);
    for (auto opened = m_opened.rbegin(); opened != m_opened.rend() && !opened->lists; ++opened) opened->lists = now;
}

std::size_t CutMarks::mark() {
    m_opened.push_back({m_mark_order.size(), m_snapped_order.size(), m_sweeps.size(), nullptr});
    return m_opened.size() - 1;
}

void CutMarks::rollback_to(std::size_t mark) {
    const Opened& opened = m_opened[mark];
    trim(opened.marks, opened.snapped, opened.sweeps);
    if (opened.lists) m_lists = *opened.lists;
    m_opened.resize(mark);
}

void CutMarks::keep(std::size_t mark) { m_opened.resize(mark); }

std::unique_ptr<SideRecord> CutMarks::commit(std::size_t mark) {
    const Opened opened = std::move(m_opened[mark]);
    m_opened.resize(mark);
    auto record = std::make_unique<Record>();
    for (std::size_t i = opened.marks; i < m_mark_order.size(); ++i)
        record->marks.emplace_back(m_mark_order[i], m_marks.at(m_mark_order[i]));
    for (std::size_t i = opened.snapped; i < m_snapped_order.size(); ++i)
        record->snapped.emplace_back(m_snapped_order[i], m_nodes[m_snapped_order[i]].was);
    record->sweeps.assign(m_sweeps.begin() + static_cast<std::ptrdiff_t>(opened.sweeps), m_sweeps.end());
    if (opened.lists) {
        record->before = opened.lists;
        record->after = std::make_shared<const Lists>(m_lists);
    }
    if (record->marks.empty() && record->snapped.empty() && record->sweeps.empty() && !record->before) return nullptr;
    return record;
}

std::unique_ptr<SideRecord> CutMarks::replay(std::unique_ptr<SideRecord> record) {
    auto& step = static_cast<Record&>(*record);
    if (step.applied) {  // undo: the step's are the newest
        trim(m_mark_order.size() - step.marks.size(), m_snapped_order.size() - step.snapped.size(),
             m_sweeps.size() - step.sweeps.size());
        if (step.before) m_lists = *step.before;
    } else {  // redo
        for (const auto& [key, mark] : step.marks) add_mark(static_cast<VertexId>(key >> 32),
                                                            static_cast<VertexId>(key & 0xffffffffu), mark);
        for (const auto& [v, was] : step.snapped) {
            node(v).was = was;
            m_nodes[v].snapped = true;
            m_snapped_order.push_back(v);
            m_tree->tree.insert(SnappedTree::value(was, v));
        }
        for (const Sweep& sweep : step.sweeps) (void)add_sweep(sweep);
        if (step.after) m_lists = *step.after;
    }
    step.applied = !step.applied;
    return record;
}

namespace {

// The end of edge {u, v} nearer where it crosses the sweep's plane; an exact half (or an edge in
// the plane) gives the lower id.
VertexId nearer_end(const Mesh& mesh, const CutMarks& marks, VertexId u, VertexId v, const Sweep& sweep) {
    switch (compare_distances_to_plane(marks.selection_position(mesh, u), marks.selection_position(mesh, v), sweep.a,
                                       sweep.b, sweep.c)) {
    case Sign::negative: return u;
    case Sign::positive: return v;
    case Sign::zero: break;
    }
    return std::min(u, v);
}

}  // namespace

bool meets_as_selected(const Mesh& mesh, const CutMarks& marks, ElementId t, const Point& a, const Point& b,
                       const Point& c) {
    return corners_meet_sweep(marks.selection_corners(mesh, t), a, b, c);
}

bool meets_as_selected(const Mesh& mesh, const CutMarks& marks, ElementId t, const Point& a, const Point& b) {
    const std::array<Point, 4> p = marks.selection_corners(mesh, t);
    return segment_meets_tetrahedron(a, b, p[0], p[1], p[2], p[3]);
}

SweptElements close_over_crossed_edges(const Mesh& mesh, const CutMarks& marks, const Sweep& sweep,
                                       std::span<const ElementId> roots) {
    SweptElements result;
    std::vector<ElementId>& found = result.elements;
    detail::FlatSet<std::uint32_t> seen;
    for (const ElementId t : roots)
        if (mesh.is_element(t) && seen.insert(t)) found.push_back(t);
    // each edge is tested once, not once from each of its elements (about five), and what it
    // missed goes to select_faces, which tests the same edges against the same sweep
    std::vector<std::uint64_t> crossed;  // edges whose elements are listed already (a few a sweep)
    std::vector<ElementId> around;
    for (std::size_t next = 0; next < found.size(); ++next) {
        const ElementId t = found[next];
        const Simplex s = mesh.simplex(t);
        for (int i = 0; i < 4; ++i)
            for (int j = i + 1; j < 4; ++j) {
                const VertexId u = s.vertex(i), v = s.vertex(j);
                const std::uint64_t edge = (std::uint64_t{u} << 32) | v;  // u < v: canonical order
                if (std::find(crossed.begin(), crossed.end(), edge) != crossed.end()) continue;
                if (result.missed.contains(edge)) continue;
                if (!segment_meets_triangle(marks.selection_position(mesh, u), marks.selection_position(mesh, v),
                                            sweep.a, sweep.b, sweep.c)) {
                    result.missed.insert(edge);
                    continue;
                }
                crossed.push_back(edge);
                around.clear();
                collect_star(mesh, u, t, around);
                for (const ElementId e : around)
                    if (mesh.simplex(e).contains(v) && seen.insert(e)) found.push_back(e);
            }
    }
    std::sort(found.begin(), found.end());
    return result;
}

Selection select_faces(const Mesh& mesh, CutMarks& marks, std::uint32_t sweep_index,
                       std::span<const ElementId> candidates, const SweptSurface* swept, MissedEdges missed) {
    const Sweep& sweep = marks.sweeps()[sweep_index];
    Selection selection;
    // `missed` grows by the edges this sweep tests here and does not cross
    std::vector<ElementId> incomplete;
    for (const ElementId t : candidates) {
        if (!mesh.is_element(t)) continue;
        ++selection.elements_searched;
        const Simplex s = mesh.simplex(t);
        // marked corners of t: which, and the first sweep that marked each
        std::array<std::uint32_t, 4> first_sweep;
        first_sweep.fill(UINT32_MAX);
        for (int i = 0; i < 4; ++i)
            for (int j = i + 1; j < 4; ++j) {
                const VertexId u = s.vertex(i), v = s.vertex(j);
                std::optional<CutMarks::Mark> mark = marks.mark(u, v);
                if (!mark) {
                    const std::uint64_t edge = (std::uint64_t{u} << 32) | v;  // u < v: canonical order
                    if (missed.contains(edge)) continue;
                    if (!segment_meets_triangle(marks.selection_position(mesh, u), marks.selection_position(mesh, v),
                                                sweep.a, sweep.b, sweep.c)) {
                        missed.insert(edge);
                        continue;
                    }
                    VertexId nearer = nearer_end(mesh, marks, u, v, sweep);
                    const VertexId other = nearer == u ? v : u;
                    if (swept != nullptr && marks.snapped(other) && !marks.snapped(nearer) &&
                        !swept->near(mesh.deformed(nearer)))
                        nearer = other;
                    mark = CutMarks::Mark{nearer, sweep_index};
                    marks.add_mark(u, v, *mark);
                    ++selection.edges_hit;
                }
                const int corner = mark->node == u ? i : j;
                first_sweep[static_cast<std::size_t>(corner)] =
                    std::min(first_sweep[static_cast<std::size_t>(corner)], mark->sweep);
            }
        auto marked = static_cast<int>(
            std::count_if(first_sweep.begin(), first_sweep.end(), [](std::uint32_t w) { return w != UINT32_MAX; }));
        if (marked < 3) {
            // corners snapped onto the cut from other tetrahedra's edges may complete a
            // tetrahedron, whether the sweep crosses it or no corner of it is marked at all
            // (face_selection.hpp, "Corners snapped elsewhere")
            const auto on_cut_elsewhere = [&](int i) {
                return first_sweep[static_cast<std::size_t>(i)] == UINT32_MAX && marks.snapped(s.vertex(i));
            };
            int on_cut = marked;
            for (int i = 0; i < 4; ++i) on_cut += on_cut_elsewhere(i) ? 1 : 0;
            if (on_cut == 3) {
                for (int i = 0; i < 4; ++i)
                    if (on_cut_elsewhere(i)) first_sweep[static_cast<std::size_t>(i)] = sweep_index;
                marked = 3;
            } else if (marked == 0) {
                continue;  // not met by any sweep, and not completed: not incomplete either
            }
        }
        if (marked < 3) {
            incomplete.push_back(t);
            continue;
        }
        // the unmarked corner, or with four marked the highest vertex id (s is sorted)
        int left_out = 3;
        for (int i = 0; i < 4; ++i)
            if (first_sweep[static_cast<std::size_t>(i)] == UINT32_MAX) left_out = i;
        if (mesh.mate(mesh.face(t, left_out)) == invalid_id) continue;  // on the boundary already
        SelectedFace face;
        std::array<VertexId, 3> corners{};
        for (int i = 0, k = 0; i < 4; ++i) {
            if (i == left_out) continue;
            corners[static_cast<std::size_t>(k)] = s.vertex(i);
            face.sweep[static_cast<std::size_t>(k++)] = first_sweep[static_cast<std::size_t>(i)];
        }
        face.face = Simplex(+1, corners);
        selection.faces.push_back(face);
    }
    // a face is selected from both its tetrahedra: keep one (the first after sorting)
    std::sort(selection.faces.begin(), selection.faces.end(),
              [](const SelectedFace& x, const SelectedFace& y) { return x.face < y.face; });
    selection.faces.erase(std::unique(selection.faces.begin(), selection.faces.end(),
                                      [](const SelectedFace& x, const SelectedFace& y) { return x.face == y.face; }),
                          selection.faces.end());
    std::sort(incomplete.begin(), incomplete.end());
    marks.set_incomplete(std::move(incomplete));
    return selection;
}

}  // namespace sxk::snapcut
