// remove_node (thesis §5.3.1, Fig. 5.10): ears flipped on a scratch link, one replace_elements.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <random>
#include <set>

#include "ops/split_collapse_fixtures.hpp"
#include "sxk/ops/flip_edge.hpp"
#include "sxk/ops/make_delaunay_by_flips.hpp"
#include "sxk/ops/remove_node.hpp"
#include "sxk/predicates.hpp"
#include "sxk/traversal.hpp"

namespace sxk {
namespace {

using test::expect_same_state;

double signed_area(const Mesh& mesh, ElementId t) {
    const Simplex& s = mesh.simplex(t);
    const Point& a = mesh.reference(s.vertex(0));
    const Point& b = mesh.reference(s.vertex(1));
    const Point& c = mesh.reference(s.vertex(2));
    return s.sign() * 0.5 * ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]));
}

double total_area(const Mesh& mesh) {
    double area = 0;
    for (ElementId t : elements(mesh))
        area += signed_area(mesh, t);
    return area;
}

bool all_edges_locally_delaunay(const Mesh& mesh) {
    for (ElementId t : elements(mesh))
        for (FaceId f : mesh.faces(t))
            if (!is_locally_delaunay(mesh, f))
                return false;
    return true;
}

// A fan around vertex 0 at `center` with the link `ring` (counter-clockwise): vertices 1..n.
Mesh fan(const Point& center, const std::vector<Point>& ring) {
    Mesh mesh(2, 2);
    mesh.add_vertex(center);
    for (const Point& p : ring)
        mesh.add_vertex(p);
    std::vector<Simplex> triangles;
    const auto n = static_cast<VertexId>(ring.size());
    for (VertexId i = 0; i < n; ++i)
        triangles.emplace_back(+1, std::initializer_list<VertexId>{0, i + 1, (i + 1) % n + 1});
    EXPECT_TRUE(mesh.assign_elements(triangles).ok());
    return mesh;
}

// The grid vertex (2,2) of planar_grid(4) has degree 6 (the diagonals run south-west to
// north-east); its hexagonal hole gets 4 triangles.
//
//   (1,3) -- (2,3)            the six neighbours (1,2), (2,3), (3,3), (3,2), (2,1), (1,1)
//     |      /   |            of v = 12 = (2,2) form a hexagon; it is cut into four
//     |    /     |            triangles and v stays, in no element
//   (1,2) -- v -- (3,2)
//     |     /    |
//   (1,1) -- (2,1)
TEST(RemoveNode, InteriorVertexOfTheGrid) {
    Mesh mesh = test::planar_grid(4);
    for (ElementId t : elements(mesh))
        mesh.set_label(t, 3);
    const std::vector<FaceId> boundary = mesh.boundary_faces();
    const std::vector<ElementId> around = star(mesh, 12);
    ASSERT_EQ(around.size(), 6u);

    const auto removed = remove_node(mesh, 12);
    ASSERT_TRUE(removed.ok()) << removed.reason();
    ASSERT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
    EXPECT_EQ(removed->size(), 4u);
    EXPECT_EQ(mesh.element_count(), 32u - 6u + 4u);
    EXPECT_EQ(mesh.vertex_element(12), invalid_id);
    EXPECT_EQ(mesh.vertex_count(), 25u);
    EXPECT_TRUE(test::all_strictly_positive(mesh));
    EXPECT_DOUBLE_EQ(total_area(mesh), 16.0);
    EXPECT_EQ(mesh.boundary_faces(), boundary);
    for (ElementId t : *removed) {
        EXPECT_FALSE(mesh.simplex(t).contains(12));
        EXPECT_EQ(mesh.label(t), 3);
    }
    EXPECT_TRUE(all_edges_locally_delaunay(mesh));
}

// Three triangles around v = 3 become the one triangle <0,1,2>; the hull edges keep their
// FaceIds (face reuse), so the boundary is the same set of faces.
//
//   2
//   | `.
//   |  3 `.        <0,1,3>, <1,2,3>, <2,0,3>  --->  <0,1,2>
//   |       `.
//   0 ------- 1
TEST(RemoveNode, DegreeThreeVertexLeavesOneTriangle) {
    Mesh mesh(2, 2);
    mesh.add_vertex({0, 0, 0});
    mesh.add_vertex({4, 0, 0});
    mesh.add_vertex({0, 4, 0});
    mesh.add_vertex({1, 1, 0});
    const std::array<Simplex, 3> triangles{Simplex(+1, {0, 1, 3}), Simplex(+1, {1, 2, 3}),
                                           Simplex(+1, {2, 0, 3})};
    ASSERT_TRUE(mesh.assign_elements(triangles).ok());
    const std::vector<FaceId> boundary = mesh.boundary_faces();

    const auto removed = remove_node(mesh, 3);
    ASSERT_TRUE(removed.ok()) << removed.reason();
    ASSERT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
    ASSERT_EQ(removed->size(), 1u);
    EXPECT_EQ(mesh.simplex(removed->front()), Simplex(+1, {0, 1, 2}));
    EXPECT_EQ(mesh.element_count(), 1u);
    EXPECT_EQ(mesh.boundary_faces(), boundary);
    EXPECT_TRUE(test::all_strictly_positive(mesh));
}

// A star whose link is a non-convex octagon (radii alternate 1 at the odd ids and 0.3 at the
// even ones): the inner vertices 2, 4, 6, 8 are reflex corners, so the first ears are the
// spikes at 1, 3, 5, 7; five ears are cut before the last triangle.
//
//               3
//              /|\ .
//        5 -- 4 | 2 -- 1         (0 in the middle; the inner vertices 2, 4, 6, 8 are reflex
//             ..0..              corners of the link polygon)
TEST(RemoveNode, ReflexLinkNeedsSeveralEars) {
    std::vector<Point> ring;
    for (int k = 0; k < 8; ++k) {
        const double angle = 2 * M_PI * k / 8, radius = k % 2 == 0 ? 1.0 : 0.3;
        ring.push_back({radius * std::cos(angle), radius * std::sin(angle), 0});
    }
    Mesh mesh = fan({0, 0, 0}, ring);
    const double area = total_area(mesh);

    const auto removed = remove_node(mesh, 0);
    ASSERT_TRUE(removed.ok()) << removed.reason();
    ASSERT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
    EXPECT_EQ(removed->size(), 6u);
    EXPECT_EQ(mesh.element_count(), 6u);
    EXPECT_TRUE(test::all_strictly_positive(mesh));
    EXPECT_NEAR(total_area(mesh), area, 1e-12);
    EXPECT_EQ(mesh.boundary_face_count(), 8u);
    // the Delaunay triangulation of the hole (ear clipping, then the Lawson flips): the four
    // spikes <inner, outer, inner> and two triangles on the inner square 2-4-6-8
    int spikes = 0;
    for (ElementId t : elements(mesh)) {
        int outer = 0;
        for (VertexId v : mesh.simplex(t).vertices())
            outer += (v % 2 == 1) ? 1 : 0;
        EXPECT_LE(outer, 1) << to_text(mesh.simplex(t));
        spikes += outer;
    }
    EXPECT_EQ(spikes, 4);
}

// v at the crossing of the diagonals of a square link: every thesis ear flip would produce a
// flat triangle (v on the chord), so the general ear of the polygon is taken.
//
//        2
//      / | \ .
//    3 - 0 - 1       --->   two triangles on a diagonal of 1-2-3-4
//      \ | / .
//        4
TEST(RemoveNode, SquareLinkWithCentreOnTheDiagonals) {
    Mesh mesh = fan({0, 0, 0}, {{1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}});
    const auto removed = remove_node(mesh, 0);
    ASSERT_TRUE(removed.ok()) << removed.reason();
    ASSERT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
    EXPECT_EQ(removed->size(), 2u);
    EXPECT_TRUE(test::all_strictly_positive(mesh));
    EXPECT_DOUBLE_EQ(total_area(mesh), 2.0);
}

// A jittered grid made Delaunay: removing an interior vertex leaves a Delaunay mesh.
TEST(RemoveNode, JitteredDelaunayGridStaysDelaunay) {
    Mesh mesh = test::planar_grid(5);
    std::mt19937 random(7);
    std::uniform_real_distribution<double> jitter(-0.3, 0.3);
    for (int j = 1; j < 5; ++j)
        for (int i = 1; i < 5; ++i) {
            const auto v = static_cast<VertexId>(j * 6 + i);
            const Point p{i + jitter(random), j + jitter(random), 0};
            mesh.set_reference(v, p);
            mesh.set_deformed(v, p);
        }
    ASSERT_TRUE(make_delaunay_by_flips(mesh).ok());
    ASSERT_TRUE(all_edges_locally_delaunay(mesh));
    const std::size_t degree = star(mesh, 14).size();

    const auto removed = remove_node(mesh, 14);
    ASSERT_TRUE(removed.ok()) << removed.reason();
    ASSERT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
    EXPECT_EQ(removed->size(), degree - 2);
    EXPECT_TRUE(test::all_strictly_positive(mesh));
    EXPECT_TRUE(all_edges_locally_delaunay(mesh));
    EXPECT_NEAR(total_area(mesh), 25.0, 1e-12);
}

// ---- refusals: exact reason, state unchanged -------------------------------------------------

void expect_refused(Mesh& mesh, VertexId v, RefusalCode code, const std::string& reason) {
    const Mesh before = mesh;
    const auto removed = remove_node(mesh, v);
    ASSERT_FALSE(removed.ok());
    EXPECT_EQ(removed.reason(), reason);
    EXPECT_EQ(removed.code(), code);
    expect_same_state(mesh, before);
    EXPECT_EQ(mesh.face_labels(), before.face_labels());
    EXPECT_TRUE(mesh.validate().ok());
}

TEST(RemoveNode, RefusesWhatIsNotARemovableVertex) {
    Mesh mesh = test::unit_square();
    expect_refused(mesh, 99, RefusalCode::not_found, "remove_node: 99 is not a vertex");
    expect_refused(mesh, 0, RefusalCode::moves_boundary,
                   "remove_node: vertex 0 is on the boundary and the boundary is not straight "
                   "there (its removal "
                   "would change the domain)");
    mesh.add_vertex({5, 5, 0});
    expect_refused(mesh, 4, RefusalCode::not_applicable, "remove_node: vertex 4 is in no element");
    Mesh grid = test::planar_grid(3);
    expect_refused(grid, 3, RefusalCode::moves_boundary,
                   "remove_node: vertex 3 is on the boundary and the boundary is not straight "
                   "there (its removal "
                   "would change the domain)");
    // straight in the reference positions only
    grid.set_deformed(1, {1, -0.25, 0});
    expect_refused(grid, 1, RefusalCode::moves_boundary,
                   "remove_node: vertex 1 is on the boundary and the boundary is not straight "
                   "there (its removal "
                   "would change the domain)");
}

// A vertex on a straight piece of boundary: its fan becomes a triangulation of the polygon
// closed by the edge 0-2, which takes over the face label of the two boundary edges it replaces.
//
//   4 ---- 5 ---- 6            4 ---- 5 ---- 6
//   |    / |    / |            |    /   `.   |
//   |  /   |  /   |    --->    |  /        `.|
//   0 ---- 1 ---- 2            0 ------------2      (1 stays, in no element)
TEST(RemoveNode, VertexOnAStraightBoundary) {
    Mesh mesh = test::planar_grid(3);
    mesh.face_labels()[Simplex(+1, {0, 1})] = 7;
    mesh.face_labels()[Simplex(+1, {1, 2})] = 7;
    const auto removed = remove_node(mesh, 1);
    ASSERT_TRUE(removed.ok()) << removed.reason();
    ASSERT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
    EXPECT_EQ(removed->size(), 2u);
    EXPECT_EQ(mesh.element_count(), 17u);
    EXPECT_EQ(mesh.boundary_face_count(), 11u);
    EXPECT_NE(mesh.find_boundary_face(Simplex(+1, {0, 2})), invalid_id);
    EXPECT_TRUE(test::all_strictly_positive(mesh));
    EXPECT_DOUBLE_EQ(total_area(mesh), 9.0);
    EXPECT_EQ(mesh.face_labels().size(), 1u);
    EXPECT_EQ(mesh.face_labels().at(Simplex(+1, {0, 2})), 7);
    EXPECT_EQ(mesh.vertex_element(1), invalid_id);
}

TEST(RemoveNode, RefusesBoundaryEdgesWithDifferentFaceLabels) {
    Mesh mesh = test::planar_grid(3);
    mesh.face_labels()[Simplex(+1, {0, 1})] = 7;
    expect_refused(
        mesh, 1, RefusalCode::label_conflict,
        "remove_node: the boundary edges at vertex 1 carry different face labels (7 and none)");
    mesh.face_labels()[Simplex(+1, {1, 2})] = 8;
    expect_refused(
        mesh, 1, RefusalCode::label_conflict,
        "remove_node: the boundary edges at vertex 1 carry different face labels (7 and 8)");
}

TEST(RemoveNode, RefusesTetrahedraAndAVertexOfATetrahedronsSurface) {
    Mesh cube = test::kuhn_cube(2);
    expect_refused(cube, 13, RefusalCode::wrong_dimension,
                   "remove_node: needs a triangle mesh (topological dimension 2)");
    Mesh surface(2, 3);
    for (const Point& p : {Point{0, 0, 0}, Point{1, 0, 0}, Point{0, 1, 0}, Point{0, 0, 1}})
        surface.add_vertex(p);
    const std::array<Simplex, 4> faces{Simplex(+1, {0, 2, 1}), Simplex(+1, {0, 1, 3}),
                                       Simplex(+1, {1, 2, 3}), Simplex(+1, {0, 3, 2})};
    ASSERT_TRUE(surface.assign_elements(faces).ok());
    // its three neighbours' triangle is the tetrahedron's fourth face already (thesis Fig. 5.9)
    expect_refused(surface, 0, RefusalCode::not_manifold,
                   "remove_node: element -<1,2,3> already exists as an element that stays (invariant 7.4)");
}

// A vertex of a curved surface (a 6 x 6 grid lifted onto z = 0.3 sin x cos y, the centre raised
// higher still): its star becomes degree - 2 triangles facing up as the old ones did, and every edge
// of the hole that a valid flip could change is Delaunay unfolded (thesis §5.3.1).
TEST(RemoveNode, RemovesAVertexOfACurvedSurfaceByEars) {
    const Mesh flat = test::planar_grid(6);
    Mesh surface(2, 3);
    for (VertexId v = 0; v < flat.vertex_count(); ++v) {
        const Point& p = flat.reference(v);
        surface.add_vertex({p[0], p[1], 0.3 * std::sin(p[0]) * std::cos(p[1]) + (v == 24 ? 0.4 : 0.0)});
    }
    std::vector<Simplex> triangles;
    for (const ElementId t : elements(flat)) triangles.push_back(flat.simplex(t));
    ASSERT_TRUE(surface.assign_elements(triangles).ok());
    const std::size_t degree = star(surface, 24).size();
    const std::size_t before = surface.element_count();
    const auto removed = remove_node(surface, 24);
    ASSERT_TRUE(removed.ok()) << removed.reason();
    ASSERT_TRUE(surface.validate().ok());
    EXPECT_EQ(removed->size(), degree - 2);
    EXPECT_EQ(surface.element_count(), before - 2);
    for (const ElementId t : *removed) {
        const auto& s = surface.simplex(t);
        const Point &a = surface.deformed(s.vertex(0)), &b = surface.deformed(s.vertex(1)),
                    &c = surface.deformed(s.vertex(2));
        // facing up: the normal's dot product with +z, through a flat reference triangle
        const Point o{0, 0, 0}, x{1, 0, 0}, y{0, 1, 0};
        EXPECT_EQ(normal_alignment(a, b, c, o, x, y) == Sign::positive, s.sign() > 0) << t;
        for (const FaceId f : surface.faces(t)) {
            if (surface.mate(f) == invalid_id) continue;
            const ElementId other = surface.face_element(surface.mate(f));
            if (std::find(removed->begin(), removed->end(), other) == removed->end()) continue;
            Mesh trial = surface;  // a flip there refused: the edge stays, as a constraint would
            EXPECT_TRUE(is_locally_delaunay(surface, f) || !flip_edge(trial, f).ok()) << t;
        }
    }
    EXPECT_EQ(star(surface, 24).size(), 0u);
}

TEST(RemoveNode, RefusesMixedLabels) {
    Mesh mesh = test::planar_grid(4);
    const std::vector<ElementId> around = star(mesh, 12);
    mesh.set_label(around[2], 5);
    mesh.set_label(around[4], -1);
    expect_refused(mesh, 12, RefusalCode::label_conflict,
                   "remove_node: the star of vertex 12 mixes element labels -1 and 5");
}

// The interior edge from v = 12 = (2,2) to (3,2) carries a face label (say an interface drawn
// as edges): removing v would drop it.
TEST(RemoveNode, RefusesALabelledInteriorEdge) {
    Mesh mesh = test::planar_grid(4);
    mesh.face_labels()[Simplex(+1, {12, 13})] = 6;
    ASSERT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
    expect_refused(mesh, 12, RefusalCode::label_conflict,
                   "remove_node: the edge +<12,13> at vertex 12 carries face label 6 (a constraint)");
}

TEST(RemoveNode, RefusesAStarInvertedInTheDeformedPositions) {
    Mesh mesh = test::planar_grid(4);
    mesh.set_deformed(12, {3.5, 2.2, 0});  // beyond the neighbour (3,2): some triangles fold
    ElementId inverted = invalid_id;
    for (ElementId t : star(mesh, 12))
        if (inverted == invalid_id &&
            element_orientation(mesh, t, Positions::deformed) != Sign::positive)
            inverted = t;
    ASSERT_NE(inverted, invalid_id);
    expect_refused(
        mesh, 12, RefusalCode::not_applicable,
        "remove_node: element " + std::to_string(inverted) +
            " of the star of vertex 12 is not counter-clockwise in the deformed positions");
}

// The link is a dart (reflex at w0 = 1) in the reference positions and the same dart turned by
// one vertex (reflex at w1 = 2) in the deformed ones: the ears are {2, 4} in one set and
// {1, 3} in the other, so no triangulation of the hole is valid in both.
//
//   reference:      2                deformed:  the labels shifted by one
//                 / |  \                         around the same shape
//              3 -- 0 -1 |
//                 \ |  /
//                   4
TEST(RemoveNode, RefusesWhenNoEarIsValidInBothPositionSets) {
    const Point v{-0.5, 0, 0};
    const std::vector<Point> ring{{-0.3, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}};
    Mesh mesh = fan(v, ring);
    for (VertexId i = 0; i < 4; ++i)
        mesh.set_deformed(i + 1, ring[(i + 3) % 4]);
    ASSERT_TRUE(test::all_strictly_positive(mesh));
    expect_refused(mesh, 0, RefusalCode::not_applicable,
                   "remove_node: no ear of the link of vertex 0 is valid in both the reference and "
                   "the deformed positions");
}

// ---- property: many removals from a random Delaunay mesh --------------------------------------

// Random points in the unit square (its sides regularly sampled) triangulated as a jittered grid
// and made Delaunay; then random interior vertices are removed. After each removal: validate, every
// triangle strictly counter-clockwise (exact orient2d, both position sets), the area of the
// square, and every edge locally Delaunay (the mesh was Delaunay, so it stays Delaunay). Then
// the vertices on the sides (straight boundary) are removed too, down to the two triangles of
// the square. SXK_SEED=<n> replays a run.
TEST(RemoveNode, RandomRemovalsKeepADelaunayMesh) {
    std::uint32_t seed = std::random_device{}();
    if (const char* given = std::getenv("SXK_SEED"))
        seed = static_cast<std::uint32_t>(std::strtoul(given, nullptr, 10));
    std::cout << "remove_node random removals seed " << seed << '\n';
    SCOPED_TRACE("seed " + std::to_string(seed));
    std::mt19937 random(seed);

    const int n = 12;
    Mesh mesh = test::planar_grid(n);
    std::uniform_real_distribution<double> jitter(-0.2, 0.2);
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
            const bool inside = i > 0 && i < n && j > 0 && j < n;
            const auto v = static_cast<VertexId>(j * (n + 1) + i);
            const Point p{(i + (inside ? jitter(random) : 0.0)) / n,
                          (j + (inside ? jitter(random) : 0.0)) / n, 0};
            mesh.set_reference(v, p);
            mesh.set_deformed(v, p);
        }
    ASSERT_TRUE(test::all_strictly_positive(mesh));
    ASSERT_TRUE(make_delaunay_by_flips(mesh).ok());
    ASSERT_TRUE(all_edges_locally_delaunay(mesh));

    std::vector<VertexId> interior;
    for (int j = 1; j < n; ++j)
        for (int i = 1; i < n; ++i)
            interior.push_back(static_cast<VertexId>(j * (n + 1) + i));
    std::shuffle(interior.begin(), interior.end(), random);
    std::size_t removals = 0;
    for (VertexId v : interior) {
        const std::size_t before = mesh.element_count();
        const std::size_t degree = star(mesh, v).size();
        const auto removed = remove_node(mesh, v);
        ASSERT_TRUE(removed.ok()) << "vertex " << v << ": " << removed.reason();
        ++removals;
        ASSERT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
        ASSERT_EQ(mesh.element_count(), before - 2);
        ASSERT_EQ(removed->size(), degree - 2);
        ASSERT_TRUE(test::all_strictly_positive(mesh)) << "after removing " << v;
        ASSERT_NEAR(total_area(mesh), 1.0, 1e-12);
        ASSERT_TRUE(all_edges_locally_delaunay(mesh)) << "after removing " << v;
    }
    EXPECT_EQ(removals, interior.size());
    // only the 4n boundary vertices are left: 4n - 2 triangles
    EXPECT_EQ(mesh.element_count(), static_cast<std::size_t>(4 * n - 2));

    // then every vertex on the straight sides, in random order, until the two triangles of the
    // square are left; the corners are refused
    std::vector<VertexId> sides;
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i)
            if ((i == 0 || i == n || j == 0 || j == n) && (i % n != 0 || j % n != 0))
                sides.push_back(static_cast<VertexId>(j * (n + 1) + i));
    std::shuffle(sides.begin(), sides.end(), random);
    for (VertexId v : sides) {
        const std::size_t before = mesh.element_count();
        const auto removed = remove_node(mesh, v);
        ASSERT_TRUE(removed.ok()) << "vertex " << v << ": " << removed.reason();
        ASSERT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
        ASSERT_EQ(mesh.element_count(), before - 1);
        ASSERT_TRUE(test::all_strictly_positive(mesh)) << "after removing " << v;
        ASSERT_NEAR(total_area(mesh), 1.0, 1e-12);
    }
    EXPECT_EQ(mesh.element_count(), 2u);
    EXPECT_EQ(mesh.boundary_face_count(), 4u);
    const Mesh square = mesh;
    const auto corner = remove_node(mesh, static_cast<VertexId>(n));
    ASSERT_FALSE(corner.ok());
    expect_same_state(mesh, square);
}

}  // namespace
}  // namespace sxk
