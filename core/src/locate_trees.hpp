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

// The next float below (above) x, at least one unit in the last place away.
inline float float_below(double x) {
    float f = static_cast<float>(x);
    if (static_cast<double>(f) > x) f = std::nextafter(f, -std::numeric_limits<float>::infinity());
    return std::nextafter(f, -std::numeric_limits<float>::infinity());
}
inline float float_above(double x) {
    float f = static_cast<float>(x);
    if (static_cast<double>(f) < x) f = std::nextafter(f, std::numeric_limits<float>::infinity());
    return std::nextafter(f, std::numeric_limits<float>::infinity());
}

// One rtree of boxes keyed by a 32-bit id (element or face), with the box each id was inserted
// with (bgi::rtree::remove finds a value by its box). Single-precision boxes: the tree's nodes
// are half the size, and the walk through them is memory-bound at 1M elements
// (docs/performance.md "locate"). quadratic<8>: of linear/quadratic/rstar at 8-32 entries,
// the fastest insertion and point query on a 1M-tetrahedron Kuhn cube (R* inserts 3-5x slower).
template <int D>
struct BoxTree {
    using Coordinates = bg::model::point<float, D, bg::cs::cartesian>;
    using QueryPoint = bg::model::point<double, D, bg::cs::cartesian>;
    using Box = bg::model::box<Coordinates>;
    using Value = std::pair<Box, std::uint32_t>;
    using Tree = bgi::rtree<Value, bgi::quadratic<8>>;

    Tree tree;
    std::vector<Box> boxes;             // by id
    std::vector<std::uint8_t> indexed;  // by id: 1 when in the tree

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

    void clear() {
        tree.clear();
        boxes.clear();
        indexed.clear();
    }
    void grow(std::uint32_t id) {
        if (id >= boxes.size()) {
            boxes.resize(static_cast<std::size_t>(id) + 1);
            indexed.resize(static_cast<std::size_t>(id) + 1, 0);
        }
    }
    bool contains(std::uint32_t id) const { return id < indexed.size() && indexed[id] != 0; }
    void insert(std::uint32_t id, const Box& box) {
        erase(id);  // never two boxes for one id
        grow(id);
        boxes[id] = box;
        indexed[id] = 1;
        tree.insert(Value(box, id));
    }
    void erase(std::uint32_t id) {
        if (!contains(id)) return;
        tree.remove(Value(boxes[id], id));
        indexed[id] = 0;
    }
    // Re-boxes id when its box changed (moves that keep a box cost no tree work).
    void update(std::uint32_t id, const Box& box) {
        if (contains(id) && bg::equals(boxes[id], box)) return;
        erase(id);
        insert(id, box);
    }
    // Replaces the whole tree by a bulk load (the packing constructor: O(n log n), better nodes
    // than n insertions).
    void load(std::vector<Value>& values) {
        clear();
        for (const Value& v : values) {
            grow(v.second);
            boxes[v.second] = v.first;
            indexed[v.second] = 1;
        }
        tree = Tree(values.begin(), values.end());
    }
    std::size_t memory_bytes() const {
        // the tree's nodes hold the values plus about 40% slack at a fill of 8/(8*0.7)
        return boxes.capacity() * sizeof(Box) + indexed.capacity() + tree.size() * sizeof(Value) * 14 / 10;
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
