#include "sxk/predicates.hpp"

#include <gtest/gtest.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/intersections.h>

#include <array>
#include <cmath>
#include <random>

#include "fixtures.hpp"

namespace sxk {
namespace {

TEST(Predicates, Orientation2D) {
    EXPECT_EQ(orient2d({0, 0, 0}, {1, 0, 0}, {0, 1, 0}), Sign::positive);
    EXPECT_EQ(orient2d({0, 0, 0}, {0, 1, 0}, {1, 0, 0}), Sign::negative);
    EXPECT_EQ(orient2d({0, 0, 0}, {1, 1, 0}, {2, 2, 0}), Sign::zero);
}

TEST(Predicates, Orientation2DIsExactNearCollinear) {
    // b and c lie on the line y = x; a sits one unit in the last place off it, far below what
    // the naive determinant's rounding error can resolve.
    const Point b{12, 12, 0}, c{24, 24, 0};
    const double up = std::nextafter(0.5, 1.0), down = std::nextafter(0.5, 0.0);
    EXPECT_EQ(orient2d({0.5, 0.5, 0}, b, c), Sign::zero);
    EXPECT_EQ(orient2d({up, 0.5, 0}, b, c), Sign::negative);  // right of b->c: clockwise
    EXPECT_EQ(orient2d({down, 0.5, 0}, b, c), Sign::positive);
    EXPECT_EQ(orient2d({0.5, 0.5, 0}, b, {24, std::nextafter(24.0, 25.0), 0}), Sign::positive);
}

TEST(Predicates, Orientation3D) {
    const Point a{0, 0, 0}, b{1, 0, 0}, c{0, 1, 0};
    EXPECT_EQ(orient3d(a, b, c, {0, 0, 1}), Sign::positive);
    EXPECT_EQ(orient3d(a, b, c, {0, 0, -1}), Sign::negative);
    EXPECT_EQ(orient3d(a, b, c, {0.3, 0.3, 0}), Sign::zero);
    EXPECT_EQ(orient3d(a, b, c, {0.3, 0.3, std::ldexp(1.0, -1000)}), Sign::positive);
}

TEST(Predicates, InCircleAndInSphere) {
    const Point a{0, 0, 0}, b{1, 0, 0}, c{0, 1, 0};
    EXPECT_EQ(incircle(a, b, c, {0.5, 0.5, 0}), Sign::positive);
    EXPECT_EQ(incircle(a, b, c, {1, 1, 0}), Sign::zero);  // cocircular
    EXPECT_EQ(incircle(a, b, c, {2, 2, 0}), Sign::negative);
    const Point d{0, 0, 1};
    EXPECT_EQ(insphere(a, b, c, d, {0.25, 0.25, 0.25}), Sign::positive);
    EXPECT_EQ(insphere(a, b, c, d, {1, 1, 1}), Sign::zero);  // the cube corner is on the sphere
    EXPECT_EQ(insphere(a, b, c, d, {2, 2, 2}), Sign::negative);
}

// The unfolded test of an edge a-b between (a, b, c) and (b, a, d): in the plane it is incircle for
// a convex quadrilateral; folding (b, a, d) about the edge changes nothing; ties are exact.
TEST(Predicates, UnfoldedIncircleIsIncircleInThePlaneAndDoesNotSeeTheFold) {
    std::mt19937_64 random(test::seed_for("Predicates.UnfoldedIncircle"));
    std::uniform_real_distribution<double> coordinate(0.05, 1.5);
    std::size_t failing = 0, compared = 0;
    for (int trial = 0; trial < 2000; ++trial) {
        const Point a{0, 0, 0}, b{2, 0, 0};
        const Point c{coordinate(random), coordinate(random), 0};   // above the edge
        const Point d{coordinate(random), -coordinate(random), 0};  // below
        if (orient2d(a, d, b) != Sign::positive || orient2d(d, b, c) != Sign::positive ||
            orient2d(b, c, a) != Sign::positive || orient2d(c, a, d) != Sign::positive)
            continue;  // only convex quadrilaterals a d b c
        ++compared;
        const Sign planar = incircle(a, b, c, d);
        EXPECT_EQ(unfolded_incircle(a, b, c, d), planar) << trial;
        failing += planar == Sign::positive;
        // fold (b, a, d) about the x axis by a right angle: d = (x, -y, 0) -> (x, 0, -y), exactly
        const Point folded{d[0], 0, d[1]};
        EXPECT_EQ(unfolded_incircle(a, b, c, folded), planar) << trial;
    }
    EXPECT_GT(compared, 500u);
    EXPECT_GT(failing, 50u);
    EXPECT_LT(failing, compared - 50);
    // two right angles, one of them folded out of the plane: the sum is pi exactly
    EXPECT_EQ(unfolded_incircle({0, 0, 0}, {2, 0, 0}, {1, 1, 0}, {1, 0, 1}), Sign::zero);
    // a hair more or less than a right angle at d
    const Point a{0, 0, 0}, b{2, 0, 0}, c{1, 1, 0};
    EXPECT_EQ(unfolded_incircle(a, b, c, {1, 0, std::nextafter(1.0, 0.0)}), Sign::positive);
    EXPECT_EQ(unfolded_incircle(a, b, c, {1, 0, std::nextafter(1.0, 2.0)}), Sign::negative);
    // degenerate triangles: c on the edge (an angle of pi) fails with any d; beyond its end (0) not
    EXPECT_EQ(unfolded_incircle({0, 0, 0}, {2, 0, 0}, {1, 0, 0}, {1, -1, 0}), Sign::positive);
    EXPECT_EQ(unfolded_incircle({0, 0, 0}, {2, 0, 0}, {3, 0, 0}, {1, -5, 0}), Sign::negative);
}

TEST(Predicates, ElementOrientationHonoursTheSimplexSign) {
    Mesh mesh = test::kuhn_cube(1);
    for (ElementId t : elements(mesh))
        EXPECT_EQ(element_orientation(mesh, t), Sign::positive);
    // push a vertex through the opposite face: (1,1,1) is in all six tetrahedra
    mesh.set_deformed(7, {-1, -1, -1});
    std::size_t inverted = 0;
    for (ElementId t : elements(mesh))
        inverted += element_orientation(mesh, t) == Sign::negative;
    EXPECT_EQ(inverted, 6u);
    for (ElementId t : elements(mesh))
        EXPECT_EQ(element_orientation(mesh, t, Positions::reference), Sign::positive);
}

// compare_distances_to_plane: which end of a cut edge is nearer the sweep (thesis §3.2.1), on the
// plane x + y + z = 0 (normal (1, 1, 1) exactly), decided exactly down to one unit in the last
// place; in doubles 0.1 + 0.2 + 0.3 already carries a rounding of 1e-16.
TEST(Predicates, CompareDistancesToAPlaneIsExact) {
    const Point p{0, 0, 0}, q{1, -1, 0}, r{1, 0, -1};
    const Point a{0.1, 0.2, 0.3};
    const Point mirror{-0.3, -0.2, -0.1};  // exactly as far on the other side
    EXPECT_EQ(compare_distances_to_plane(a, mirror, p, q, r), Sign::zero);
    const Point farther{-0.3, -0.2, std::nextafter(-0.1, -1.0)};
    const Point nearer{-0.3, -0.2, std::nextafter(-0.1, 0.0)};
    EXPECT_EQ(compare_distances_to_plane(a, farther, p, q, r), Sign::negative);  // a is nearer
    EXPECT_EQ(compare_distances_to_plane(a, nearer, p, q, r), Sign::positive);
    EXPECT_EQ(compare_distances_to_plane(farther, a, p, q, r), Sign::positive);  // antisymmetric
    // a segment crossing z = 0 a quarter of the way from its lower end
    EXPECT_EQ(compare_distances_to_plane({0, 0, -1}, {5, 2, 3}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}),
              Sign::negative);
    // both ends on one side: the nearer to the plane
    EXPECT_EQ(compare_distances_to_plane({0, 0, 4}, {0, 0, 3}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}),
              Sign::positive);
    // a degenerate plane (collinear p, q, r): no distance to compare
    EXPECT_EQ(compare_distances_to_plane({0, 0, 4}, {0, 0, 3}, {0, 0, 0}, {1, 0, 0}, {2, 0, 0}),
              Sign::zero);
}


TEST(Predicates, SegmentMeetsTriangleExactlyOnItsClosure) {
    const Point p{0, 0, 0}, q{1, 0, 0}, r{0, 1, 0};
    EXPECT_TRUE(segment_meets_triangle({0.2, 0.2, -1}, {0.2, 0.2, 1}, p, q, r));   // through the inside
    EXPECT_TRUE(segment_meets_triangle({0, 0, -1}, {0, 0, 1}, p, q, r));           // through a corner
    EXPECT_TRUE(segment_meets_triangle({0.5, 0.5, -1}, {0.5, 0.5, 1}, p, q, r));   // through the hypotenuse
    EXPECT_FALSE(segment_meets_triangle({0.5, 0.5 + 1e-16, -1}, {0.5, 0.5 + 1e-16, 1}, p, q, r));
    EXPECT_TRUE(segment_meets_triangle({0.2, 0.2, 0}, {0.2, 0.2, 1}, p, q, r));    // ends on it
    EXPECT_FALSE(segment_meets_triangle({0.2, 0.2, 1e-300}, {0.2, 0.2, 1}, p, q, r));
    EXPECT_TRUE(segment_meets_triangle({-1, 0.5, 0}, {2, 0.5, 0}, p, q, r));       // in its plane
    EXPECT_TRUE(segment_meets_triangle({0.1, 0.1, 0}, {0.1, 0.1, 0}, p, q, r));    // a point on it
    // collinear corners: the segment between the two farthest
    const Point a{0, 0, 0}, b{2, 0, 0}, c{1, 0, 0};
    EXPECT_TRUE(segment_meets_triangle({1.5, -1, 0}, {1.5, 1, 0}, a, c, b));
    EXPECT_FALSE(segment_meets_triangle({2.5, -1, 0}, {2.5, 1, 0}, a, c, b));
}

TEST(Predicates, TriangleMeetsTetrahedronOnItsClosureAndDegenerateInputs) {
    const Point p{0, 0, 0}, q{1, 0, 0}, r{0, 1, 0}, s{0, 0, 1};
    EXPECT_TRUE(triangle_meets_tetrahedron({-1, -1, 0.5}, {3, -1, 0.5}, {-1, 3, 0.5}, p, q, r, s));  // slices it
    EXPECT_TRUE(triangle_meets_tetrahedron({0.1, 0.1, 0.1}, {5, 5, 5}, {5, 0, 5}, p, q, r, s));     // a corner inside
    EXPECT_TRUE(triangle_meets_tetrahedron({1, 0, 0}, {2, 0, 0}, {2, 1, 0}, p, q, r, s));           // touches a corner
    EXPECT_FALSE(triangle_meets_tetrahedron({1, 1e-300, 0}, {2, 0, 0}, {2, 1, 0}, p, q, r, s));     // just misses it
    EXPECT_FALSE(triangle_meets_tetrahedron({-1, -1, 1.5}, {3, -1, 1.5}, {-1, 3, 1.5}, p, q, r, s));
    EXPECT_TRUE(triangle_meets_tetrahedron({0.2, 0.2, -1}, {0.2, 0.2, 1}, {0.2, 0.2, 3}, p, q, r, s));  // collinear
    EXPECT_FALSE(triangle_meets_tetrahedron({2, 2, -1}, {2, 2, 1}, {2, 2, 3}, p, q, r, s));
    EXPECT_TRUE(triangle_meets_tetrahedron({0.1, 0.1, 0.1}, {0.1, 0.1, 0.1}, {0.1, 0.1, 0.1}, p, q, r, s));  // a point
    EXPECT_FALSE(triangle_meets_tetrahedron({-1, -1, 0}, {3, -1, 0}, {-1, 3, 0}, p, q, r, {1, 1, 0}));  // flat
}

// Points of the small integer grid [-2, 2]^3, now and then nudged by a unit in the last place:
// configurations drawn from it are degenerate somewhere more often than not.
class GridPoints {
public:
    explicit GridPoints(std::uint64_t seed) : m_random(seed) {}
    Point operator()() {
        Point x{};
        for (double& v : x) {
            v = m_coordinate(m_random);
            if (m_nudge(m_random)) v = std::nextafter(v, m_nudge(m_random) ? 3.0 : -3.0);
        }
        return x;
    }

private:
    std::mt19937_64 m_random;
    std::uniform_int_distribution<int> m_coordinate{-2, 2};
    std::bernoulli_distribution m_nudge{0.1};
};

// triangle_meets_tetrahedron (orientation signs) against CGAL's do_intersect (the peer it
// replaces), on corners drawn from a small integer grid, where most configurations are
// degenerate somewhere (a corner in a face's plane, an edge in the triangle's plane, crossings
// through corners and edges), and on grid corners nudged by a unit in the last place.
TEST(Predicates, TriangleMeetsTetrahedronAgreesWithCgalOnDegenerateConfigurations) {
    using K = CGAL::Exact_predicates_inexact_constructions_kernel;
    const std::uint64_t seed = test::seed_for("Predicates.TriangleMeetsTetrahedronAgreesWithCgalOnDegenerateConfigurations");
    GridPoints draw(seed);
    auto cgal = [](const Point& x) { return K::Point_3(x[0], x[1], x[2]); };
    int tetrahedra = 0, meeting = 0;
    for (int round = 0; round < 200000; ++round) {
        const Point a = draw(), b = draw(), c = draw(), p = draw(), q = draw(), r = draw(), s = draw();
        // CGAL's test needs a proper triangle and tetrahedron (ours: the test above)
        if (collinear(a, b, c) || orient3d(p, q, r, s) == Sign::zero) continue;
        const bool expected = CGAL::do_intersect(K::Triangle_3(cgal(a), cgal(b), cgal(c)),
                                                 K::Tetrahedron_3(cgal(p), cgal(q), cgal(r), cgal(s)));
        ASSERT_EQ(triangle_meets_tetrahedron(a, b, c, p, q, r, s), expected) << "round " << round;
        ++tetrahedra;
        meeting += expected;
    }
    // both answers occur often (the test is not one-sided)
    EXPECT_GT(meeting, tetrahedra / 10);
    EXPECT_LT(meeting, tetrahedra * 9 / 10);
}

TEST(Predicates, SegmentMeetsTetrahedronOnItsClosureAndDegenerateInputs) {
    const Point p{0, 0, 0}, q{1, 0, 0}, r{0, 1, 0}, s{0, 0, 1};
    EXPECT_TRUE(segment_meets_tetrahedron({0.2, 0.2, -1}, {0.2, 0.2, 3}, p, q, r, s));     // through it
    EXPECT_TRUE(segment_meets_tetrahedron({0.1, 0.1, 0.1}, {5, 5, 5}, p, q, r, s));        // an end inside
    EXPECT_TRUE(segment_meets_tetrahedron({1, 0, 0}, {2, 0, 0}, p, q, r, s));              // touches a corner
    EXPECT_TRUE(segment_meets_tetrahedron({-1, 0, 0}, {2, 0, 0}, p, q, r, s));             // along an edge
    EXPECT_TRUE(segment_meets_tetrahedron({-1, 0.5, 0}, {2, 0.5, 0}, p, q, r, s));         // across a face, in it
    EXPECT_TRUE(segment_meets_tetrahedron({0.5, -1, 0.5}, {0.5, 1, 0.5}, p, q, r, s));     // through an edge
    EXPECT_FALSE(segment_meets_tetrahedron({1, 1e-300, 0}, {2, 0, 0}, p, q, r, s));        // just misses it
    EXPECT_FALSE(segment_meets_tetrahedron({0.6, 0.6, -1}, {0.6, 0.6, 3}, p, q, r, s));    // passes beside it
    EXPECT_TRUE(segment_meets_tetrahedron({0.1, 0.1, 0.1}, {0.1, 0.1, 0.1}, p, q, r, s));  // a point inside
    EXPECT_FALSE(segment_meets_tetrahedron({2, 2, 2}, {2, 2, 2}, p, q, r, s));             // a point outside
    EXPECT_FALSE(segment_meets_tetrahedron({0.2, 0.2, -1}, {0.2, 0.2, 3}, p, q, r, {1, 1, 0}));  // flat
}

// segment_meets_tetrahedron against CGAL's do_intersect, on grid corners as above (nudged by a
// unit in the last place now and then), points included.
TEST(Predicates, SegmentMeetsTetrahedronAgreesWithCgalOnDegenerateConfigurations) {
    using K = CGAL::Exact_predicates_inexact_constructions_kernel;
    const std::uint64_t seed =
        test::seed_for("Predicates.SegmentMeetsTetrahedronAgreesWithCgalOnDegenerateConfigurations");
    GridPoints draw(seed);
    auto cgal = [](const Point& x) { return K::Point_3(x[0], x[1], x[2]); };
    int tetrahedra = 0, meeting = 0;
    for (int round = 0; round < 200000; ++round) {
        const Point a = draw(), b = draw(), p = draw(), q = draw(), r = draw(), s = draw();
        if (orient3d(p, q, r, s) == Sign::zero) continue;  // CGAL's test needs a proper tetrahedron
        const K::Tetrahedron_3 k(cgal(p), cgal(q), cgal(r), cgal(s));
        const bool expected =
            a == b ? !k.has_on_unbounded_side(cgal(a)) : CGAL::do_intersect(K::Segment_3(cgal(a), cgal(b)), k);
        ASSERT_EQ(segment_meets_tetrahedron(a, b, p, q, r, s), expected) << "round " << round;
        ++tetrahedra;
        meeting += expected;
    }
    EXPECT_GT(meeting, tetrahedra / 10);
    EXPECT_LT(meeting, tetrahedra * 9 / 10);
}

}  // namespace
}  // namespace sxk
