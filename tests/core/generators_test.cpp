#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "sxk/generators.hpp"
#include "sxk/predicates.hpp"
#include "sxk/traversal.hpp"

namespace sxk {
namespace {

// |volume| of tetrahedron t at its reference positions.
double tetrahedron_volume(const Mesh& mesh, ElementId t) {
    const Simplex& s = mesh.simplex(t);
    auto p = [&](int j) { return mesh.reference(s.vertex(j)); };
    const Point a = p(0), b = p(1), c = p(2), d = p(3);
    const double ux = b[0] - a[0], uy = b[1] - a[1], uz = b[2] - a[2];
    const double vx = c[0] - a[0], vy = c[1] - a[1], vz = c[2] - a[2];
    const double wx = d[0] - a[0], wy = d[1] - a[1], wz = d[2] - a[2];
    return std::abs(ux * (vy * wz - vz * wy) - uy * (vx * wz - vz * wx) + uz * (vx * wy - vy * wx)) / 6;
}

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
        volume += tetrahedron_volume(mesh, t);
    }
    EXPECT_NEAR(volume, 64.0, 64.0 * 1e-12);  // (8 * 0.5)^3, 3072 rounded terms of 1/48
    const Point corner = mesh.reference(728);
    EXPECT_EQ(corner, (Point{4.0, 4.0, 4.0}));
    EXPECT_EQ(mesh.reference(1), (Point{0.5, 0.0, 0.0}));  // x fastest
    EXPECT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
}

// The thesis' coarsest cantilever beam (Table 3.1: 16 x 4 x 4 cells, 425 nodes), boxes of
// 0.075 x 0.05 x 0.075 m, positive and conforming, its volume the beam's.
TEST(MakeKuhnBox, IsTheThesisBeam) {
    auto made = make_kuhn_box({16, 4, 4}, {1.2 / 16, 0.2 / 4, 0.3 / 4});
    ASSERT_TRUE(made.ok()) << made.reason();
    const Mesh& mesh = *made;
    EXPECT_EQ(mesh.vertex_count(), 425u);
    EXPECT_EQ(mesh.element_count(), 6u * 16u * 4u * 4u);
    EXPECT_EQ(mesh.boundary_face_count(), 2u * (2u * 16u * 4u + 2u * 16u * 4u + 2u * 4u * 4u));
    double volume = 0;
    for (const ElementId t : elements(mesh)) {
        EXPECT_EQ(element_orientation(mesh, t, Positions::reference), Sign::positive) << t;
        volume += tetrahedron_volume(mesh, t);
    }
    EXPECT_NEAR(volume, 1.2 * 0.2 * 0.3, 1.2 * 0.2 * 0.3 * 1e-12);  // 1536 rounded terms
    EXPECT_EQ(mesh.reference(1), (Point{0.075, 0.0, 0.0}));  // x fastest
    EXPECT_EQ(mesh.reference(17), (Point{0.0, 0.05, 0.0}));
    EXPECT_EQ(mesh.reference(85), (Point{0.0, 0.0, 0.075}));
    EXPECT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
}

TEST(MakeKuhnBox, RefusesBadSizes) {
    EXPECT_EQ(make_kuhn_box({2, 0, 2}, {1, 1, 1}).reason(), "make_kuhn_box: 0 cells along y is not in 1..1000");
    EXPECT_EQ(make_kuhn_box({2, 0, 2}, {1, 1, 1}).code(), RefusalCode::bad_argument);
    EXPECT_EQ(make_kuhn_box({2, 2, 1001}, {1, 1, 1}).reason(), "make_kuhn_box: 1001 cells along z is not in 1..1000");
    EXPECT_EQ(make_kuhn_box({2, 2, 2}, {-1, 1, 1}).reason(),
              "make_kuhn_box: spacing -1.000000 along x is not positive and finite");
    EXPECT_FALSE(make_kuhn_box({2, 2, 2}, {1, std::numeric_limits<double>::infinity(), 1}).ok());
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


TEST(MakeDelaunay, TetrahedralisesACloudAndRefusesWhatSpansNoTetrahedron) {
    const std::vector<Point> cloud = cylinder_cloud(4, 13);
    ASSERT_EQ(cloud.size(), 896u);  // 14 discs of 1 + 6 + 13 + 19 + 25 points
    const Mesh mesh = make_delaunay(cloud).value();
    EXPECT_EQ(mesh.vertex_count(), 896u);
    EXPECT_GT(mesh.element_count(), 3000u);
    const auto valid = mesh.validate({.orientation = true, .flat_is_invalid = true});
    EXPECT_TRUE(valid) << valid.reason();
    for (VertexId v = 0; v < mesh.vertex_count(); ++v) EXPECT_NE(mesh.vertex_element(v), invalid_id);

    const std::vector<Point> three{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    EXPECT_EQ(make_delaunay(three).reason(), "make_delaunay: 3 points; a tetrahedron needs 4");
    const std::vector<Point> flat{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {0.5, 0.2, 0}};
    EXPECT_EQ(make_delaunay(flat).reason(), "make_delaunay: the points are coplanar");
    const std::vector<Point> nan{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, std::nan("")}};
    EXPECT_EQ(make_delaunay(nan).reason(), "make_delaunay: point 3 is not finite");
}

// The thesis' Fig. 5.19 surface: the 14 x 14 grid lifted into a Gaussian bell, its top at the centre.
TEST(MakeGaussianBell, LiftsTheGridIntoABellAndRefusesBadShapes) {
    auto bell = make_gaussian_bell({14, 14}, {1.0, 1.0}, 5.0, 2.0);
    ASSERT_TRUE(bell.ok()) << bell.reason();
    EXPECT_EQ(bell->topological_dimension(), 2);
    EXPECT_EQ(bell->ambient_dimension(), 3);
    EXPECT_EQ(bell->element_count(), 392u);
    EXPECT_EQ(bell->vertex_count(), 225u);
    EXPECT_TRUE(bell->validate().ok());
    const VertexId top = 7 * 15 + 7;
    EXPECT_EQ(bell->reference(top), (Point{7, 7, 5}));
    EXPECT_DOUBLE_EQ(bell->reference(0)[2], 5 * std::exp(-98.0 / 8));
    EXPECT_EQ(make_gaussian_bell({14, 14}, {1, 1}, 5, 0).reason(),
              "make_gaussian_bell: width 0.000000 is not positive and finite");
    EXPECT_EQ(make_gaussian_bell({0, 14}, {1, 1}, 5, 2).reason(),
              "make_gaussian_bell: 0 cells along x is not in 1..5000");
    EXPECT_EQ(make_gaussian_bell({2, 2}, {1, 1}, std::nan(""), 2).reason(),
              "make_gaussian_bell: height nan is not finite");
}

}  // namespace
}  // namespace sxk
