// What a SpatialIndex must agree with: every query answered by testing every element (or
// boundary face) with the element-level tests of sxk/locate.hpp, and the comparison of the two.
// Shared by tests/core/locate_test.cpp and tests/ops/locate_random_test.cpp.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "sxk/locate.hpp"
#include "sxk/mesh.hpp"

namespace sxk::test {

inline bool is_surface(const Mesh& mesh) { return mesh.topological_dimension() < mesh.ambient_dimension(); }

// The elements containing x (surfaces: within `tolerance`), by id.
inline std::vector<ElementId> scan_containing(const Mesh& mesh, const Point& x, Positions positions, double tolerance) {
    std::vector<ElementId> found;
    for (const ElementId t : elements(mesh))
        if (locate_in_element(mesh, t, x, positions, tolerance).found()) found.push_back(t);
    return found;
}

inline std::vector<ElementId> scan_crossed(const Mesh& mesh, const Point& a, const Point& b, Positions positions) {
    std::vector<ElementId> found;
    for (const ElementId t : elements(mesh))
        if (segment_meets_element(mesh, t, a, b, positions)) found.push_back(t);
    return found;
}

inline TriangleHits scan_triangle(const Mesh& mesh, const Point& a, const Point& b, const Point& c,
                                  Positions positions) {
    TriangleHits hits;
    for (const ElementId t : elements(mesh))
        if (triangle_meets_element(mesh, t, a, b, c, positions)) hits.elements.push_back(t);
    for (const FaceId f : mesh.boundary_faces())
        if (triangle_meets_face(mesh, f, a, b, c, positions)) hits.boundary_faces.push_back(f);
    return hits;
}

inline double scan_nearest_distance(const Mesh& mesh, const Point& x, Positions positions) {
    double best = std::numeric_limits<double>::infinity();
    for (const FaceId f : mesh.boundary_faces()) best = std::min(best, nearest_point_on_face(mesh, f, x, positions).distance);
    return best;
}

inline double scan_pick_t(const Mesh& mesh, const Point& o, const Point& d, Positions positions) {
    double best = std::numeric_limits<double>::infinity();
    if (is_surface(mesh)) {
        for (const ElementId t : elements(mesh)) best = std::min(best, ray_meets_triangle_element(mesh, t, o, d, positions).t);
    } else {
        for (const FaceId f : mesh.boundary_faces()) best = std::min(best, ray_meets_face(mesh, f, o, d, positions).t);
    }
    return best;
}

// The position x the weights of a location give, in the index's positions.
inline Point point_of(const Mesh& mesh, const Location& location, Positions positions) {
    Point p{0, 0, 0};
    const Simplex& s = mesh.simplex(location.element);
    for (int j = 0; j < s.count(); ++j) {
        const Point& q = positions == Positions::reference ? mesh.reference(s.vertex(j)) : mesh.deformed(s.vertex(j));
        for (std::size_t k = 0; k < 3; ++k) p[k] += location.barycentric[static_cast<std::size_t>(j)] * q[k];
    }
    return p;
}

// The bounding box of the mesh in `positions`, grown by a tenth on each side.
struct Bounds {
    Point low{}, high{};
};
inline Bounds bounds_of(const Mesh& mesh, Positions positions) {
    Bounds b;
    for (std::size_t k = 0; k < 3; ++k) {
        b.low[k] = std::numeric_limits<double>::infinity();
        b.high[k] = -b.low[k];
    }
    for (VertexId v = 0; v < mesh.vertex_count(); ++v) {
        if (mesh.vertex_element(v) == invalid_id) continue;
        const Point& p = positions == Positions::reference ? mesh.reference(v) : mesh.deformed(v);
        for (std::size_t k = 0; k < 3; ++k) {
            b.low[k] = std::min(b.low[k], p[k]);
            b.high[k] = std::max(b.high[k], p[k]);
        }
    }
    for (std::size_t k = 0; k < 3; ++k) {
        const double margin = 0.1 * (b.high[k] - b.low[k]);
        b.low[k] -= margin;
        b.high[k] += margin;
    }
    return b;
}

// A query point: a random point of the grown box, a vertex, the midpoint of an element's edge
// (on a shared face where the mesh is a grid), or a random point of a random element.
inline Point random_query(const Mesh& mesh, Positions positions, std::mt19937_64& rng) {
    const Bounds b = bounds_of(mesh, positions);
    std::uniform_real_distribution<double> unit(0, 1);
    auto at = [&](VertexId v) { return positions == Positions::reference ? mesh.reference(v) : mesh.deformed(v); };
    const std::uint64_t kind = rng() % 4;
    if (kind > 0 && mesh.element_count() > 0) {
        ElementId t = static_cast<ElementId>(rng() % mesh.element_capacity());
        while (!mesh.is_element(t)) t = static_cast<ElementId>((t + 1) % mesh.element_capacity());
        const Simplex& s = mesh.simplex(t);
        if (kind == 1) return at(s.vertex(static_cast<int>(rng() % static_cast<std::uint64_t>(s.count()))));
        if (kind == 2) {
            const Point &p = at(s.vertex(0)), &q = at(s.vertex(1));
            return {0.5 * (p[0] + q[0]), 0.5 * (p[1] + q[1]), 0.5 * (p[2] + q[2])};
        }
        Point x{0, 0, 0};
        double total = 0;
        std::array<double, 4> w{};
        for (int j = 0; j < s.count(); ++j) total += w[static_cast<std::size_t>(j)] = unit(rng);
        for (int j = 0; j < s.count(); ++j)
            for (std::size_t k = 0; k < 3; ++k) x[k] += w[static_cast<std::size_t>(j)] / total * at(s.vertex(j))[k];
        return x;
    }
    Point x{};
    for (std::size_t k = 0; k < 3; ++k) x[k] = b.low[k] + unit(rng) * (b.high[k] - b.low[k]);
    if (mesh.ambient_dimension() == 2) x[2] = 0;
    return x;
}

// Every query of `index` against the scans, at `queries` random points and segments, triangles
// and rays made of them. `where` names the situation in failure messages.
inline void expect_index_agrees(const SpatialIndex& index, std::mt19937_64& rng, int queries, const std::string& where) {
    const Mesh& mesh = index.mesh();
    const Positions positions = index.positions();
    const double tolerance = index.surface_tolerance();
    ASSERT_TRUE(index.validate().ok()) << where << ": " << index.validate().reason();
    for (int q = 0; q < queries; ++q) {
        const Point x = random_query(mesh, positions, rng);
        const Point y = random_query(mesh, positions, rng);
        const Point z = random_query(mesh, positions, rng);
        SCOPED_TRACE(where + ", query " + std::to_string(q));
        // locate, with and without a hint
        const std::vector<ElementId> containing = scan_containing(mesh, x, positions, tolerance);
        ElementId hint = invalid_id;
        if (rng() % 2 == 0 && mesh.element_count() > 0) {
            hint = static_cast<ElementId>(rng() % mesh.element_capacity());
            while (!mesh.is_element(hint)) hint = static_cast<ElementId>((hint + 1) % mesh.element_capacity());
        }
        const Location found = index.locate(x, hint);
        EXPECT_EQ(found.found(), !containing.empty()) << "locate(" << x[0] << ", " << x[1] << ", " << x[2] << ")";
        if (found.found()) {
            EXPECT_TRUE(std::binary_search(containing.begin(), containing.end(), found.element))
                << "locate gave element " << found.element << ", which does not contain the point";
            const Point back = point_of(mesh, found, positions);
            if (!is_surface(mesh)) {
                for (int k = 0; k < mesh.ambient_dimension(); ++k)
                    EXPECT_NEAR(back[static_cast<std::size_t>(k)], x[static_cast<std::size_t>(k)], 1e-9)
                        << "element " << found.element << " " << to_text(mesh.simplex(found.element)) << " weights "
                        << found.barycentric[0] << " " << found.barycentric[1] << " " << found.barycentric[2] << " "
                        << found.barycentric[3] << " hint " << hint << " positions " << int(positions);
            }
        }
        // segments, triangles, nearest boundary points, rays
        EXPECT_EQ(index.elements_crossed(x, y), scan_crossed(mesh, x, y, positions));
        EXPECT_EQ(index.elements_crossed(x, x), scan_crossed(mesh, x, x, positions));
        const TriangleHits hits = index.elements_hit_by_triangle(x, y, z);
        const TriangleHits scanned = scan_triangle(mesh, x, y, z, positions);
        EXPECT_EQ(hits.elements, scanned.elements);
        std::vector<FaceId> faces = scanned.boundary_faces;
        std::sort(faces.begin(), faces.end());
        EXPECT_EQ(hits.boundary_faces, faces);
        const TriangleHits elements_only = index.elements_hit_by_triangle(x, y, z, TriangleHitsOf::elements);
        EXPECT_EQ(elements_only.elements, scanned.elements);
        EXPECT_TRUE(elements_only.boundary_faces.empty());
        const TriangleHits faces_only = index.elements_hit_by_triangle(x, y, z, TriangleHitsOf::boundary_faces);
        EXPECT_TRUE(faces_only.elements.empty());
        EXPECT_EQ(faces_only.boundary_faces, faces);
        // the box spanned by x and y, against every element's vertices
        Point low{}, high{};
        for (std::size_t k = 0; k < 3; ++k) {
            low[k] = std::min(x[k], y[k]);
            high[k] = std::max(x[k], y[k]);
        }
        std::vector<ElementId> in_box;
        for (const ElementId t : elements(mesh))
            for (const VertexId v : mesh.simplex(t).vertices()) {
                const Point& p = positions == Positions::reference ? mesh.reference(v) : mesh.deformed(v);
                bool inside = true;
                for (int k = 0; k < mesh.ambient_dimension(); ++k)
                    inside = inside && p[static_cast<std::size_t>(k)] >= low[static_cast<std::size_t>(k)] &&
                             p[static_cast<std::size_t>(k)] <= high[static_cast<std::size_t>(k)];
                if (inside) {
                    in_box.push_back(t);
                    break;
                }
            }
        EXPECT_EQ(index.elements_with_vertex_in_box(low, high), in_box);
        const BoundaryPoint nearest = index.nearest_boundary_point(x);
        const double scanned_distance = scan_nearest_distance(mesh, x, positions);
        EXPECT_EQ(nearest.found(), scanned_distance < std::numeric_limits<double>::infinity());
        if (nearest.found()) {
            EXPECT_EQ(nearest.distance, scanned_distance);
        }
        const Point direction{y[0] - x[0], y[1] - x[1], mesh.ambient_dimension() == 2 ? 0 : y[2] - x[2]};
        if (direction != Point{0, 0, 0}) {
            const RayHit hit = index.pick(x, direction);
            const double t = scan_pick_t(mesh, x, direction, positions);
            EXPECT_EQ(hit.found(), t < std::numeric_limits<double>::infinity());
            if (hit.found()) {
                EXPECT_EQ(hit.t, t) << std::setprecision(17) << "pick from (" << x[0] << ", " << x[1] << ", " << x[2]
                                    << ") along (" << direction[0] << ", " << direction[1] << ", " << direction[2]
                                    << "): element " << hit.element;
            }
        }
    }
}

}  // namespace sxk::test
