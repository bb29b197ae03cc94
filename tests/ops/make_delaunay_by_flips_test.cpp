// Tests of Lawson's flip algorithm (sxk/ops/make_delaunay_by_flips.hpp), with CGAL's
// Delaunay_triangulation_2 as the peer oracle.
//
//            3                      3          kite 0 1 2 3: vertex 3 lies inside the circle
//          /   \                  / | \        through 0, 1, 2, so the long diagonal 0-2 is
//     0 --------- 2    ---->    0   |   2      illegal and one flip makes it 1-3
//          \   /                  \ | /
//            1                      1
#include "sxk/ops/make_delaunay_by_flips.hpp"
#include "sxk/ops/flip_edge.hpp"

#include <gtest/gtest.h>

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <numeric>
#include <random>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "core/fixtures.hpp"
#include "sxk/predicates.hpp"

namespace sxk {
namespace {

using Edge = std::pair<VertexId, VertexId>;

FaceId find_edge(const Mesh& mesh, VertexId u, VertexId v) {
    const Simplex wanted(+1, {u, v});
    for (ElementId t : elements(mesh))
        for (FaceId f : mesh.faces(t))
            if (mesh.face_simplex(f).same_vertices(wanted)) return f;
    return invalid_id;
}

std::set<Edge> edge_set(const Mesh& mesh) {
    std::set<Edge> edges;
    for (ElementId t : elements(mesh))
        for (FaceId f : mesh.faces(t)) {
            const Simplex s = mesh.face_simplex(f);
            edges.insert({s.vertex(0), s.vertex(1)});
        }
    return edges;
}

Mesh kite() {
    Mesh mesh(2, 2);
    mesh.add_vertex({0, 0, 0});
    mesh.add_vertex({1, -0.3, 0});
    mesh.add_vertex({2, 0, 0});
    mesh.add_vertex({1, 0.3, 0});
    const std::array<Simplex, 2> triangles{Simplex(+1, {0, 1, 2}), Simplex(+1, {0, 2, 3})};
    EXPECT_TRUE(mesh.assign_elements(triangles).ok());
    return mesh;
}

// A valid, far from Delaunay, initial triangulation: sweep the points by x and connect each new
// point to the hull edges it sees (the lower and upper chains of Andrew's monotone chain). Every
// triangle is counter-clockwise by construction.
Mesh sweep_triangulation(const std::vector<Point>& points) {
    std::vector<VertexId> order(points.size());
    std::iota(order.begin(), order.end(), VertexId{0});
    std::sort(order.begin(), order.end(), [&](VertexId u, VertexId v) {
        return std::pair(points[u][0], points[u][1]) < std::pair(points[v][0], points[v][1]);
    });
    std::vector<Simplex> triangles;
    std::vector<VertexId> lower, upper;
    for (VertexId p : order) {
        // p below the lower-hull edge u->v (left to right): <u,p,v> is counter-clockwise
        while (lower.size() >= 2 &&
               orient2d(points[lower[lower.size() - 2]], points[lower.back()], points[p]) == Sign::negative) {
            triangles.emplace_back(+1, std::initializer_list<VertexId>{lower[lower.size() - 2], p, lower.back()});
            lower.pop_back();
        }
        // p above the upper-hull edge u->v: <u,v,p> is counter-clockwise
        while (upper.size() >= 2 &&
               orient2d(points[upper[upper.size() - 2]], points[upper.back()], points[p]) == Sign::positive) {
            triangles.emplace_back(+1, std::initializer_list<VertexId>{upper[upper.size() - 2], upper.back(), p});
            upper.pop_back();
        }
        lower.push_back(p);
        upper.push_back(p);
    }
    Mesh mesh(2, 2);
    for (const Point& p : points) mesh.add_vertex(p);
    EXPECT_TRUE(mesh.assign_elements(triangles).ok());
    return mesh;
}

std::set<Edge> cgal_delaunay_edges(const std::vector<Point>& points) {
    using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
    using VertexBase = CGAL::Triangulation_vertex_base_with_info_2<VertexId, Kernel>;
    using Tds = CGAL::Triangulation_data_structure_2<VertexBase>;
    using Delaunay = CGAL::Delaunay_triangulation_2<Kernel, Tds>;
    std::vector<std::pair<Kernel::Point_2, VertexId>> input;
    for (VertexId v = 0; v < points.size(); ++v) input.emplace_back(Kernel::Point_2(points[v][0], points[v][1]), v);
    const Delaunay delaunay(input.begin(), input.end());
    std::set<Edge> edges;
    for (auto e = delaunay.finite_edges_begin(); e != delaunay.finite_edges_end(); ++e) {
        const VertexId u = e->first->vertex(Delaunay::cw(e->second))->info();
        const VertexId v = e->first->vertex(Delaunay::ccw(e->second))->info();
        edges.insert({std::min(u, v), std::max(u, v)});
    }
    return edges;
}

TEST(MakeDelaunayByFlips, FlipsKiteDiagonal) {
    Mesh mesh = kite();
    EXPECT_FALSE(is_locally_delaunay(mesh, find_edge(mesh, 0, 2)));
    auto flips = make_delaunay_by_flips(mesh);
    ASSERT_TRUE(flips.ok()) << flips.reason();
    EXPECT_EQ(*flips, 1u);
    EXPECT_EQ(edge_set(mesh), (std::set<Edge>{{0, 1}, {1, 2}, {2, 3}, {0, 3}, {1, 3}}));
    EXPECT_TRUE(is_locally_delaunay(mesh, find_edge(mesh, 1, 3)));
    ASSERT_TRUE(mesh.validate().ok());
}

// The kite's flip is wanted in the reference positions, but in the deformed ones vertex 1 has
// moved right past vertex 2, so the new triangle <1,2,3> would be clockwise there: the edge stays
// (EditJournalRandom.PlanarRandomPoints, SXK_SEED=2911892313, step 1252, made such a flip).
TEST(MakeDelaunayByFlips, NeverInvertsATriangleInTheOtherPositions) {
    Mesh mesh = kite();
    mesh.set_deformed(1, {2.5, -0.1, 0});
    ASSERT_EQ(orient2d(mesh.deformed(0), mesh.deformed(1), mesh.deformed(2)), Sign::positive);
    ASSERT_EQ(orient2d(mesh.deformed(1), mesh.deformed(2), mesh.deformed(3)), Sign::negative);
    const Mesh copy = mesh;
    EXPECT_FALSE(is_locally_delaunay(mesh, find_edge(mesh, 0, 2), Positions::reference));
    auto flips = make_delaunay_by_flips(mesh, Positions::reference);
    ASSERT_TRUE(flips.ok()) << flips.reason();
    EXPECT_EQ(*flips, 0u);
    test::expect_same_state(mesh, copy);
    for (ElementId t : elements(mesh)) {
        EXPECT_EQ(element_orientation(mesh, t, Positions::reference), Sign::positive);
        EXPECT_EQ(element_orientation(mesh, t, Positions::deformed), Sign::positive);
    }
    ASSERT_TRUE(mesh.validate().ok());
}

TEST(MakeDelaunayByFlips, TerminatesOnCocircularGrid) {
    // every grid square is cocircular: no edge is strictly illegal, nothing is flipped
    Mesh mesh = test::planar_grid(6);
    const Mesh copy = mesh;
    auto flips = make_delaunay_by_flips(mesh);
    ASSERT_TRUE(flips.ok()) << flips.reason();
    EXPECT_EQ(*flips, 0u);
    test::expect_same_state(mesh, copy);
    ASSERT_TRUE(mesh.validate().ok());
}

TEST(MakeDelaunayByFlips, RefusesSurfaceMesh) {
    Mesh mesh(2, 3);
    mesh.add_vertex({0, 0, 0});
    mesh.add_vertex({1, 0, 0});
    mesh.add_vertex({0, 1, 1});
    const std::array<Simplex, 1> triangle{Simplex(+1, {0, 1, 2})};
    ASSERT_TRUE(mesh.assign_elements(triangle).ok());
    const Mesh copy = mesh;
    auto flips = make_delaunay_by_flips(mesh);
    ASSERT_FALSE(flips.ok());
    EXPECT_EQ(flips.reason(),
              "make_delaunay_by_flips: needs a planar triangle mesh (topological and ambient dimension 2)");
    EXPECT_EQ(flips.code(), RefusalCode::wrong_dimension);
    test::expect_same_state(mesh, copy);
    ASSERT_TRUE(mesh.validate().ok());
}

// On a surface in space the two triangles of an edge are unfolded about it (thesis §5.3.1): a kite
// folded along its long diagonal 0-2 keeps that diagonal illegal, however far it is folded; after
// the flip the short diagonal 1-3 is legal.
TEST(MakeDelaunayByFlips, UnfoldsTheTrianglesOfAnEdgeOnASurface) {
    for (const double fold : {0.0, 1.0, 3.0}) {
        Mesh mesh(2, 3);
        mesh.add_vertex({0, 0, 0});        // 0
        mesh.add_vertex({2, -0.6, 0});     // 1: below the diagonal 0-2
        mesh.add_vertex({4, 0, 0});        // 2
        mesh.add_vertex({2, 0.6, fold});   // 3: above it, folded up by `fold`
        // the angle at 1 opposite 0-2 is 147 degrees, at 3 from 147 (flat) down to 66 (fold 3): the
        // two sum to more than 180 in every fold
        const std::array<Simplex, 2> triangles{Simplex(+1, {0, 1, 2}), Simplex(+1, {0, 2, 3})};
        ASSERT_TRUE(mesh.assign_elements(triangles).ok());
        FaceId diagonal = invalid_id;
        for (const FaceId f : mesh.faces(ElementId{0}))
            if (mesh.mate(f) != invalid_id) diagonal = f;
        ASSERT_NE(diagonal, invalid_id);
        EXPECT_FALSE(is_locally_delaunay(mesh, diagonal)) << "fold " << fold;
        auto flipped = flip_edge(mesh, diagonal);
        ASSERT_TRUE(flipped.ok()) << flipped.reason();
        for (const FaceId f : mesh.faces((*flipped)[0])) {
            if (mesh.mate(f) == invalid_id) continue;
            EXPECT_TRUE(is_locally_delaunay(mesh, f)) << "fold " << fold;
        }
        ASSERT_TRUE(mesh.validate().ok());
    }
}

TEST(MakeDelaunayByFlips, RefusesClockwiseTriangle) {
    Mesh mesh = kite();
    mesh.set_deformed(3, {1, -0.1, 0});  // <0,2,3> turns clockwise
    const Mesh copy = mesh;
    auto flips = make_delaunay_by_flips(mesh);
    ASSERT_FALSE(flips.ok());
    const ElementId clockwise = mesh.face_element(find_edge(mesh, 2, 3));
    EXPECT_EQ(flips.reason(), "make_delaunay_by_flips: element " + std::to_string(clockwise) +
                                  " is not counter-clockwise in the deformed positions");
    EXPECT_EQ(flips.code(), RefusalCode::not_applicable);
    test::expect_same_state(mesh, copy);
    ASSERT_TRUE(mesh.validate().ok());
}

class MakeDelaunayByFlipsRandom : public ::testing::TestWithParam<std::size_t> {};

TEST_P(MakeDelaunayByFlipsRandom, MatchesCgalDelaunayTriangulation) {
    const std::size_t count = GetParam();
    const std::uint64_t seed = 0x5eed0000u + count;
    std::printf("make_delaunay_by_flips peer check: %zu points, seed %llu\n", count,
                static_cast<unsigned long long>(seed));
    std::mt19937_64 random(seed);
    std::uniform_real_distribution<double> coordinate(0.0, 1.0);
    std::vector<Point> points(count);
    for (Point& p : points) p = {coordinate(random), coordinate(random), 0.0};

    Mesh mesh = sweep_triangulation(points);
    ASSERT_TRUE(mesh.validate().ok());
    ASSERT_EQ(mesh.vertex_count(), count);
    const std::set<Edge> expected = cgal_delaunay_edges(points);
    ASSERT_NE(edge_set(mesh), expected) << "the sweep should not already be Delaunay";

    auto flips = make_delaunay_by_flips(mesh);
    ASSERT_TRUE(flips.ok()) << flips.reason();
    EXPECT_GT(*flips, 0u);
    EXPECT_EQ(edge_set(mesh), expected);
    for (ElementId t : elements(mesh)) {
        EXPECT_EQ(element_orientation(mesh, t), Sign::positive) << "element " << t;
        for (FaceId f : mesh.faces(t)) EXPECT_TRUE(is_locally_delaunay(mesh, f));
    }
    ASSERT_TRUE(mesh.validate().ok());
}

INSTANTIATE_TEST_SUITE_P(PointCounts, MakeDelaunayByFlipsRandom, ::testing::Values(200u, 2000u));

}  // namespace
}  // namespace sxk
