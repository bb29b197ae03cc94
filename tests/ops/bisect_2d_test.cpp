// 2D bisection of thesis §6.5: simple_bisect, bisect_edge (Fig. 6.7), refine_around (Fig. 6.8).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <random>
#include <set>

#include "ops/split_collapse_fixtures.hpp"
#include "sxk/ops/bisect_edge.hpp"
#include "sxk/ops/refine_around.hpp"
#include "sxk/ops/simple_bisect.hpp"
#include "sxk/predicates.hpp"

namespace sxk {
namespace {

using test::expect_same_state;

double distance(const Point& p, const Point& q) {
    return std::hypot(p[0] - q[0], p[1] - q[1]);
}

// The sorted angles of t in thousandths of a degree: the shape up to similarity.
std::array<long, 3> angle_class(const Mesh& mesh, ElementId t) {
    const Simplex& s = mesh.simplex(t);
    std::array<long, 3> angles{};
    for (int i = 0; i < 3; ++i) {
        const Point& a = mesh.reference(s.vertex(i));
        const Point& b = mesh.reference(s.vertex((i + 1) % 3));
        const Point& c = mesh.reference(s.vertex((i + 2) % 3));
        const double dot = (b[0] - a[0]) * (c[0] - a[0]) + (b[1] - a[1]) * (c[1] - a[1]);
        const double angle = std::acos(dot / (distance(a, b) * distance(a, c))) * 180 / M_PI;
        angles[static_cast<std::size_t>(i)] = std::lround(angle * 1000);
    }
    std::sort(angles.begin(), angles.end());
    return angles;
}

std::set<std::array<long, 3>> angle_classes(const Mesh& mesh) {
    std::set<std::array<long, 3>> classes;
    for (ElementId t : elements(mesh))
        classes.insert(angle_class(mesh, t));
    return classes;
}

double boundary_length(const Mesh& mesh) {
    double length = 0;
    mesh.for_each_boundary_face([&](FaceId f) {
        const Simplex edge = mesh.face_simplex(f);
        length += distance(mesh.reference(edge.vertex(0)), mesh.reference(edge.vertex(1)));
    });
    return length;
}

double area(const Mesh& mesh) {
    double total = 0;
    for (ElementId t : elements(mesh)) {
        const Simplex& s = mesh.simplex(t);
        const Point& a = mesh.reference(s.vertex(0));
        const Point& b = mesh.reference(s.vertex(1));
        const Point& c = mesh.reference(s.vertex(2));
        total += s.sign() * 0.5 * ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]));
    }
    return total;
}

// Longest edge of t, as a length.
double longest_edge(const Mesh& mesh, ElementId t) {
    const Simplex& s = mesh.simplex(t);
    double longest = 0;
    for (int i = 0; i < 3; ++i)
        longest = std::max(
            longest, distance(mesh.reference(s.vertex(i)), mesh.reference(s.vertex((i + 1) % 3))));
    return longest;
}

bool contains(const Mesh& mesh, ElementId t, const Point& x) {
    const Simplex& s = mesh.simplex(t);
    for (int i = 0; i < 3; ++i) {
        std::array<Point, 3> p{mesh.reference(s.vertex(0)), mesh.reference(s.vertex(1)),
                               mesh.reference(s.vertex(2))};
        p[static_cast<std::size_t>(i)] = x;
        if (static_cast<int>(orient2d(p[0], p[1], p[2])) * s.sign() < 0)
            return false;
    }
    return true;
}

const std::array<long, 3> right_isosceles{45000, 45000, 90000};

// planar_grid cuts each unit square along its south-west/north-east diagonal: every triangle
// is right-angled and isosceles, the diagonal is its hypotenuse.
TEST(Bisect2d, PlanarGridIsRightIsosceles) {
    const Mesh mesh = test::planar_grid(3);
    EXPECT_EQ(angle_classes(mesh), (std::set<std::array<long, 3>>{right_isosceles}));
}

//   2 ------- 3            2 ------- 3
//   |       / |            | \     / |     the hypotenuse 0-3 of both triangles gets
//   |     /   |    --->    |   \ /   |     n = 4 at (1/2, 1/2); four right isosceles halves
//   |   /     |            |   / \   |
//   | /       |            | /     \ |
//   0 ------- 1            0 ------- 1
TEST(Bisect2d, SimpleBisectOfTheHypotenuse) {
    Mesh mesh = test::planar_grid(1);
    mesh.set_label(0, 4);
    const auto split = simple_bisect(mesh, 3, 0);
    ASSERT_TRUE(split.ok()) << split.reason();
    ASSERT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
    EXPECT_EQ(split->vertex, 4u);
    EXPECT_EQ(mesh.reference(4), (Point{0.5, 0.5, 0}));
    EXPECT_EQ(mesh.element_count(), 4u);
    EXPECT_EQ(angle_classes(mesh), (std::set<std::array<long, 3>>{right_isosceles}));
    for (ElementId t : split->elements)
        EXPECT_EQ(mesh.label(t), mesh.simplex(t).contains(1) ? 4 : 0);
    EXPECT_TRUE(test::all_strictly_positive(mesh));
}

void expect_simple_bisect_refused(Mesh& mesh, VertexId p, VertexId q, RefusalCode code,
                          const std::string& reason) {
    const Mesh before = mesh;
    const auto split = simple_bisect(mesh, p, q);
    ASSERT_FALSE(split.ok());
    EXPECT_EQ(split.reason(), reason);
    EXPECT_EQ(split.code(), code);
    expect_same_state(mesh, before);
}

TEST(Bisect2d, SimpleBisectRefusals) {
    Mesh mesh = test::planar_grid(1);
    expect_simple_bisect_refused(
        mesh, 0, 1, RefusalCode::not_applicable,
        "simple_bisect: +<0,1> is not the hypotenuse of element 0 (its hypotenuse is +<0,3>)");
    expect_simple_bisect_refused(mesh, 1, 2, RefusalCode::not_found,
                                 "simple_bisect: +<1,2> is not an edge");
    expect_simple_bisect_refused(mesh, 0, 9, RefusalCode::not_found,
                                 "simple_bisect: 9 is not a vertex");
    expect_simple_bisect_refused(mesh, 2, 2, RefusalCode::bad_argument,
                                 "simple_bisect: the two ends are the same vertex");
    Mesh cube = test::kuhn_cube(1);
    expect_simple_bisect_refused(cube, 0, 7, RefusalCode::wrong_dimension,
                                 "simple_bisect: needs a triangle mesh (topological dimension 2)");
}

// Thesis Fig. 6.7 on planar_grid(2): the vertical edge 1-4 is a leg of both its triangles, so
// their hypotenuses 0-4 and 1-5 are bisected first, then 1-4 itself.
//
//   6 ----- 7 ----- 8         6 ----- 7 ----- 8
//   |     / |     / |         |     / |     / |
//   |   /   |   /   |         |   /   |   /   |
//   3 ----- 4 ----- 5   --->  3 ----- 4 ----- 5
//   |     / |     / |         | \   / | \   / |
//   |   /   |   /   |         |  x -- m -- y  |     x, y first (the neighbours'
//   0 ----- 1 ----- 2         | /   \ | /   \ |     hypotenuses), then m on 1-4
//                             0 ----- 1 ----- 2
TEST(Bisect2d, BisectEdgeBisectsTheNeighboursFirst) {
    Mesh mesh = test::planar_grid(2);
    const auto bisected = bisect_edge(mesh, 4, 1);
    ASSERT_TRUE(bisected.ok()) << bisected.reason();
    ASSERT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
    ASSERT_EQ(bisected->vertices, (std::vector<VertexId>{9, 10, 11}));
    EXPECT_EQ(bisected->midpoint, 11u);
    EXPECT_EQ(mesh.reference(11), (Point{1, 0.5, 0}));
    const std::set<Point> first{mesh.reference(9), mesh.reference(10)};
    EXPECT_EQ(first, (std::set<Point>{{0.5, 0.5, 0}, {1.5, 0.5, 0}}));
    EXPECT_EQ(mesh.element_count(), 14u);
    EXPECT_EQ(angle_classes(mesh), (std::set<std::array<long, 3>>{right_isosceles}));
    EXPECT_DOUBLE_EQ(boundary_length(mesh), 8.0);
    EXPECT_TRUE(test::all_strictly_positive(mesh));
}

// A boundary leg: only its one triangle's hypotenuse goes first.
TEST(Bisect2d, BisectEdgeOnTheBoundary) {
    Mesh mesh = test::planar_grid(2);
    const auto bisected = bisect_edge(mesh, 0, 1);
    ASSERT_TRUE(bisected.ok()) << bisected.reason();
    ASSERT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
    ASSERT_EQ(bisected->vertices, (std::vector<VertexId>{9, 10}));
    EXPECT_EQ(mesh.reference(9), (Point{0.5, 0.5, 0}));
    EXPECT_EQ(mesh.reference(10), (Point{0.5, 0, 0}));
    EXPECT_EQ(mesh.element_count(), 11u);
    EXPECT_EQ(angle_classes(mesh), (std::set<std::array<long, 3>>{right_isosceles}));
}

// A hypotenuse is bisected at once (bisect_edge == simple_bisect there).
TEST(Bisect2d, BisectEdgeOfAHypotenuseIsASimpleBisection) {
    Mesh mesh = test::planar_grid(2);
    const auto bisected = bisect_edge(mesh, 0, 4);
    ASSERT_TRUE(bisected.ok()) << bisected.reason();
    ASSERT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
    EXPECT_EQ(bisected->vertices, (std::vector<VertexId>{9}));
    EXPECT_EQ(mesh.element_count(), 10u);
}

// Triangle surfaces in space bisect too: the surface of the corner tetrahedron 0-1-2-3 (legs
// 0-1, 0-2, 0-3 of length 1). bisect(0-1) first bisects the hypotenuses 1-2 and 1-3 of its two
// triangles; the equilateral face <1,2,3> takes 1-2 (equal lengths: the smaller id pair).
TEST(Bisect2d, BisectEdgeOnASurfaceInSpace) {
    Mesh mesh(2, 3);
    for (const Point& p : {Point{0, 0, 0}, Point{1, 0, 0}, Point{0, 1, 0}, Point{0, 0, 1}})
        mesh.add_vertex(p);
    const std::array<Simplex, 4> faces{Simplex(+1, {0, 2, 1}), Simplex(+1, {0, 1, 3}),
                                       Simplex(+1, {1, 2, 3}), Simplex(+1, {0, 3, 2})};
    ASSERT_TRUE(mesh.assign_elements(faces).ok());
    const auto bisected = bisect_edge(mesh, 0, 1);
    ASSERT_TRUE(bisected.ok()) << bisected.reason();
    ASSERT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
    EXPECT_EQ(bisected->vertices, (std::vector<VertexId>{4, 5, 6}));
    EXPECT_EQ(mesh.reference(4), (Point{0.5, 0.5, 0}));  // on 1-2
    EXPECT_EQ(mesh.reference(5), (Point{0.5, 0, 0.5}));  // on 1-3
    EXPECT_EQ(mesh.reference(6), (Point{0.5, 0, 0}));    // on 0-1
    EXPECT_EQ(mesh.element_count(), 10u);
    EXPECT_EQ(mesh.boundary_face_count(), 0u);
}

void expect_bisect_refused(Mesh& mesh, VertexId p, VertexId q, RefusalCode code,
                          const std::string& reason) {
    const Mesh before = mesh;
    const auto bisected = bisect_edge(mesh, p, q);
    ASSERT_FALSE(bisected.ok());
    EXPECT_EQ(bisected.reason(), reason);
    EXPECT_EQ(bisected.code(), code);
    expect_same_state(mesh, before);
}

TEST(Bisect2d, BisectEdgeRefusals) {
    Mesh mesh = test::planar_grid(2);
    expect_bisect_refused(mesh, 0, 8, RefusalCode::not_found, "bisect_edge: +<0,8> is not an edge");
    expect_bisect_refused(mesh, 0, 9, RefusalCode::not_found, "bisect_edge: 9 is not a vertex");
    expect_bisect_refused(mesh, 3, 3, RefusalCode::bad_argument,
                          "bisect_edge: the two ends are the same vertex");
    Mesh cube = test::kuhn_cube(1);
    expect_bisect_refused(cube, 0, 7, RefusalCode::wrong_dimension,
                          "bisect_edge: needs a triangle mesh (topological dimension 2)");
}

// planar_grid(2) whose corner triangle <1,2,5> is flat in the deformed positions (vertex 2
// moved onto the line 1-5). Bisecting 1-4 first splits 0-4 (fine), then must split 1-5, whose
// children in <1,2,5> are flat: the whole bisection is refused and nothing was split, although
// the refusal comes after a planned split.
Mesh grid_with_a_flat_corner() {
    Mesh mesh = test::planar_grid(2);
    mesh.set_deformed(2, {3, 2, 0});
    return mesh;
}

TEST(Bisect2d, BisectEdgeIsATransactionAcrossItsSplits) {
    Mesh mesh = grid_with_a_flat_corner();
    const Mesh before = mesh;
    const auto bisected = bisect_edge(mesh, 1, 4);
    ASSERT_FALSE(bisected.ok());
    // vertex 10: the refused split is the second one planned (9 went to 0-4)
    EXPECT_EQ(bisected.reason(),
              "bisect_edge: new element +<2,5,10> would be flat in the deformed positions");
    EXPECT_EQ(bisected.code(), RefusalCode::would_flatten);
    expect_same_state(mesh, before);
    EXPECT_TRUE(mesh.validate().ok());
}

// ---- refine_around ----------------------------------------------------------------------------

//   2 ------- 3        x = (0.3, 0.2), h = 0.75: the hypotenuse 0-3 (1.41) is bisected
//   |       / |        (n = 4), then the hypotenuse 0-1 (1) of x's new triangle <0,1,4>
//   |     4   |        (m = 5); x's triangle <0,5,4> has hypotenuse 0-4 (0.71) <= h
//   |   /  \  |
//   | /  x   \|
//   0 -- 5 -- 1
TEST(Bisect2d, RefineAroundAPoint) {
    Mesh mesh = test::planar_grid(1);
    const Point x{0.3, 0.2, 0};
    const auto refined = refine_around(mesh, x, 0.75);
    ASSERT_TRUE(refined.ok()) << refined.reason();
    ASSERT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
    EXPECT_EQ(refined->bisections, 2u);
    EXPECT_EQ(mesh.reference(4), (Point{0.5, 0.5, 0}));
    EXPECT_EQ(mesh.reference(5), (Point{0.5, 0, 0}));
    ASSERT_TRUE(mesh.is_element(refined->element));
    EXPECT_EQ(mesh.simplex(refined->element), Simplex(+1, {0, 5, 4}));
    // already fine enough: nothing to do
    const auto again = refine_around(mesh, x, 0.75, refined->element);
    ASSERT_TRUE(again.ok()) << again.reason();
    EXPECT_EQ(again->bisections, 0u);
    EXPECT_EQ(again->element, refined->element);
}

void expect_refine_refused(Mesh& mesh, const Point& x, double h, RefusalCode code,
                          const std::string& reason) {
    const Mesh before = mesh;
    const auto refined = refine_around(mesh, x, h);
    ASSERT_FALSE(refined.ok());
    EXPECT_EQ(refined.reason(), reason);
    EXPECT_EQ(refined.code(), code);
    expect_same_state(mesh, before);
}

TEST(Bisect2d, RefineAroundRefusals) {
    Mesh mesh = test::planar_grid(2);
    expect_refine_refused(mesh, {2, 3, 0}, 0.5, RefusalCode::not_found,
                          "refine_around: point (2, 3) is not in the mesh");
    expect_refine_refused(mesh, {-0.25, 1, 0}, 0.5, RefusalCode::not_found,
                          "refine_around: point (-0.25, 1) is not in the mesh");
    expect_refine_refused(mesh, {NAN, 1, 0}, 0.5, RefusalCode::not_found,
                          "refine_around: point (nan, 1) is not in the mesh");
    expect_refine_refused(mesh, {1, 1, 0}, 0, RefusalCode::bad_argument,
                          "refine_around: size h = 0 is not a positive number");
    expect_refine_refused(mesh, {1, 1, 0}, -1, RefusalCode::bad_argument,
                          "refine_around: size h = -1 is not a positive number");
    expect_refine_refused(mesh, {1, 1, 0}, NAN, RefusalCode::bad_argument,
                          "refine_around: size h = nan is not a positive number");
    Mesh cube = test::kuhn_cube(1);
    expect_refine_refused(cube, {0.5, 0.5, 0.5}, 0.1, RefusalCode::wrong_dimension,
                          "refine_around: tetrahedral meshes use refine_around_tetrahedra");
    Mesh surface(2, 3);
    for (const Point& p : {Point{0, 0, 0}, Point{1, 0, 0}, Point{0, 1, 0}})
        surface.add_vertex(p);
    ASSERT_TRUE(surface.assign_elements(std::array<Simplex, 1>{Simplex(+1, {0, 1, 2})}).ok());
    expect_refine_refused(surface, {0.1, 0.1, 0}, 0.1, RefusalCode::wrong_dimension,
                          "refine_around: needs a planar triangle mesh (ambient dimension 2)");
}

// Refining next to vertex 1 plans two bisections (vertices 9 and 10) before it meets the flat
// corner <1,2,5>: nothing is applied.
TEST(Bisect2d, RefineAroundIsATransactionAcrossItsBisections) {
    Mesh mesh = grid_with_a_flat_corner();
    const Mesh before = mesh;
    const auto refined = refine_around(mesh, {0.95, 0.02, 0}, 0.01);
    ASSERT_FALSE(refined.ok());
    // vertex 11: two bisections were planned before the refused one
    EXPECT_EQ(refined.reason(),
              "refine_around: new element +<2,5,11> would be flat in the deformed positions");
    EXPECT_EQ(refined.code(), RefusalCode::would_flatten);
    expect_same_state(mesh, before);
}

// Point location walks from the hint and falls back to a scan when the walk leaves an
// L-shaped (non-convex) domain.
//
//   6 ----- 7
//   |     / |
//   |   /   |              (the cell 4-5-8-7 is missing)
//   3 ----- 4 ----- 5
//   |     / |     / |
//   |   /   |   /   |
//   0 ----- 1 ----- 2
TEST(Bisect2d, LocateTriangleInANonConvexDomain) {
    Mesh mesh(2, 2);
    for (int j = 0; j <= 2; ++j)
        for (int i = 0; i <= 2; ++i)
            mesh.add_vertex({double(i), double(j), 0});
    const std::array<Simplex, 6> triangles{Simplex(+1, {0, 1, 4}), Simplex(+1, {0, 4, 3}),
                                           Simplex(+1, {1, 2, 5}), Simplex(+1, {1, 5, 4}),
                                           Simplex(+1, {3, 4, 7}), Simplex(+1, {3, 7, 6})};
    ASSERT_TRUE(mesh.assign_elements(triangles).ok());
    for (ElementId hint : elements(mesh)) {
        const ElementId found = locate_triangle(mesh, {1.9, 0.2, 0}, hint);
        ASSERT_NE(found, invalid_id);
        EXPECT_EQ(mesh.simplex(found), Simplex(+1, {1, 2, 5}));
        EXPECT_EQ(locate_triangle(mesh, {1.5, 1.5, 0}, hint), invalid_id);  // in the missing cell
    }
    const auto refined = refine_around(mesh, {1.9, 0.2, 0}, 0.3, 5);
    ASSERT_TRUE(refined.ok()) << refined.reason();
    ASSERT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
    EXPECT_LE(longest_edge(mesh, refined->element), 0.3);
    EXPECT_DOUBLE_EQ(boundary_length(mesh), 8.0);
    EXPECT_EQ(angle_classes(mesh), (std::set<std::array<long, 3>>{right_isosceles}));
}

// Thesis §6.5 properties after many refinements around random points of the square (seeded;
// SXK_SEED=<n> replays): the mesh validates, it is conforming (the boundary length and the area
// are those of the square: a hanging vertex would add boundary edges inside), every triangle
// is strictly positive and congruent up to scale to the starting right isosceles triangle, and
// the triangle containing x has a hypotenuse no longer than h.
TEST(Bisect2d, RandomRefinementsStayConformingAndCongruent) {
    std::uint32_t seed = std::random_device{}();
    if (const char* given = std::getenv("SXK_SEED"))
        seed = static_cast<std::uint32_t>(std::strtoul(given, nullptr, 10));
    std::cout << "refine_around random refinements seed " << seed << '\n';
    SCOPED_TRACE("seed " + std::to_string(seed));
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> coordinate(0, 2);
    std::uniform_real_distribution<double> log_size(std::log(0.05), std::log(1.5));

    Mesh mesh = test::planar_grid(2);
    const auto start_classes = angle_classes(mesh);
    ElementId hint = invalid_id;
    std::size_t bisections = 0;
    for (int call = 0; call < 1000; ++call) {
        const Point x{coordinate(random), coordinate(random), 0};
        const double h = std::exp(log_size(random));
        const std::size_t vertices = mesh.vertex_count();
        const auto refined = refine_around(mesh, x, h, hint);
        ASSERT_TRUE(refined.ok()) << "call " << call << ": " << refined.reason();
        bisections += refined->bisections;
        ASSERT_EQ(mesh.vertex_count(), vertices + refined->bisections);
        ASSERT_TRUE(mesh.is_element(refined->element));
        ASSERT_TRUE(contains(mesh, refined->element, x)) << "call " << call;
        ASSERT_LE(longest_edge(mesh, refined->element), h) << "call " << call;
        hint = refined->element;
        if (call % 25 == 24 || call == 999) {
            ASSERT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
            ASSERT_DOUBLE_EQ(boundary_length(mesh), 8.0) << "call " << call;
            ASSERT_DOUBLE_EQ(area(mesh), 4.0) << "call " << call;
            ASSERT_TRUE(test::all_strictly_positive(mesh)) << "call " << call;
            ASSERT_EQ(angle_classes(mesh), start_classes) << "call " << call;
        }
    }
    std::cout << "refine_around: " << bisections << " bisections, " << mesh.element_count()
              << " triangles\n";
    EXPECT_GT(bisections, 100u);
}

}  // namespace
}  // namespace sxk
