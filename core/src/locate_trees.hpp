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

#include <algorithm>
#include <array>
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

// Where the index reads positions.
inline const Point& position(const Mesh& mesh, VertexId v, Positions positions) {
    return positions == Positions::reference ? mesh.reference(v) : mesh.deformed(v);
}

// The next float below (above) x, at least one unit in the last place away (a double beyond
// the floats' range, which a cast may not take, gives the largest float or infinity).
inline float float_below(double x) {
    constexpr double largest = std::numeric_limits<float>::max();
    if (!(x <= largest)) return std::numeric_limits<float>::max();
    if (x < -largest) return -std::numeric_limits<float>::infinity();
    float f = static_cast<float>(x);
    if (static_cast<double>(f) > x) f = std::nextafter(f, -std::numeric_limits<float>::infinity());
    return std::nextafter(f, -std::numeric_limits<float>::infinity());
}
inline float float_above(double x) {
    constexpr double largest = std::numeric_limits<float>::max();
    if (!(x >= -largest)) return -std::numeric_limits<float>::max();
    if (x > largest) return std::numeric_limits<float>::infinity();
    float f = static_cast<float>(x);
    if (static_cast<double>(f) < x) f = std::nextafter(f, std::numeric_limits<float>::infinity());
    return std::nextafter(f, std::numeric_limits<float>::infinity());
}

// One rtree of boxes keyed by a 32-bit id (element or face), with the box each id was inserted
// with (bgi::rtree::remove finds a value by its box). Single-precision boxes: the tree's nodes
// are half the size, and the walk through them is memory-bound at 1M elements
// (docs/performance.md "locate"). quadratic<8>: of linear/quadratic/rstar at 8-32 entries,
// the fastest insertion and point query on a 1M-tetrahedron Kuhn cube (R* inserts 3-5x slower).
//
// Boxes are conservative: an entry's box contains its element's, and may be larger. An edit
// frees ids and hands them out again at once (the pools' free lists), and a tree operation costs
// ~1.5 us at 1M entries against ~3 us for a whole flip (docs/performance.md "locate"), so:
//   * a removed id is RETIRED: its entry stays in the tree, skipped by every query;
//   * an id added again keeps its entry when the entry's box holds the new box and is not more
//     than `slack_factor` times wider along any axis (a flipped diagonal, a split child in
//     its parent's id, a move within the box): no tree operation at all;
//   * retired entries are removed for good, oldest first and at most two per removal event, once
//     there are more than 64 + live/64 of them (no stall: removing them all at once could mean
//     125k removals of ~1.5 us each at 1M).
template <int D>
struct BoxTree {
    using Coordinates = bg::model::point<float, D, bg::cs::cartesian>;
    using QueryPoint = bg::model::point<double, D, bg::cs::cartesian>;
    using Box = bg::model::box<Coordinates>;
    using Value = std::pair<Box, std::uint32_t>;
    using Tree = bgi::rtree<Value, bgi::quadratic<8>>;
    enum State : std::uint8_t { absent = 0, live = 1, retired = 2 };
    static constexpr float slack_factor = 4;

    Tree tree;
    std::vector<Box> boxes;     // by id: the box of its entry in the tree
    std::vector<State> states;  // by id
    std::size_t live_count = 0, retired_count = 0;
    std::deque<std::uint32_t> retired_order;  // ids as they were retired (revived ones too)

    static Box box_of(std::span<const Point* const> points) {
        Box box;
        for (int k = 0; k < D; ++k) {
            double lo = std::numeric_limits<double>::infinity(), hi = -lo;
            for (const Point* p : points) {
                lo = std::min(lo, (*p)[static_cast<std::size_t>(k)]);
                hi = std::max(hi, (*p)[static_cast<std::size_t>(k)]);
            }
            // grown by about a millionth of the box's size and distance from the origin: Boost's
            // segment and distance tests on float boxes compute in double precision with rounding,
            // and a segment through a corner of an element at a coordinate 0 (a float unit of
            // 1e-45 there) was missed without it (tests/core/locate_test.cpp found it)
            const double pad = (hi - lo + std::max(std::abs(lo), std::abs(hi))) * 0x1p-20;
            set_corner(box.min_corner(), k, float_below(lo - pad));
            set_corner(box.max_corner(), k, float_above(hi + pad));
        }
        return box;
    }
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
        boxes.clear();
        states.clear();
        retired_order.clear();
        live_count = retired_count = 0;
    }
    void grow(std::uint32_t id) {
        if (id >= boxes.size()) {
            boxes.resize(static_cast<std::size_t>(id) + 1);
            states.resize(static_cast<std::size_t>(id) + 1, absent);
        }
    }
    bool is_live(std::uint32_t id) const { return id < states.size() && states[id] == live; }
    // id (added, changed or moved) now has the tight box `box`.
    void insert(std::uint32_t id, const Box& box) {
        grow(id);
        if (states[id] != absent && holds(boxes[id], box)) {
            if (states[id] == retired) {
                --retired_count;
                ++live_count;
            }
            states[id] = live;
            return;
        }
        if (states[id] != absent) {
            tree.remove(Value(boxes[id], id));
            (states[id] == live ? live_count : retired_count) -= 1;
        }
        boxes[id] = box;
        states[id] = live;
        ++live_count;
        tree.insert(Value(box, id));
    }
    void erase(std::uint32_t id) {
        if (!is_live(id)) return;
        states[id] = retired;
        --live_count;
        ++retired_count;
        retired_order.push_back(id);
        trim(2);
    }
    void update(std::uint32_t id, const Box& box) { insert(id, box); }
    // Removes up to `budget` of the oldest retired entries from the tree while there are more
    // than 64 + live/64; keeps the queue of retired ids within a few times their number.
    void trim(int budget) {
        const std::size_t limit = 64 + live_count / 64;
        while (retired_count > limit && budget > 0 && !retired_order.empty()) {
            const std::uint32_t id = retired_order.front();
            retired_order.pop_front();
            if (id >= states.size() || states[id] != retired) continue;  // revived since
            tree.remove(Value(boxes[id], id));
            states[id] = absent;
            --retired_count;
            --budget;
        }
        if (retired_order.size() > 4 * (retired_count + 64)) {
            std::deque<std::uint32_t> still;
            for (const std::uint32_t id : retired_order)
                if (id < states.size() && states[id] == retired) still.push_back(id);
            retired_order.swap(still);
        }
    }
    // Replaces the whole tree by a bulk load (the packing constructor: O(n log n), better nodes
    // than n insertions).
    void load(std::vector<Value>& values) {
        clear();
        for (const Value& v : values) {
            grow(v.second);
            boxes[v.second] = v.first;
            states[v.second] = live;
        }
        live_count = values.size();
        tree = Tree(values.begin(), values.end());
    }
    std::size_t memory_bytes() const {
        // the tree's nodes hold the values plus about 40% slack at a fill of 8/(8*0.7)
        return boxes.capacity() * sizeof(Box) + states.capacity() + retired_order.size() * sizeof(std::uint32_t) +
               tree.size() * sizeof(Value) * 14 / 10;
    }
};

}  // namespace sxk::detail

namespace sxk {

struct SpatialIndex::Trees {
    detail::BoxTree<2> elements2, faces2;  // planar meshes
    detail::BoxTree<3> elements3, faces3;  // surfaces in space, tetrahedral meshes
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

template <int D>
typename BoxTree<D>::Box element_box(const Mesh& mesh, ElementId t, Positions positions) {
    return BoxTree<D>::box_of(element_points(mesh, t, positions).span());
}
template <int D>
typename BoxTree<D>::Box face_box(const Mesh& mesh, FaceId f, Positions positions) {
    return BoxTree<D>::box_of(face_points(mesh, f, positions).span());
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
