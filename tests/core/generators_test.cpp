#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "sxk/generators.hpp"
#include "sxk/predicates.hpp"
#include "sxk/traversal.hpp"

namespace sxk {
namespace {

// The thesis' cube (§3.3: 729 nodes, 3072 elements), conforming and positive, filling the cube.
TEST(MakeKuhnCube, IsTheThesisCube) {
    auto made = make_kuhn_cube(8, 0.5);
    ASSERT_TRUE(made.ok()) << made.reason();
    const Mesh& mesh = *made;
    EXPECT_EQ(mesh.vertex_count(), 729u);
    EXPECT_EQ(mesh.element_count(), 3072u);
    EXPECT_EQ(mesh.boundary_face_count(), 6u * 8u * 8u * 2u);
    double volume = 0;
    for (const ElementId t : elements(mesh)) {
        EXPECT_EQ(element_orientation(mesh, t, Positions::reference), Sign::positive) << t;
        EXPECT_EQ(mesh.label(t), 0);
        const Simplex& s = mesh.simplex(t);
        auto p = [&](int j) { return mesh.reference(s.vertex(j)); };
        const Point a = p(0), b = p(1), c = p(2), d = p(3);
        const double ux = b[0] - a[0], uy = b[1] - a[1], uz = b[2] - a[2];
        const double vx = c[0] - a[0], vy = c[1] - a[1], vz = c[2] - a[2];
        const double wx = d[0] - a[0], wy = d[1] - a[1], wz = d[2] - a[2];
        volume += std::abs(ux * (vy * wz - vz * wy) - uy * (vx * wz - vz * wx) + uz * (vx * wy - vy * wx)) / 6;
    }
    EXPECT_NEAR(volume, 64.0, 64.0 * 1e-12);  // (8 * 0.5)^3, 3072 rounded terms of 1/48
    const Point corner = mesh.reference(728);
    EXPECT_EQ(corner, (Point{4.0, 4.0, 4.0}));
    EXPECT_EQ(mesh.reference(1), (Point{0.5, 0.0, 0.0}));  // x fastest
    EXPECT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
}

TEST(MakeKuhnCube, RefusesBadSizes) {
    EXPECT_EQ(make_kuhn_cube(0).reason(), "make_kuhn_cube: 0 cubes per side is not in 1..1000");
    EXPECT_EQ(make_kuhn_cube(0).code(), RefusalCode::bad_argument);
    EXPECT_EQ(make_kuhn_cube(1001).reason(), "make_kuhn_cube: 1001 cubes per side is not in 1..1000");
    EXPECT_EQ(make_kuhn_cube(1001).code(), RefusalCode::bad_argument);
    EXPECT_EQ(make_kuhn_cube(2, 0.0).reason(),
              "make_kuhn_cube: spacing 0.000000 is not positive and finite");
    EXPECT_EQ(make_kuhn_cube(2, 0.0).code(), RefusalCode::bad_argument);
    EXPECT_FALSE(make_kuhn_cube(2, std::numeric_limits<double>::quiet_NaN()).ok());
    EXPECT_FALSE(make_kuhn_cube(2, std::numeric_limits<double>::infinity()).ok());
}

}  // namespace
}  // namespace sxk
