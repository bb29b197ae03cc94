// SpatialIndex (sxk/locate.hpp): each query on hand-drawn meshes with exact answers, agreement
// with a scan of every element on a planar grid, a Kuhn cube and an octahedron surface (both
// position sets, after moves), the index-less walks, and refine_around with an index.
#include <gtest/gtest.h>

#include <random>

#include "../../fuzz/ops_driver.hpp"
#include "core/fixtures.hpp"
#include "core/locate_scan.hpp"
#include "sxk/edit_journal.hpp"
#include "sxk/locate.hpp"
#include "sxk/ops/refine_around.hpp"
#include "sxk/ops/refine_around_tetrahedra.hpp"
#include "sxk/ops/split_edge.hpp"

namespace sxk {
namespace {

// The vertices of face f, sorted.
std::vector<VertexId> face_vertices(const Mesh& mesh, FaceId f) {
    const Simplex s = mesh.face_simplex(f);
    return {s.vertices().begin(), s.vertices().end()};
}

//   3 ------- 2
//   |  B   /  |      A = element 0 = <0,1,2>, B = element 1 = <0,2,3>
//   |   /  A  |
//   0 ------- 1
TEST(SpatialIndex, LocatesInsideOnTheDiagonalAtAVertexAndOutside) {
    Mesh mesh = test::unit_square();
    const SpatialIndex index(mesh);
    const Location inside = index.locate({0.75, 0.25, 0});
    ASSERT_TRUE(inside.found());
    EXPECT_EQ(inside.element, 0u);
    // (0.75, 0.25) = 0.25 (0,0) + 0.5 (1,0) + 0.25 (1,1)
    EXPECT_DOUBLE_EQ(inside.barycentric[0], 0.25);
    EXPECT_DOUBLE_EQ(inside.barycentric[1], 0.5);
    EXPECT_DOUBLE_EQ(inside.barycentric[2], 0.25);
    EXPECT_EQ(inside.barycentric[3], 0.0);
    // z is ignored in a planar mesh
    EXPECT_EQ(index.locate({0.75, 0.25, 7}).element, 0u);
    // on the shared diagonal: either triangle, the weight of the vertex off the diagonal exactly 0
    const Location diagonal = index.locate({0.5, 0.5, 0});
    ASSERT_TRUE(diagonal.found());
    const Simplex& s = mesh.simplex(diagonal.element);
    const int off = s.index(diagonal.element == 0 ? 1u : 3u);
    EXPECT_EQ(diagonal.barycentric[static_cast<std::size_t>(off)], 0.0);
    EXPECT_TRUE(index.locate({1, 1, 0}).found());
    EXPECT_FALSE(index.locate({2, 2, 0}).found());
    EXPECT_FALSE(index.locate({1.0000001, 0.5, 0}).found());
    EXPECT_FALSE(index.locate({std::nan(""), 0.5, 0}).found());
    // a hint walks; a hint far away or dead still finds the point through the tree
    EXPECT_EQ(index.locate({0.25, 0.75, 0}, 0).element, 1u);
    EXPECT_EQ(index.locate({0.25, 0.75, 0}, 77).element, 1u);
}

// A tetrahedron from EditJournalRandom.JitteredKuhnCube (SXK_SEED=3763780165, step 1776) and a
// point the exact test puts strictly inside it. The double-precision solve gave weights
// 0.585, -0.0061, 0.406, 0.0154, which reproduce x to 2e-16 and were then clamped to a point
// 1.75e-3 away; the weights must be positive and give back x.
TEST(SpatialIndex, WeightsInANearFlatTetrahedronArePositiveAndGiveBackThePoint) {
    Mesh mesh(3, 3);
    mesh.add_vertex({0x1.3575757575757p+0, 0x1.f737373737373p+0, 0x1.b636363636364p-1});
    mesh.add_vertex({0x1.1a449a49f6e1cp+0, 0x1.6a6eb14e70898p+0, 0x1.f2dc60c11f3cfp-1});
    mesh.add_vertex({0x1.a297c29a70e65p+0, 0x1.9e4061b0414dcp+0, 0x1.76107189a1289p+0});
    mesh.add_vertex({0x1.b030303030302p+0, 0x1.e4a4a4a4a4a4ap+0, 0x1.66e6e6e6e6e6ep+0});
    const std::array<Simplex, 1> tetrahedron{Simplex(+1, {0, 1, 2, 3})};
    ASSERT_TRUE(mesh.assign_elements(tetrahedron).ok());
    const Point x{0x1.63d69beea2f4bp+0, 0x1.d3a99622c65d7p+0, 0x1.1c0186394db9cp+0};
    const Location found = locate_in_element(mesh, 0, x, Positions::reference, 0);
    ASSERT_TRUE(found.found());
    double sum = 0;
    for (std::size_t j = 0; j < 4; ++j) {
        EXPECT_GT(found.barycentric[j], 0.0) << "weight " << j;
        sum += found.barycentric[j];
    }
    EXPECT_NEAR(sum, 1.0, 1e-15);
    const Point back = test::point_of(mesh, found, Positions::reference);
    for (std::size_t k = 0; k < 3; ++k) EXPECT_NEAR(back[k], x[k], 1e-14) << "coordinate " << k;
    EXPECT_TRUE(mesh.validate().ok());
}

// A surface triangle from EditJournalRandom.OctahedronSurface (SXK_SEED=358757303, step 1180)
// and a ray in its plane that starts 0.03 outside it and ends on its corner p1 at t = 1 (origin +
// direction == p1 exactly). The triangle's edge p2-p0 is parallel to the ray in the projection
// but off its line; it was taken for an edge the ray runs along, which answered t = 0.
TEST(SpatialIndex, ARayInATrianglesPlaneMeetsItWhereItMeetsIt) {
    Mesh mesh(2, 3);
    mesh.add_vertex({0x1.bc759a96060bp-2, -0x1.cbc8b6a40ad78p-3, 0x1.2a1ac1ba746e4p-2});
    mesh.add_vertex({0x1.65c6c4ba2ea63p-2, -0x1.3b4c5aa468c34p-3, 0x1.fc2f35994f6acp-2});
    mesh.add_vertex({0x1.d49d42728d59p-2, -0x1.15bd52cc7cacfp-3, 0x1.a39f8aa0d9924p-2});
    const std::array<Simplex, 1> triangle{Simplex(+1, {0, 1, 2})};
    ASSERT_TRUE(mesh.assign_elements(triangle).ok());
    const Point origin{0x1.4d9f1cdda7584p-2, -0x1.f157be7bf6eddp-3, 0x1.82aa6cb2ea46cp-2};
    const Point direction{0x1.827a7dc874dfp-6, 0x1.6c16c7af1c552p-4, 0x1.e6132399949p-4};
    const RayHit hit = ray_meets_triangle_element(mesh, 0, origin, direction, Positions::reference);
    ASSERT_TRUE(hit.found());
    EXPECT_NEAR(hit.t, 1.0, 1e-12);
    EXPECT_NEAR(hit.barycentric[1], 1.0, 1e-9);
    // the same ray from beyond the corner, pointing away, misses
    const Point beyond{origin[0] + 2 * direction[0], origin[1] + 2 * direction[1], origin[2] + 2 * direction[2]};
    EXPECT_FALSE(ray_meets_triangle_element(mesh, 0, beyond, direction, Positions::reference).found());
    EXPECT_TRUE(mesh.validate().ok());
}

// A needle triangle from EditJournalRandom.OctahedronSurface (SXK_SEED=3331795627, step 1372):
// edges of about 0.1 and an area of about 1e-19, and a ray that passes exactly through its corner
// p2 at t = 1 (origin + direction == p2 after rounding; the exact test says the ray meets it).
// The normal in doubles is rounding only and put the crossing at t = -0.9, which was clamped to 0.
TEST(SpatialIndex, ARayThroughTheCornerOfANeedleTriangleMeetsItThere) {
    Mesh mesh(2, 3);
    mesh.add_vertex({-0x1.f05abbbe300bap-6, 0x1.5562d5d08b0f2p-7, -0x1.181d44f049213p-4});
    mesh.add_vertex({-0x1.0125980194c4cp-3, -0x1.25abe8215d20ep-4, 0x1.60e181b9e1816p-4});
    mesh.add_vertex({-0x1.3f30ef795ac63p-4, -0x1.f5ff1ace977ep-6, 0x1.2310f3266180cp-7});
    const std::array<Simplex, 1> triangle{Simplex(+1, {0, 1, 2})};
    ASSERT_TRUE(mesh.assign_elements(triangle).ok());
    const Point origin{-0x1.34e7b66b87ef4p-3, -0x1.2a91d11cd77c3p-7, 0x1.1c764147789c8p-4};
    const Point direction{0x1.2a9e7d5db5185p-4, -0x1.60b632402bbfep-6, -0x1.f02845c558d8dp-5};
    const RayHit hit = ray_meets_triangle_element(mesh, 0, origin, direction, Positions::reference);
    ASSERT_TRUE(hit.found());
    EXPECT_NEAR(hit.t, 1.0, 1e-12);
    for (std::size_t k = 0; k < 3; ++k) EXPECT_NEAR(hit.point[k], mesh.reference(2)[k], 1e-12) << "coordinate " << k;
    // the index answers the same
    const SpatialIndex index(mesh);
    EXPECT_EQ(index.pick(origin, direction).t, hit.t);
    EXPECT_TRUE(mesh.validate().ok());
}

TEST(SpatialIndex, SegmentsOnTheUnitSquare) {
    Mesh mesh = test::unit_square();
    const SpatialIndex index(mesh);
    EXPECT_EQ(index.elements_crossed({0.25, 0.75, 0}, {0.75, 0.25, 0}), (std::vector<ElementId>{0, 1}));
    EXPECT_EQ(index.elements_crossed({0.9, 0.05, 0}, {0.95, 0.02, 0}), (std::vector<ElementId>{0}));
    EXPECT_EQ(index.elements_crossed({-1, 0.5, 0}, {-0.5, 0.5, 0}), (std::vector<ElementId>{}));
    // touching vertex 1, which only A has
    EXPECT_EQ(index.elements_crossed({1, 0, 0}, {2, 0, 0}), (std::vector<ElementId>{0}));
    // a point: the elements containing it
    EXPECT_EQ(index.elements_crossed({0.5, 0.5, 0}, {0.5, 0.5, 0}), (std::vector<ElementId>{0, 1}));
}

TEST(SpatialIndex, TriangleSweepOnTheUnitSquare) {
    Mesh mesh = test::unit_square();
    const SpatialIndex index(mesh);
    // the corner region x + y <= 0.5: both triangles, the bottom and the left edge
    const TriangleHits hits = index.elements_hit_by_triangle({-1, -1, 0}, {1.5, -1, 0}, {-1, 1.5, 0});
    EXPECT_EQ(hits.elements, (std::vector<ElementId>{0, 1}));
    ASSERT_EQ(hits.boundary_faces.size(), 2u);
    std::vector<std::vector<VertexId>> faces;
    for (const FaceId f : hits.boundary_faces) faces.push_back(face_vertices(mesh, f));
    std::sort(faces.begin(), faces.end());
    EXPECT_EQ(faces, (std::vector<std::vector<VertexId>>{{0, 1}, {0, 3}}));
    // inside A only, away from every boundary edge
    const TriangleHits inner = index.elements_hit_by_triangle({0.6, 0.1, 0}, {0.9, 0.1, 0}, {0.9, 0.4, 0});
    EXPECT_EQ(inner.elements, (std::vector<ElementId>{0}));
    EXPECT_TRUE(inner.boundary_faces.empty());
    // a degenerate blade is the segment between its farthest corners
    const TriangleHits flat = index.elements_hit_by_triangle({0.25, 0.75, 0}, {0.5, 0.5, 0}, {0.75, 0.25, 0});
    EXPECT_EQ(flat.elements, (std::vector<ElementId>{0, 1}));
}

TEST(SpatialIndex, ElementsWithAVertexInABoxOnTheUnitSquare) {
    Mesh mesh = test::unit_square();  // <0,1,2> and <0,2,3>
    const SpatialIndex index(mesh);
    EXPECT_EQ(index.elements_with_vertex_in_box({0.9, -0.1, 0}, {1.1, 0.1, 0}), std::vector<ElementId>{0});  // vertex 1
    EXPECT_EQ(index.elements_with_vertex_in_box({-1, 0.5, 7}, {0, 2, 9}), std::vector<ElementId>{1});        // vertex 3, z ignored
    EXPECT_EQ(index.elements_with_vertex_in_box({1, 1, 0}, {1, 1, 0}), (std::vector<ElementId>{0, 1}));      // vertex 2 exactly
    EXPECT_TRUE(index.elements_with_vertex_in_box({0.2, 0.2, 0}, {0.8, 0.8, 0}).empty());  // inside, no vertex
    EXPECT_TRUE(index.elements_with_vertex_in_box({1, 1, 0}, {0, 0, 0}).empty());          // low > high
    EXPECT_TRUE(mesh.validate().ok());
}

TEST(SpatialIndex, NearestBoundaryPointAndPickOnTheUnitSquare) {
    Mesh mesh = test::unit_square();
    const SpatialIndex index(mesh);
    const BoundaryPoint bottom = index.nearest_boundary_point({0.5, 0.2, 0});
    ASSERT_TRUE(bottom.found());
    EXPECT_EQ(face_vertices(mesh, bottom.face), (std::vector<VertexId>{0, 1}));
    EXPECT_EQ(bottom.element, 0u);
    EXPECT_DOUBLE_EQ(bottom.distance, 0.2);
    EXPECT_EQ(bottom.point, (Point{0.5, 0, 0}));
    EXPECT_DOUBLE_EQ(bottom.barycentric[0], 0.5);
    const BoundaryPoint right = index.nearest_boundary_point({2, 0.5, 0});
    EXPECT_EQ(face_vertices(mesh, right.face), (std::vector<VertexId>{1, 2}));
    EXPECT_DOUBLE_EQ(right.distance, 1.0);

    const RayHit out = index.pick({0.5, 0.5, 0}, {1, 0, 0});
    ASSERT_TRUE(out.found());
    EXPECT_EQ(face_vertices(mesh, out.face), (std::vector<VertexId>{1, 2}));
    EXPECT_EQ(out.element, 0u);
    EXPECT_DOUBLE_EQ(out.t, 0.5);
    EXPECT_EQ(out.point, (Point{1, 0.5, 0}));
    const RayHit in = index.pick({-1, 0.5, 0}, {2, 0, 0});
    ASSERT_TRUE(in.found());
    EXPECT_EQ(face_vertices(mesh, in.face), (std::vector<VertexId>{0, 3}));
    EXPECT_DOUBLE_EQ(in.t, 0.5);
    EXPECT_FALSE(index.pick({-1, 0.5, 0}, {-1, 0, 0}).found());
    EXPECT_FALSE(index.pick({-1, 0.5, 0}, {0, 0, 0}).found());
}

TEST(SpatialIndex, TetrahedraByHand) {
    Mesh mesh = test::kuhn_cube(1);  // six tetrahedra around the diagonal (0,0,0)-(1,1,1)
    const SpatialIndex index(mesh);
    const Location centre = index.locate({0.5, 0.5, 0.5});
    ASSERT_TRUE(centre.found());  // on the diagonal: any of the six
    const Location off = index.locate({0.7, 0.2, 0.1});
    ASSERT_TRUE(off.found());
    double sum = 0;
    for (const double w : off.barycentric) sum += w;
    EXPECT_NEAR(sum, 1.0, 1e-15);
    EXPECT_FALSE(index.locate({1.5, 0.5, 0.5}).found());
    EXPECT_EQ(index.elements_crossed({0.5, 0.5, 0.5}, {0.5, 0.5, 0.5}).size(), 6u);
    EXPECT_EQ(index.elements_crossed({-1, -1, -1}, {2, 2, 2}).size(), 6u);
    // the cube's surface: 12 boundary triangles, the nearest point on the face x = 1
    const BoundaryPoint nearest = index.nearest_boundary_point({1.25, 0.5, 0.25});
    ASSERT_TRUE(nearest.found());
    EXPECT_NEAR(nearest.distance, 0.25, 1e-15);
    for (std::size_t k = 0; k < 3; ++k) EXPECT_NEAR(nearest.point[k], (Point{1, 0.5, 0.25})[k], 1e-15);
    const RayHit hit = index.pick({0.3, 0.4, 5}, {0, 0, -1});
    ASSERT_TRUE(hit.found());
    EXPECT_NEAR(hit.t, 4.0, 1e-15);
    for (std::size_t k = 0; k < 3; ++k) EXPECT_NEAR(hit.point[k], (Point{0.3, 0.4, 1})[k], 1e-15);
    EXPECT_EQ(index.indexed_elements(), 6u);
    EXPECT_EQ(index.indexed_boundary_faces(), 12u);
}

TEST(SpatialIndex, SurfaceInSpaceLocatesWithinTheTolerance) {
    Mesh mesh = ops_driver::octahedron(1);
    const SpatialIndex index(mesh);
    EXPECT_NEAR(index.surface_tolerance(), 1e-9 * std::sqrt(12.0), 1e-14);
    // the centre of face <0,2,4> (the +x +y +z face) is on the surface
    const Location on = index.locate({1.0 / 3, 1.0 / 3, 1.0 / 3});
    ASSERT_TRUE(on.found());
    EXPECT_EQ(mesh.simplex(on.element).vertices()[0], 0u);
    for (int j = 0; j < 3; ++j) EXPECT_NEAR(on.barycentric[static_cast<std::size_t>(j)], 1.0 / 3, 1e-15);
    EXPECT_FALSE(index.locate({0, 0, 0}).found());
    EXPECT_FALSE(index.locate({0.34, 0.34, 0.34}).found());
    // a closed surface has no boundary; a ray hits the triangles themselves
    EXPECT_FALSE(index.nearest_boundary_point({3, 0, 0}).found());
    const RayHit hit = index.pick({3, 0.1, 0.2}, {-1, 0, 0});
    ASSERT_TRUE(hit.found());
    EXPECT_EQ(hit.face, invalid_id);
    EXPECT_NEAR(hit.t, 3 - 0.7, 1e-12);
    // a generous tolerance: the nearest triangle and the weights of the nearest point
    const SpatialIndex loose(mesh, SpatialIndexOptions{Positions::reference, 0.1});
    const Location near = loose.locate({0.36, 0.36, 0.36});
    ASSERT_TRUE(near.found());
    for (int j = 0; j < 3; ++j) EXPECT_NEAR(near.barycentric[static_cast<std::size_t>(j)], 1.0 / 3, 1e-12);
}

TEST(SpatialIndex, AgreesWithAScanOnAGridACubeAndASurface) {
    const std::uint64_t seed = test::seed_for("SpatialIndex.AgreesWithAScanOnAGridACubeAndASurface");
    std::mt19937_64 rng(seed);
    std::vector<Mesh> meshes;
    meshes.push_back(test::planar_grid(6));
    meshes.push_back(test::kuhn_cube(3));
    meshes.push_back(ops_driver::octahedron(2));
    for (Mesh& mesh : meshes) {
        const SpatialIndex index(mesh);
        test::expect_index_agrees(index, rng, 150, "dimension " + std::to_string(mesh.topological_dimension()) +
                                                       "/" + std::to_string(mesh.ambient_dimension()));
    }
}

// Large triangles oblique to the axes (a scalpel's sweep) are gathered from the boxes of their
// pieces (locate_triangle_sweep.cpp): on a cube of 16,464 tetrahedra, slivers and broad
// triangles in every direction meet what a scan finds, and so do triangles a hundred times the
// cube's size (more than the 1024 pieces the triangle is cut into before any lookup), with and
// without the boundary faces.
TEST(SpatialIndex, LongObliqueTrianglesMeetWhatAScanFinds) {
    const std::uint64_t seed = test::seed_for("SpatialIndex.LongObliqueTrianglesMeetWhatAScanFinds");
    std::mt19937_64 rng(seed);
    Mesh mesh = test::kuhn_cube(14);
    const SpatialIndex index(mesh);
    Point low{1e300, 1e300, 1e300}, high{-1e300, -1e300, -1e300};
    for (VertexId v = 0; v < mesh.vertex_count(); ++v)
        for (std::size_t k = 0; k < 3; ++k) {
            low[k] = std::min(low[k], mesh.reference(v)[k]);
            high[k] = std::max(high[k], mesh.reference(v)[k]);
        }
    std::uniform_real_distribution<double> unit(-0.2, 1.2);
    auto anywhere = [&] {
        Point x{};
        for (std::size_t k = 0; k < 3; ++k) x[k] = low[k] + unit(rng) * (high[k] - low[k]);
        return x;
    };
    for (int i = 0; i < 60; ++i) {
        Point a = anywhere(), b = anywhere(), c = anywhere();
        if (i % 2 == 0)  // a sliver: c a little off a
            for (std::size_t k = 0; k < 3; ++k) c[k] = a[k] + (c[k] - a[k]) * 1e-3;
        if (i % 5 == 4)  // a hundred times larger, about the cube's middle
            for (Point* x : {&a, &b, &c})
                for (std::size_t k = 0; k < 3; ++k) {
                    const double middle = (low[k] + high[k]) / 2;
                    (*x)[k] = middle + 100 * ((*x)[k] - middle);
                }
        const TriangleHits hits = index.elements_hit_by_triangle(a, b, c);
        const TriangleHits scanned = test::scan_triangle(mesh, a, b, c, Positions::deformed);
        EXPECT_EQ(hits.elements, scanned.elements) << "triangle " << i;
        std::vector<FaceId> faces = scanned.boundary_faces;
        std::sort(faces.begin(), faces.end());
        EXPECT_EQ(hits.boundary_faces, faces) << "triangle " << i;
        const TriangleHits elements_only = index.elements_hit_by_triangle(a, b, c, TriangleHitsOf::elements);
        EXPECT_EQ(elements_only.elements, scanned.elements) << "triangle " << i;
        EXPECT_TRUE(elements_only.boundary_faces.empty()) << "triangle " << i;
        const TriangleHits faces_only = index.elements_hit_by_triangle(a, b, c, TriangleHitsOf::boundary_faces);
        EXPECT_TRUE(faces_only.elements.empty()) << "triangle " << i;
        EXPECT_EQ(faces_only.boundary_faces, faces) << "triangle " << i;
    }
    EXPECT_TRUE(mesh.validate().ok());
}

// Moving vertices re-boxes their stars in the index of the set that moved, and only there.
TEST(SpatialIndex, FollowsMovesInItsOwnPositionSet) {
    const std::uint64_t seed = test::seed_for("SpatialIndex.FollowsMovesInItsOwnPositionSet");
    std::mt19937_64 rng(seed);
    Mesh mesh = test::kuhn_cube(3);
    const SpatialIndex reference(mesh, Positions::reference);
    const SpatialIndex deformed(mesh, Positions::deformed);
    // stretch the deformed cube along x: every interior vertex and the far face move
    std::vector<VertexId> moved;
    std::vector<Point> to;
    for (VertexId v = 0; v < mesh.vertex_count(); ++v) {
        const Point& p = mesh.deformed(v);
        moved.push_back(v);
        to.push_back({p[0] * 1.5 + 0.01 * p[1], p[1], p[2] + 0.02 * p[0]});
    }
    ASSERT_TRUE(mesh.move_vertices(moved, to, PositionSet::deformed, MoveCheck{true, true}).ok());
    EXPECT_TRUE(deformed.locate({4.4, 1.5, 1.5}).found());
    EXPECT_FALSE(reference.locate({4.4, 1.5, 1.5}).found());
    test::expect_index_agrees(reference, rng, 60, "reference");
    test::expect_index_agrees(deformed, rng, 60, "deformed");
    // one interior vertex, (1,1,2), a little in the reference positions
    const std::array<VertexId, 1> one{static_cast<VertexId>((2 * 4 + 1) * 4 + 1)};
    const std::array<Point, 1> there{Point{1.2, 1.1, 1.9}};
    ASSERT_TRUE(mesh.move_vertices(one, there, PositionSet::reference, MoveCheck{true, true}).ok());
    test::expect_index_agrees(reference, rng, 40, "reference after one move");
    test::expect_index_agrees(deformed, rng, 40, "deformed after one move");
    ASSERT_TRUE(mesh.validate(ValidateOptions{true}).ok());
}

// A simulation writes every deformed position each frame; the index refits its trees: an element
// or boundary face still inside its box costs a test, one that left it gets a box with a margin,
// one by one when few left, by one bulk load when many did. Frames of every kind: all of the cube
// moved far (the bulk load), all of it a little (inside the margins), one corner region far and
// the rest still (one by one), with edits between them (the edits' tight boxes among the grown
// ones). After each the trees hold every live id once with a box that covers it, and every query
// agrees with a scan.
TEST(SpatialIndex, FollowsASimulationsFramesByRefitting) {
    const std::uint64_t seed = test::seed_for("SpatialIndex.FollowsASimulationsFramesByRefitting");
    std::mt19937_64 rng(seed);
    Mesh mesh = test::kuhn_cube(4);
    const SpatialIndex deformed(mesh, Positions::deformed);
    std::vector<VertexId> all;
    for (VertexId v = 0; v < mesh.vertex_count(); ++v) all.push_back(v);
    // z bent by `bend` along x, and the corner region x, y < 1.5 pushed up by `corner`
    const auto frame = [&](double bend, double corner) {
        std::vector<Point> to;
        for (const VertexId v : all) {
            const Point& r = mesh.reference(v);
            const double push = r[0] < 1.5 && r[1] < 1.5 ? corner : 0;
            to.push_back({r[0], r[1], r[2] + bend * std::sin(3.14159 * r[0] / 4) + push});
        }
        return mesh.move_vertices(all, to, PositionSet::deformed, MoveCheck{true, true});
    };
    const std::array<std::pair<double, double>, 8> frames{
        std::pair{0.3, 0.0}, {0.31, 0.0}, {0.32, 0.0}, {0.32, 0.4}, {0.33, 0.41}, {-0.2, 0.0}, {-0.21, 0.2}, {0, 0}};
    for (std::size_t i = 0; i < frames.size(); ++i) {
        ASSERT_TRUE(frame(frames[i].first, frames[i].second).ok()) << "frame " << i;
        test::expect_index_agrees(deformed, rng, 30, "frame " + std::to_string(i));
        if (i % 3 == 1) {
            // an edit between frames: a random interior edge split where the frame left it
            std::vector<VertexId> ends;
            for (ElementId t = static_cast<ElementId>(rng() % mesh.element_capacity());; t = (t + 1) % mesh.element_capacity())
                if (mesh.is_element(t)) {
                    ends = {mesh.simplex(t).vertex(0), mesh.simplex(t).vertex(1)};
                    break;
                }
            ASSERT_TRUE(split_edge(mesh, ends[0], ends[1], 0.5).ok()) << "frame " << i;
            all.push_back(static_cast<VertexId>(mesh.vertex_count() - 1));
            test::expect_index_agrees(deformed, rng, 30, "after the edit of frame " + std::to_string(i));
        }
    }
    ASSERT_TRUE(mesh.validate(ValidateOptions{true}).ok());
}

TEST(SpatialIndex, FollowsEditsAndRollbacks) {
    const std::uint64_t seed = test::seed_for("SpatialIndex.FollowsEditsAndRollbacks");
    std::mt19937_64 rng(seed);
    Mesh mesh = test::planar_grid(4);
    const SpatialIndex index(mesh);
    EditJournal journal(mesh);
    journal.checkpoint();
    ASSERT_TRUE(split_edge(mesh, 0, 6, 0.5).ok());
    ASSERT_TRUE(split_edge(mesh, 6, 12, 0.25).ok());
    ASSERT_TRUE(split_edge(mesh, 0, 1, 0.5).ok());  // on the boundary: the face tree follows
    test::expect_index_agrees(index, rng, 40, "after three splits");
    ASSERT_TRUE(journal.rollback().ok());
    test::expect_index_agrees(index, rng, 40, "after the rollback");
    EXPECT_EQ(index.indexed_elements(), 32u);
    EXPECT_EQ(index.indexed_boundary_faces(), 16u);
    // many splits taken back at once: the rollback retires their ids, more than the tree keeps
    // (locate_trees.hpp removes the oldest), and the next splits hand the same ids out again
    for (int round = 0; round < 2; ++round) {
        journal.checkpoint();
        for (int k = 0; k < 80; ++k) {
            const ElementId t = static_cast<ElementId>(rng() % mesh.element_capacity());
            if (!mesh.is_element(t)) continue;
            const Simplex& s = mesh.simplex(t);
            (void)split_edge(mesh, s.vertex(0), s.vertex(1), 0.5);
        }
        EXPECT_GT(index.indexed_elements(), 100u);
        test::expect_index_agrees(index, rng, 20, "after 80 splits");
        ASSERT_TRUE(journal.rollback().ok());
        test::expect_index_agrees(index, rng, 20, "after rolling them back");
        EXPECT_EQ(index.indexed_elements(), 32u);
    }
    ASSERT_TRUE(mesh.validate().ok());
}

TEST(SpatialIndex, DetachesWhenDestroyedAndRebuildsOnAssignment) {
    Mesh mesh = test::planar_grid(2);
    {
        const SpatialIndex index(mesh);
        EXPECT_EQ(index.indexed_elements(), 8u);
        const Mesh bigger = test::planar_grid(3);
        mesh = bigger;  // a copy assignment re-initialises the watchers
        EXPECT_EQ(index.indexed_elements(), 18u);
        EXPECT_TRUE(index.validate().ok());
    }
    ASSERT_TRUE(split_edge(mesh, 0, 5, 0.5).ok());  // nobody watches any more
    ASSERT_TRUE(mesh.validate().ok());
}

TEST(SpatialIndex, FlatElementsContainNothing) {
    Mesh mesh(2, 2);
    for (const Point& p : {Point{0, 0, 0}, Point{1, 0, 0}, Point{2, 0, 0}, Point{1, 1, 0}}) mesh.add_vertex(p);
    const std::array<Simplex, 2> triangles{Simplex(+1, {0, 1, 3}), Simplex(+1, {1, 2, 3})};
    ASSERT_TRUE(mesh.assign_elements(triangles).ok());
    const SpatialIndex index(mesh);
    EXPECT_TRUE(index.locate({1, 0.5, 0}).found());
    // move vertex 3 onto the x axis: both triangles flat, nothing contains anything
    const std::array<VertexId, 1> v{3};
    const std::array<Point, 1> onto{Point{1.5, 0, 0}};
    ASSERT_TRUE(mesh.move_vertices(v, onto, PositionSet::reference).ok());
    EXPECT_FALSE(index.locate({1, 0, 0}).found());
    EXPECT_TRUE(index.elements_crossed({-1, 0, 0}, {3, 0, 0}).empty());
    EXPECT_TRUE(index.validate().ok());
    ASSERT_TRUE(mesh.validate().ok());
}

TEST(Walks, LocateTriangleAndTetrahedronWithoutAnIndex) {
    Mesh grid = test::planar_grid(5);
    const ElementId t = locate_triangle(grid, {3.7, 1.2, 0});
    ASSERT_NE(t, invalid_id);
    EXPECT_TRUE(locate_in_element(grid, t, {3.7, 1.2, 0}, Positions::reference).found());
    EXPECT_EQ(locate_triangle(grid, {6, 1, 0}), invalid_id);
    EXPECT_EQ(walk_to_point(grid, {3.7, 1.2, 0}, 0, Positions::reference, 100), t);
    EXPECT_EQ(walk_to_point(grid, {3.7, 1.2, 0}, 0, Positions::reference, 2), invalid_id);  // gives up
    Mesh cube = test::kuhn_cube(4);
    const ElementId u = locate_tetrahedron(cube, {3.2, 0.4, 2.9}, invalid_id);
    ASSERT_NE(u, invalid_id);
    EXPECT_TRUE(locate_in_element(cube, u, {3.2, 0.4, 2.9}, Positions::reference).found());
    EXPECT_EQ(locate_tetrahedron(cube, {5, 0.4, 2.9}, u), invalid_id);
    EXPECT_EQ(locate_tetrahedron(grid, {1, 1, 0}, 0), invalid_id);
    EXPECT_EQ(locate_triangle(cube, {1, 1, 1}), invalid_id);
}

// Refines a copy of `start` without an index and one with (refine(mesh, nullptr or &index) says
// what it did): the same answer and the same mesh, and the index in step with it.
template <class Refine>
void expect_refines_alike(const Mesh& start, Refine refine) {
    Mesh plain = start, indexed = start;
    const SpatialIndex index(indexed);
    EXPECT_EQ(refine(plain, nullptr), refine(indexed, &index));
    EXPECT_TRUE(ops_driver::snapshot(plain) == ops_driver::snapshot(indexed));
    EXPECT_TRUE(index.validate().ok());
    ASSERT_TRUE(indexed.validate().ok());
}

// The index changes how x is found, not what is refined (x inside an element: one answer).
TEST(RefineAroundWithIndex, RefinesAsWithout) {
    expect_refines_alike(test::planar_grid(8), [](Mesh& mesh, const SpatialIndex* index) {
        const Point x{3.3, 5.6, 0};
        const auto done = index ? refine_around(mesh, x, 0.1, *index) : refine_around(mesh, x, 0.1);
        return done ? std::to_string(done->bisections) + " bisections, element " + std::to_string(done->element)
                    : done.reason();
    });
    expect_refines_alike(test::kuhn_cube(3), [](Mesh& mesh, const SpatialIndex* index) {
        const Point y{1.3, 2.1, 0.7};
        const auto done = index ? refine_around_tetrahedra(mesh, y, 0.4, *index) : refine_around_tetrahedra(mesh, y, 0.4);
        return done ? std::to_string(*done) + " bisections" : done.reason();
    });
}

TEST(RefineAroundWithIndex, RefusesAForeignIndexAndPointsOutside) {
    Mesh grid = test::planar_grid(8);
    Mesh other = grid;
    const SpatialIndex index(grid);
    const SpatialIndex deformed(grid, Positions::deformed);
    EXPECT_EQ(refine_around(other, {3, 3, 0}, 0.1, index).reason(),
              "refine_around: the spatial index watches another mesh");
    EXPECT_EQ(refine_around(grid, {3, 3, 0}, 0.1, deformed).reason(),
              "refine_around: the spatial index is over the deformed positions; refinement locates in the "
              "reference positions");
    EXPECT_EQ(refine_around(grid, {9, 1, 0}, 0.1, index).reason(), "refine_around: point (9, 1) is not in the mesh");
    EXPECT_EQ(refine_around(other, {3, 3, 0}, 0.1, index).code(), RefusalCode::bad_argument);
    EXPECT_EQ(refine_around(grid, {3, 3, 0}, 0.1, deformed).code(), RefusalCode::bad_argument);
    EXPECT_EQ(refine_around(grid, {9, 1, 0}, 0.1, index).code(), RefusalCode::not_found);
    Mesh cube = test::kuhn_cube(3);
    Mesh other_cube = cube;
    const SpatialIndex cube_index(cube);
    EXPECT_EQ(refine_around_tetrahedra(cube, {5, 1, 1}, 0.4, cube_index).reason(),
              "refine_around_tetrahedra: point (5, 1, 1) is not in the mesh");
    EXPECT_EQ(refine_around_tetrahedra(other_cube, {1, 1, 1}, 0.4, cube_index).reason(),
              "refine_around_tetrahedra: the spatial index watches another mesh");
    EXPECT_EQ(refine_around_tetrahedra(cube, {5, 1, 1}, 0.4, cube_index).code(), RefusalCode::not_found);
    EXPECT_EQ(refine_around_tetrahedra(other_cube, {1, 1, 1}, 0.4, cube_index).code(), RefusalCode::bad_argument);
    auto state = TetBisection::for_kuhn_mesh(cube);
    ASSERT_TRUE(state.ok()) << state.reason();
    const auto refined = refine_around_tetrahedra(*state, {1.3, 2.1, 0.7}, 0.4, cube_index);
    ASSERT_TRUE(refined.ok()) << refined.reason();
    EXPECT_GT(*refined, 0u);
    EXPECT_TRUE(cube_index.validate().ok());
    ASSERT_TRUE(grid.validate().ok());
    ASSERT_TRUE(cube.validate().ok());
}

}  // namespace
}  // namespace sxk
