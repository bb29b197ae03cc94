// The R-trees behind SpatialIndex (sxk/locate.hpp) and the geometry its queries share. The one
// place Boost.Geometry enters the toolkit; include only from core/src/locate_*.cpp.
#pragma once

// Boost 1.74's rtree includes headers Boost itself marks deprecated (a #pragma message per
// translation unit, not a defect of ours): silenced so that the build stays quiet.
#ifndef BOOST_ALLOW_DEPRECATED_HEADERS
#define BOOST_ALLOW_DEPRECATED_HEADERS
#endif
#include <boost/geometry.hpp>
#include <boost/geometry/index/rtree.hpp>
#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <array>
#include <bit>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <deque>
#include <limits>
#include <span>
#include <type_traits>
#include <utility>
#include <vector>

#include "sxk/locate.hpp"
#include "sxk/mesh.hpp"

namespace sxk::detail {

namespace bg = boost::geometry;
namespace bgi = boost::geometry::index;

// Boost orders the candidates by distances it computes in the boxes' single precision: a later
// box may be nearer, in double precision, than the current one by a few float units. A search
// for the nearest stops only past this factor, which keeps every box that may hold something
// nearer.
inline constexpr double float_box_slack = 1 + 1e-5;

// std::nextafter toward -inf (+inf) for a finite float, by its bits: the libm call was an eighth
// of re-boxing every element of a frame (perf, the 1M Kuhn cube bending). Zero steps to the
// smallest subnormal of the other sign (as nextafter does); the largest float up gives infinity.
inline float next_float_down(float f) {
    if (f == 0) return -std::numeric_limits<float>::denorm_min();
    const auto bits = std::bit_cast<std::uint32_t>(f);
    return std::bit_cast<float>(f > 0 ? bits - 1 : bits + 1);
}
inline float next_float_up(float f) {
    if (f == 0) return std::numeric_limits<float>::denorm_min();
    const auto bits = std::bit_cast<std::uint32_t>(f);
    return std::bit_cast<float>(f > 0 ? bits + 1 : bits - 1);
}

// The next float below (above) x, at least one unit in the last place away (a double beyond
// the floats' range, which a cast may not take, gives the largest float or infinity).
inline float float_below(double x) {
    constexpr double largest = std::numeric_limits<float>::max();
    if (!(x <= largest)) return std::numeric_limits<float>::max();
    if (x < -largest) return -std::numeric_limits<float>::infinity();
    float f = static_cast<float>(x);
    if (static_cast<double>(f) > x) f = next_float_down(f);
    return next_float_down(f);
}
inline float float_above(double x) {
    constexpr double largest = std::numeric_limits<float>::max();
    if (!(x >= -largest)) return -std::numeric_limits<float>::max();
    if (x > largest) return std::numeric_limits<float>::infinity();
    float f = static_cast<float>(x);
    if (static_cast<double>(f) < x) f = next_float_up(f);
    return next_float_up(f);
}

// One rtree of boxes over 32-bit ids (elements or boundary faces). Single-precision boxes: the
// tree's nodes are half the size, and the walk through them is memory-bound at 1M elements
// (docs/performance.md "locate"). quadratic<8>: of linear/quadratic/rstar at 8-32 entries, the
// fastest insertion and point query on a 1M-tetrahedron Kuhn cube (R* inserts 3-5x slower).
//
// The tree holds ENTRIES, not ids: an entry is a box and the few ids (at most max_members) whose
// boxes it holds; queries test the members of every entry they meet. A tree operation costs
// ~1.5 us at 1M entries against ~3 us for a whole flip (docs/performance.md "locate"), and an
// edit removes elements and adds others in the same place, so:
//   * an id added (or re-boxed after a move) joins an entry that holds its box and is not more
//     than `slack_factor` times wider along any axis, looked for among the entries that lost a
//     member lately (its parent's, when a split's child is added: the pools hand the parents'
//     ids to the children in another order, so keying entries by id missed most of them);
//     only when none holds it does it get an entry of its own, one tree insertion;
//   * an entry left without members stays in the tree as a host for what comes next; empty
//     entries are removed for good, oldest first and at most two per removal event, once there
//     are more than 64 + live/64 of them (no stall: removing them all at once could mean 125k
//     removals of ~1.5 us each at 1M).
template <int D>
struct BoxTree {
    using Coordinates = bg::model::point<float, D, bg::cs::cartesian>;
    using QueryPoint = bg::model::point<double, D, bg::cs::cartesian>;
    using Box = bg::model::box<Coordinates>;
    using Value = std::pair<Box, std::uint32_t>;  // an entry's box and key
    using Tree = bgi::rtree<Value, bgi::quadratic<8>>;
    static constexpr float slack_factor = 4;
    static constexpr std::uint32_t none = std::numeric_limits<std::uint32_t>::max();
    // A query tests every member of an entry it meets: few, so that a hosted id costs a query
    // about what a tree entry of its own would.
    static constexpr std::uint32_t max_members = 4;
    static constexpr std::size_t recent_size = 16;

    struct Entry {
        Box box;
        std::uint32_t first = none;  // first member id; next_member links the others
        std::uint32_t members = 0;
        bool in_tree = false;
    };

    Tree tree;
    std::vector<Entry> entries;                // by key
    std::vector<std::uint32_t> free_keys;      // keys of entries no longer in the tree
    std::vector<std::uint32_t> entry_of;       // by id: its entry's key, or none
    std::vector<std::uint32_t> next_member;    // by id: the next member of its entry, or none
    std::size_t live_count = 0, empty_count = 0;
    // The mean largest side of the entries' boxes at the last load: the scale below which a query
    // box holds few entries (elements_hit_by_triangle splits its triangle down to it). Edits do
    // not change it; it only steers how queries are cut up, never what they find.
    double mean_side = 0;
    std::deque<std::uint32_t> empty_order;     // keys as they became empty (refilled ones too)
    std::array<std::uint32_t, recent_size> recent;  // keys of entries that lost a member lately
    std::size_t recent_next = 0;

    BoxTree() { recent.fill(none); }

    // The points' extent along each axis, in doubles, before any padding.
    struct Extent {
        std::array<double, D> lo, hi;
    };
    static Extent extent_of(std::span<const Point* const> points) {
        Extent e;
        for (int k = 0; k < D; ++k) {
            const auto uk = static_cast<std::size_t>(k);
            double lo = std::numeric_limits<double>::infinity(), hi = -lo;
            for (const Point* p : points) {
                lo = std::min(lo, (*p)[uk]);
                hi = std::max(hi, (*p)[uk]);
            }
            e.lo[uk] = lo;
            e.hi[uk] = hi;
        }
        return e;
    }
    // Grown by about a millionth of the box's size and distance from the origin: Boost's segment
    // and distance tests on float boxes compute in double precision with rounding, and a segment
    // through a corner of an element at a coordinate 0 (a float unit of 1e-45 there) was missed
    // without it (tests/core/locate_test.cpp found it).
    static double pad(double lo, double hi) { return (hi - lo + std::max(std::abs(lo), std::abs(hi))) * 0x1p-20; }
    static Box box_of(const Extent& e, double margin = 0) {
        Box box;
        for (int k = 0; k < D; ++k) {
            const auto uk = static_cast<std::size_t>(k);
            const double grow = pad(e.lo[uk], e.hi[uk]) + margin;
            set_corner(box.min_corner(), k, float_below(e.lo[uk] - grow));
            set_corner(box.max_corner(), k, float_above(e.hi[uk] + grow));
        }
        return box;
    }
    static Box box_of(std::span<const Point* const> points) { return box_of(extent_of(points)); }
    static void set_corner(Coordinates& c, int k, float value) {
        if (k == 0) bg::set<0>(c, value);
        else if (k == 1) bg::set<1>(c, value);
        else if constexpr (D == 3) bg::set<2>(c, value);
    }
    static float corner(const Coordinates& c, int k) {
        if (k == 0) return bg::get<0>(c);
        if (k == 1) return bg::get<1>(c);
        if constexpr (D == 3) return bg::get<2>(c);
        return 0;
    }
    static QueryPoint query_point(const Point& x) {
        if constexpr (D == 2) return QueryPoint(x[0], x[1]);
        else return QueryPoint(x[0], x[1], x[2]);
    }
    // The box of a query point: the float box that contains it, so a point query compares floats
    // only.
    static Box point_box(const Point& x) {
        const Point* p = &x;
        return box_of(std::span<const Point* const>(&p, 1));
    }
    // `outer` holds `inner` and is at most slack_factor times as wide along every axis.
    static bool holds(const Box& outer, const Box& inner) {
        for (int k = 0; k < D; ++k) {
            const float lo = corner(outer.min_corner(), k), hi = corner(outer.max_corner(), k);
            const float in_lo = corner(inner.min_corner(), k), in_hi = corner(inner.max_corner(), k);
            if (in_lo < lo || in_hi > hi || hi - lo > slack_factor * (in_hi - in_lo)) return false;
        }
        return true;
    }

    void clear() {
        tree.clear();
        entries.clear();
        free_keys.clear();
        entry_of.clear();
        next_member.clear();
        empty_order.clear();
        recent.fill(none);
        live_count = empty_count = 0;
        mean_side = 0;
    }
    bool is_live(std::uint32_t id) const { return id < entry_of.size() && entry_of[id] != none; }
    // The box the tree holds for a live id (its entry's).
    const Box& box(std::uint32_t id) const { return entries[entry_of[id]].box; }
    // Calls f(id) for each member of the entry `key` until f returns true; true if one did.
    template <class F>
    bool any_member(std::uint32_t key, F&& f) const {
        for (std::uint32_t id = entries[key].first; id != none; id = next_member[id])
            if (f(id)) return true;
        return false;
    }

    // id (added, changed or moved) now has the tight box `box`.
    void insert(std::uint32_t id, const Box& box) {
        if (id >= entry_of.size()) {
            entry_of.resize(static_cast<std::size_t>(id) + 1, none);
            next_member.resize(static_cast<std::size_t>(id) + 1, none);
        }
        if (entry_of[id] != none) {
            if (holds(entries[entry_of[id]].box, box)) return;
            unlink(id);
        }
        for (const std::uint32_t key : recent)
            if (key != none && entries[key].in_tree && entries[key].members < max_members &&
                holds(entries[key].box, box)) {
                link(id, key);
                return;
            }
        std::uint32_t key;
        if (!free_keys.empty()) {
            key = free_keys.back();
            free_keys.pop_back();
        } else {
            key = static_cast<std::uint32_t>(entries.size());
            entries.emplace_back();
        }
        entries[key] = Entry{box, none, 0, true};
        tree.insert(Value(box, key));
        ++empty_count;  // link counts it full again
        link(id, key);
    }
    void erase(std::uint32_t id) {
        if (!is_live(id)) return;
        unlink(id);
        trim(2);
    }
    void update(std::uint32_t id, const Box& box) { insert(id, box); }
    // `id` moved to the extent `e` with a few vertices (a tool's local solve writing its region):
    // what refit does for one id. An entry that still covers it costs that test; one it left is
    // re-entered grown by a margin, so the next frames, which move it about as far, find it
    // inside. Re-entering the tight box instead left it again at the next frame: every element
    // around a local solve's region was removed and inserted every frame, 30 % of the needle's
    // step on a million triangles (docs/performance.md "needle").
    void follow(std::uint32_t id, const Extent& e) {
        if (!is_live(id)) {
            insert(id, box_of(e));
            return;
        }
        const Box& held = entries[entry_of[id]].box;
        if (follows(held, e)) return;
        insert(id, grown(held, e));
        trim(1);
    }

    // After a move of most of what the tree indexes (a simulation writing its frame): `extent(id)`
    // is the extent of id's positions now. An id whose entry still covers its box costs that test
    // (in doubles, no rounding to floats: `follows`); one that left it gets an entry grown by a
    // margin (`grown`), so that the frames after, which move it about as far, find it inside.
    // When more than one id in `rebuild_share` left its entry, one bulk load of every id (the
    // boxes that stayed, the grown ones) is cheaper than a removal and an insertion each (~0.4 us
    // an id against ~3 us). The test runs in parallel over the entries (TBB): it was the frame's
    // whole cost.
    static constexpr std::size_t rebuild_share = 8;
    template <class TightExtent>
    void refit(TightExtent&& extent) {
        using Left = std::vector<std::pair<std::uint32_t, Box>>;
        using Range = tbb::blocked_range<std::size_t>;
        // by entry, not by id: the boundary faces are a few of all the faces' ids (four an
        // element); the ranges' lists are joined in the entries' order (parallel_reduce keeps the
        // order of a reduction that is not commutative), which the bulk load below relies on
        const Left left = tbb::parallel_reduce(
            Range(0, entries.size(), 4096), Left{},
            [&](const Range& range, Left found) {
                for (std::size_t key = range.begin(); key != range.end(); ++key) {
                    const Entry& entry = entries[key];
                    if (!entry.in_tree) continue;
                    for (std::uint32_t id = entry.first; id != none; id = next_member[id]) {
                        const Extent e = extent(id);
                        if (!follows(entry.box, e)) found.emplace_back(id, grown(entry.box, e));
                    }
                }
                return found;
            },
            [](Left a, const Left& b) {
                a.insert(a.end(), b.begin(), b.end());
                return a;
            });
        if (left.size() * rebuild_share > live_count) {
            std::vector<Value> values;
            values.reserve(live_count);
            auto next = left.begin();
            for (const Entry& entry : entries) {
                if (!entry.in_tree) continue;
                for (std::uint32_t id = entry.first; id != none; id = next_member[id]) {
                    if (next != left.end() && next->first == id) values.emplace_back((next++)->second, id);
                    else values.emplace_back(entry.box, id);
                }
            }
            load(values);
        } else {
            for (const auto& [id, box] : left) insert(id, box);
            trim(static_cast<int>(left.size()));
        }
    }
    // `held` covers box_of(e), and is no wider along any axis than slack_factor times that box's
    // largest side (a margin from `grown` stays, the box of an id now elsewhere does not; a
    // boundary face's box may be flat along an axis, so the slack is against the largest side).
    // In doubles: `held` must reach 1.5 pads beyond the extent, where box_of reaches at most 1.3
    // (the pad, then at most two float units below it, each at most 2^-23 of the coordinate and
    // so a quarter of the pad, or 2 subnormal units near zero), so what this passes validate()
    // passes too; an id it fails on a rounding is re-boxed, which is only work.
    static bool follows(const Box& held, const Extent& e) {
        double side = 0;
        std::array<double, D> reach{};
        for (int k = 0; k < D; ++k) {
            const auto uk = static_cast<std::size_t>(k);
            const double p = pad(e.lo[uk], e.hi[uk]);
            reach[uk] = 1.5 * p + 0x1p-146;  // 2^-146: 8 subnormal float units
            side = std::max(side, e.hi[uk] - e.lo[uk] + 2 * p);
        }
        for (int k = 0; k < D; ++k) {
            const auto uk = static_cast<std::size_t>(k);
            const double lo = corner(held.min_corner(), k), hi = corner(held.max_corner(), k);
            if (lo > e.lo[uk] - reach[uk] || hi < e.hi[uk] + reach[uk] || hi - lo > slack_factor * side) return false;
        }
        return true;
    }
    // The box of `e` grown on every side by twice as far as it left `held`, at least an eighth of
    // its largest side (a haptic frame moves the nodes by much less), at most its largest side.
    static Box grown(const Box& held, const Extent& e) {
        double side = 0, left = 0;
        for (int k = 0; k < D; ++k) {
            const auto uk = static_cast<std::size_t>(k);
            side = std::max(side, e.hi[uk] - e.lo[uk]);
            left = std::max({left, double(corner(held.min_corner(), k)) - e.lo[uk],
                             e.hi[uk] - double(corner(held.max_corner(), k))});
        }
        return box_of(e, std::min(std::max(2 * left, side / 8), side));
    }
    // Removes up to `budget` of the oldest empty entries from the tree while there are more
    // than 64 + live/64; keeps the queue of empty keys within a few times their number.
    void trim(int budget) {
        const std::size_t limit = 64 + live_count / 64;
        while (empty_count > limit && budget > 0 && !empty_order.empty()) {
            const std::uint32_t key = empty_order.front();
            empty_order.pop_front();
            Entry& e = entries[key];
            if (!e.in_tree || e.members != 0) continue;  // refilled since, or gone
            tree.remove(Value(e.box, key));
            e.in_tree = false;
            free_keys.push_back(key);
            --empty_count;
            --budget;
        }
        if (empty_order.size() > 4 * (empty_count + 64)) {
            std::deque<std::uint32_t> still;
            for (const std::uint32_t key : empty_order)
                if (entries[key].in_tree && entries[key].members == 0) still.push_back(key);
            empty_order.swap(still);
        }
    }
    // Replaces the whole tree by a bulk load (the packing constructor: O(n log n), better nodes
    // than n insertions), one entry per id: `values` pairs boxes with ids.
    void load(std::vector<Value>& values) {
        clear();
        std::uint32_t largest = 0;
        for (const Value& v : values) largest = std::max(largest, v.second);
        // room for the first edits' new ids and entries: growing an exactly sized array copies
        // all of it into fresh pages (40 MB of entries at 1.2M elements): in a profile of the
        // snap cutter on the 1.2M femur, about 0.2 s of each session's first steps
        const auto headroom = [](std::size_t n) { return n + n / 8 + 64; };
        if (!values.empty()) {
            entry_of.reserve(headroom(static_cast<std::size_t>(largest) + 1));
            next_member.reserve(headroom(static_cast<std::size_t>(largest) + 1));
            entry_of.assign(static_cast<std::size_t>(largest) + 1, none);
            next_member.assign(static_cast<std::size_t>(largest) + 1, none);
        }
        entries.reserve(headroom(values.size()));
        entries.resize(values.size());
        for (std::uint32_t key = 0; key < values.size(); ++key) {
            const std::uint32_t id = values[key].second;
            entries[key] = Entry{values[key].first, id, 1, true};
            entry_of[id] = key;
            values[key].second = key;
        }
        live_count = values.size();
        double sides = 0;
        for (const Value& v : values) {
            double side = 0;
            for (int k = 0; k < D; ++k)
                side = std::max(side, double(corner(v.first.max_corner(), k) - corner(v.first.min_corner(), k)));
            sides += side;
        }
        mean_side = values.empty() ? 0 : sides / double(values.size());
        tree = Tree(values.begin(), values.end());
    }
    std::size_t memory_bytes() const {
        // the tree's nodes hold the values plus about 40% slack at a fill of 8/(8*0.7)
        return entries.capacity() * sizeof(Entry) + (entry_of.capacity() + next_member.capacity() +
                                                     free_keys.capacity() + empty_order.size()) *
                                                        sizeof(std::uint32_t) +
               tree.size() * sizeof(Value) * 14 / 10;
    }

private:
    void link(std::uint32_t id, std::uint32_t key) {
        Entry& e = entries[key];
        if (e.members == 0) --empty_count;
        next_member[id] = e.first;
        e.first = id;
        ++e.members;
        entry_of[id] = key;
        ++live_count;
    }
    void unlink(std::uint32_t id) {
        const std::uint32_t key = entry_of[id];
        Entry& e = entries[key];
        if (e.first == id) {
            e.first = next_member[id];
        } else {
            std::uint32_t before = e.first;
            while (next_member[before] != id) before = next_member[before];
            next_member[before] = next_member[id];
        }
        next_member[id] = none;
        entry_of[id] = none;
        --live_count;
        if (--e.members == 0) {
            ++empty_count;
            empty_order.push_back(key);
        }
        recent[recent_next] = key;
        recent_next = (recent_next + 1) % recent_size;
    }
};

}  // namespace sxk::detail

namespace sxk {

namespace detail {

// Where a locate without a hint starts walking: a uniform grid over the mesh's bounding box at
// build time, about one cell per `elements_per_cell` elements, each holding the element that
// contains the cell's centre (or, outside the mesh, one near the cell; later also the last
// answer the tree gave for a point of it). 0.75 elements per cell: with centre seeds, a locate
// at 1M tetrahedra visits 1.72 elements on average against 1.95 at 1.5 per cell and 2.36 with the
// centroid seeds of before, and each visit there is a cache miss (docs/performance.md "locate");
// the grid costs 4 bytes a cell. A seed that died, or whose id now names an element elsewhere,
// makes the short walk from it fail and the tree decide; the answer becomes the cell's seed.
// Why beside the rtree: its descent misses the cache at 1M elements (7 levels of nodes), the
// grid costs one load and a walk of a step or two. Seeds are atomics so that const queries from
// several threads may refresh them (relaxed: any live element is a correct start).
struct SeedGrid {
    static constexpr double elements_per_cell = 0.75;
    std::array<double, 3> low{}, cell{1, 1, 1};
    std::array<std::size_t, 3> cells{0, 0, 0};
    std::vector<std::atomic<std::uint32_t>> seeds;

    bool empty() const { return seeds.empty(); }
    // The cell of x, or npos outside the grid (or for non-finite x).
    std::size_t cell_of(const Point& x, int dimension) const {
        std::size_t index = 0;
        for (int k = dimension - 1; k >= 0; --k) {
            const auto uk = static_cast<std::size_t>(k);
            const double at = (x[uk] - low[uk]) / cell[uk];
            if (!(at >= 0) || !(at < static_cast<double>(cells[uk]))) return npos;
            index = index * cells[uk] + static_cast<std::size_t>(at);
        }
        return index;
    }
    // The centre of a cell (z = 0 on a planar grid, whose cells[2] is 0).
    Point centre(std::size_t index) const {
        Point x{0, 0, 0};
        for (std::size_t k = 0; k < 3 && cells[k] > 0; ++k) {
            x[k] = low[k] + (static_cast<double>(index % cells[k]) + 0.5) * cell[k];
            index /= cells[k];
        }
        return x;
    }
    static constexpr std::size_t npos = std::numeric_limits<std::size_t>::max();
};

}  // namespace detail

struct SpatialIndex::Trees {
    detail::BoxTree<2> elements2, faces2;  // planar meshes
    detail::BoxTree<3> elements3, faces3;  // surfaces in space, tetrahedral meshes
    detail::SeedGrid seeds;                // planar and tetrahedral meshes
};

namespace detail {

template <int D>
BoxTree<D>& element_tree(SpatialIndex::Trees& trees) {
    if constexpr (D == 2) return trees.elements2;
    else return trees.elements3;
}
template <int D>
const BoxTree<D>& element_tree(const SpatialIndex::Trees& trees) {
    if constexpr (D == 2) return trees.elements2;
    else return trees.elements3;
}
template <int D>
BoxTree<D>& face_tree(SpatialIndex::Trees& trees) {
    if constexpr (D == 2) return trees.faces2;
    else return trees.faces3;
}
template <int D>
const BoxTree<D>& face_tree(const SpatialIndex::Trees& trees) {
    if constexpr (D == 2) return trees.faces2;
    else return trees.faces3;
}

// Calls f(std::integral_constant<int, D>{}) for D the mesh's ambient dimension, the dimension of
// its trees.
template <class F>
decltype(auto) in_dimension(const Mesh& mesh, F&& f) {
    if (mesh.ambient_dimension() == 2) return f(std::integral_constant<int, 2>{});
    return f(std::integral_constant<int, 3>{});
}

// The positions of element t's vertices (canonical order), and of face f's.
struct ElementPoints {
    std::array<const Point*, 4> p{};
    int count = 0;
    std::span<const Point* const> span() const { return {p.data(), static_cast<std::size_t>(count)}; }
};
inline ElementPoints element_points(const Mesh& mesh, ElementId t, Positions positions) {
    const Simplex& s = mesh.simplex(t);
    ElementPoints e;
    e.count = s.count();
    for (int j = 0; j < s.count(); ++j) e.p[static_cast<std::size_t>(j)] = &position(mesh, s.vertex(j), positions);
    return e;
}
inline ElementPoints face_points(const Mesh& mesh, FaceId f, Positions positions) {
    const Simplex s = mesh.face_simplex(f);
    ElementPoints e;
    e.count = s.count();
    for (int j = 0; j < s.count(); ++j) e.p[static_cast<std::size_t>(j)] = &position(mesh, s.vertex(j), positions);
    return e;
}

// The extent of an element's or a face's positions (what a moved id is tested against), and the
// box the tree stores for it.
template <int D>
typename BoxTree<D>::Extent element_extent(const Mesh& mesh, ElementId t, Positions positions) {
    return BoxTree<D>::extent_of(element_points(mesh, t, positions).span());
}
template <int D>
typename BoxTree<D>::Extent face_extent(const Mesh& mesh, FaceId f, Positions positions) {
    return BoxTree<D>::extent_of(face_points(mesh, f, positions).span());
}
template <int D>
typename BoxTree<D>::Box element_box(const Mesh& mesh, ElementId t, Positions positions) {
    return BoxTree<D>::box_of(element_extent<D>(mesh, t, positions));
}
template <int D>
typename BoxTree<D>::Box face_box(const Mesh& mesh, FaceId f, Positions positions) {
    return BoxTree<D>::box_of(face_extent<D>(mesh, f, positions));
}

inline double distance_squared(const Point& a, const Point& b) {
    const double x = a[0] - b[0], y = a[1] - b[1], z = a[2] - b[2];
    return x * x + y * y + z * z;
}

// Sorted, without repeats.
template <class Id>
void sort_unique(std::vector<Id>& ids) {
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
}

}  // namespace detail
}  // namespace sxk
