#include "sxk/quality.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "fixtures.hpp"

namespace sxk {
namespace {

const std::array<Point, 4> regular{{{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}}};

TEST(Quality, MeanEdgeLengthCountsEachEdgeOnce) {
    // unit square: four sides of 1 and the shared diagonal of sqrt 2 (counted once, not twice)
    EXPECT_NEAR(mean_edge_length(test::unit_square()), (4 + std::sqrt(2.0)) / 5, 1e-15);
    // one Kuhn cube: 12 cube edges, one diagonal per face (6 x sqrt 2), the main diagonal
    // (sqrt 3): 19 edges shared by 6 tetrahedra
    EXPECT_NEAR(mean_edge_length(test::kuhn_cube(1)), (12 + 6 * std::sqrt(2.0) + std::sqrt(3.0)) / 19, 1e-15);
    // each position set on its own
    Mesh square = test::unit_square();
    square.set_deformed(2, {2, 2, 0});
    EXPECT_NEAR(mean_edge_length(square), (4 + std::sqrt(2.0)) / 5, 1e-15);
    EXPECT_GT(mean_edge_length(square, Positions::deformed), (4 + std::sqrt(2.0)) / 5 + 0.1);
    EXPECT_EQ(mean_edge_length(Mesh(3, 3)), 0.0);
}

TEST(Quality, RegularTetrahedron) {
    EXPECT_NEAR(aspect_ratio(regular), std::sqrt(2.0 / 3.0), 1e-12);
    EXPECT_NEAR(radius_ratio(regular), 1.0, 1e-12);
    for (double a : dihedral_angles(regular)) EXPECT_NEAR(a, std::acos(1.0 / 3.0), 1e-12);
}

TEST(Quality, EquilateralTriangle) {
    const std::array<Point, 3> t{{{0, 0, 0}, {1, 0, 0}, {0.5, std::sqrt(3.0) / 2, 0}}};
    EXPECT_NEAR(aspect_ratio(t), std::sqrt(3.0) / 2, 1e-12);
    EXPECT_NEAR(radius_ratio(t), 1.0, 1e-12);
    for (double a : triangle_angles(t)) EXPECT_NEAR(a, pi / 3, 1e-12);
}

TEST(Quality, CubeCornerDihedralAngles) {
    const std::array<Point, 4> corner{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
    const auto a = dihedral_angles(corner);
    // edges 01, 02, 03 meet at the right-angled corner
    EXPECT_NEAR(a[0], pi / 2, 1e-12);
    EXPECT_NEAR(a[1], pi / 2, 1e-12);
    EXPECT_NEAR(a[2], pi / 2, 1e-12);
    EXPECT_NEAR(a[3], std::acos(1 / std::sqrt(3.0)), 1e-12);
}

// The four classes of §3.2.3 (Fig. 3.8), each almost flat:
//   needle: a very short edge, no large angle
//   spindle: one vertex just above the middle of an edge: one large angle (at the edge
//            joining that vertex to the far vertex)
//   sliver: two opposite edges almost crossing: two large angles
//   cap: one vertex almost in the opposite face: three large angles
TEST(Quality, ClassifiesDegenerateTetrahedra) {
    const double e = 1e-4;
    const std::array<Point, 4> needle{{{0, 0, 0}, {1, 0, 0}, {0.5, 0.8, 0}, {0.5, 0.8, e}}};
    const std::array<Point, 4> sliver{{{0, 0, 0}, {1, 0, 0}, {0.5, -0.5, e}, {0.5, 0.5, e}}};
    const std::array<Point, 4> cap{{{0, 0, 0}, {1, 0, 0}, {0.5, 0.9, 0}, {0.5, 0.3, e}}};
    const std::array<Point, 4> spindle{{{0, 0, 0}, {1, 0, 0}, {0.5, 1, 0}, {0.5, 0, e}}};
    EXPECT_EQ(classify_tetrahedron(regular), DegenerateClass::none);
    EXPECT_EQ(classify_tetrahedron(needle), DegenerateClass::needle);
    EXPECT_EQ(classify_tetrahedron(sliver), DegenerateClass::sliver);
    EXPECT_EQ(classify_tetrahedron(cap), DegenerateClass::cap);
    EXPECT_EQ(classify_tetrahedron(spindle), DegenerateClass::spindle);
    EXPECT_EQ(to_string(DegenerateClass::sliver), "sliver");
    // thresholds are parameters
    EXPECT_EQ(classify_tetrahedron(sliver, {1e-6, 0.99 * pi}), DegenerateClass::none);
}

TEST(Quality, SummaryOfTheKuhnCube) {
    const Mesh mesh = test::kuhn_cube(2);
    const QualitySummary q = summarize_quality(mesh);
    EXPECT_EQ(q.elements, 48u);
    EXPECT_EQ(q.inverted, 0u);
    EXPECT_EQ(q.flat, 0u);
    EXPECT_EQ(q.degenerate, 0u);
    // every Kuhn tetrahedron is congruent: min = max
    EXPECT_NEAR(q.min_aspect_ratio, q.max_aspect_ratio, 1e-12);
    EXPECT_NEAR(q.min_angle, pi / 4, 1e-12);   // dihedral angles of the Kuhn simplex: 45, 60, 90
    EXPECT_NEAR(q.max_angle, pi / 2, 1e-12);
    EXPECT_EQ(q.by_class[0], 48u);
}

}  // namespace
}  // namespace sxk
