// Tests of 3D conforming bisection: TetBisection (Maubach tuples in AMP's marked-tetrahedron form
// on Kuhn meshes, longest-edge marks on any mesh),
// bisect_tetrahedron and refine_around_tetrahedra (issue 3, item 6, 3D part).
//
// Conformity oracle. split_edge halves every tetrahedron around its edge, so a hanging node
// cannot be built; what could go wrong is a wrong marking (endless recursion, degenerating
// shapes) or a wrong record of the children. Each test checks validate(), exact positive
// orientation, the check_marking() conformity of the marks, and that the domain is unchanged:
// total volume and total boundary area equal to the start's (a crack or hanging node would add
// inner boundary). The number of boundary faces does grow: boundary edges are bisected too.
//
// Randomised tests print their seed; SXK_SEED=<n> replays a run.
//
//      x3 = (1,1,1)          The Kuhn tetrahedron of the unit cube with Maubach's tuple
//       |\                   (x0,x1,x2,x3), tag 3: refinement edge x0-x3 (the cube diagonal),
//       | \                  children (x0,x1,x2,z) and (x1,x2,x3,z), tag 2, z = cube centre.
//       |  x2 = (1,1,0)      Three generations later every descendant is a Kuhn tetrahedron
//       | /                  of half the size.
//      x1 = (1,0,0)
//       |
//      x0 = (0,0,0)
#include <gtest/gtest.h>

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <limits>
#include <map>
#include <optional>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "ops/edge_star.hpp"
#include "ops/split_collapse_fixtures.hpp"
#include "ops/tet_bisection_plan.hpp"
#include "sxk/ops/refine_around_tetrahedra.hpp"
#include "sxk/ops/split_edge.hpp"
#include "sxk/ops/tet_bisection.hpp"
#include "sxk/predicates.hpp"

namespace sxk {
namespace {

using test::expect_same_state;
using Edge = std::array<VertexId, 2>;

using test::seed_for;

Edge sorted(VertexId u, VertexId v) { return u < v ? Edge{u, v} : Edge{v, u}; }

Point minus(const Point& p, const Point& q) { return {p[0] - q[0], p[1] - q[1], p[2] - q[2]}; }
Point cross(const Point& u, const Point& v) {
    return {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
}
double dot(const Point& u, const Point& v) { return u[0] * v[0] + u[1] * v[1] + u[2] * v[2]; }

double total_volume(const Mesh& mesh) {
    double sum = 0;
    for (ElementId t : elements(mesh)) {
        const Simplex& s = mesh.simplex(t);
        const Point& a = mesh.reference(s.vertex(0));
        sum += std::abs(dot(minus(mesh.reference(s.vertex(1)), a),
                            cross(minus(mesh.reference(s.vertex(2)), a),
                                  minus(mesh.reference(s.vertex(3)), a)))) / 6;
    }
    return sum;
}

double boundary_area(const Mesh& mesh) {
    double sum = 0;
    for (FaceId f : mesh.boundary_faces()) {
        const Simplex s = mesh.face_simplex(f);
        const Point& a = mesh.reference(s.vertex(0));
        const Point n = cross(minus(mesh.reference(s.vertex(1)), a), minus(mesh.reference(s.vertex(2)), a));
        sum += std::sqrt(dot(n, n)) / 2;
    }
    return sum;
}

using test::shape_signature;
using Signature = test::ShapeSignature;

void add_shapes(const Mesh& mesh, std::set<Signature>& shapes) {
    for (ElementId t : elements(mesh)) shapes.insert(shape_signature(mesh, t));
}

// The conformity oracle of the file header.
void expect_conforming(const TetBisection& state, double volume, double area) {
    const Mesh& mesh = state.mesh();
    ASSERT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
    EXPECT_TRUE(test::all_strictly_positive(mesh));
    const auto marks = state.check_marking();
    EXPECT_TRUE(marks.ok()) << marks.reason();
    EXPECT_FALSE(state.is_stale()) << state.stale_reason();
    EXPECT_NEAR(total_volume(mesh), volume, 1e-9 * volume);
    EXPECT_NEAR(boundary_area(mesh), area, 1e-9 * area);
}

// A Kuhn cube with every vertex moved at random (no longer Kuhn; ties in edge length gone).
Mesh jittered_kuhn_cube(int n, std::mt19937_64& random) {
    Mesh kuhn = test::kuhn_cube(n);
    std::uniform_real_distribution<double> jitter(-0.1, 0.1);
    for (VertexId v = 0; v < kuhn.vertex_count(); ++v) {
        Point p = kuhn.reference(v);
        for (double& c : p)
            if (c > 0 && c < n) c += jitter(random);
        kuhn.set_reference(v, p);
        kuhn.set_deformed(v, p);
    }
    return kuhn;
}

// The Delaunay tetrahedralisation (CGAL) of the unit cube's corners and `count` random points.
Mesh delaunay_mesh(int count, std::mt19937_64& random) {
    using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
    using VertexBase = CGAL::Triangulation_vertex_base_with_info_3<VertexId, Kernel>;
    using Tds = CGAL::Triangulation_data_structure_3<VertexBase>;
    using Delaunay = CGAL::Delaunay_triangulation_3<Kernel, Tds>;
    Mesh mesh(3, 3);
    std::vector<std::pair<Kernel::Point_3, VertexId>> points;
    auto add = [&](const Point& p) {
        points.emplace_back(Kernel::Point_3(p[0], p[1], p[2]), mesh.add_vertex(p));
    };
    for (int corner = 0; corner < 8; ++corner)
        add({double(corner & 1), double((corner >> 1) & 1), double((corner >> 2) & 1)});
    std::uniform_real_distribution<double> coordinate(0.02, 0.98);
    for (int i = 0; i < count; ++i) add({coordinate(random), coordinate(random), coordinate(random)});
    const Delaunay delaunay(points.begin(), points.end());
    std::vector<Simplex> tets;
    for (auto cell = delaunay.finite_cells_begin(); cell != delaunay.finite_cells_end(); ++cell) {
        const std::array<VertexId, 4> v{cell->vertex(0)->info(), cell->vertex(1)->info(),
                                        cell->vertex(2)->info(), cell->vertex(3)->info()};
        const Sign sign = orient3d(mesh.reference(v[0]), mesh.reference(v[1]),
                                   mesh.reference(v[2]), mesh.reference(v[3]));
        tets.emplace_back(sign == Sign::negative ? -1 : +1, v);
    }
    EXPECT_TRUE(mesh.assign_elements(tets).ok());
    return mesh;
}

// ---- the marking rules --------------------------------------------------------------------------

// One Kuhn tetrahedron, three generations by the rules alone: they are Maubach's tuples.
TEST(TetBisection, MarkingRulesAreMaubachsOnAKuhnTetrahedron) {
    // Maubach (x0,x1,x2,x3) tag 3 = vertices 0,1,2,3: a = x0, b = x3, c = x1, d = x2
    TetMarking kuhn;
    kuhn.vertices = {0, 3, 1, 2};
    kuhn.acd_unmarked = 1;  // face x0x1x2 marked x0x2
    kuhn.bcd_unmarked = 2;  // face x1x2x3 marked x1x3
    EXPECT_EQ(tet_type(kuhn), TetType::adjacent);
    EXPECT_EQ(face_mark(kuhn, 3), sorted(0, 2));
    EXPECT_EQ(face_mark(kuhn, 0), sorted(1, 3));
    EXPECT_EQ(face_mark(kuhn, 1), sorted(0, 3));

    // tag 3 -> (x0,x1,x2,z) and (x1,x2,x3,z) with z = 4, tag 2: refinement edges x0x2, x1x3
    const auto level1 = bisected_markings(kuhn, 4);
    EXPECT_EQ(sorted(level1[0].vertices[0], level1[0].vertices[1]), sorted(0, 2));
    EXPECT_EQ(sorted(level1[1].vertices[0], level1[1].vertices[1]), sorted(1, 3));
    for (const TetMarking& child : level1) {
        EXPECT_EQ(tet_type(child), TetType::planar_unflagged);
        EXPECT_EQ(child.generation, 1u);
    }
    // tag 2 (x0,x1,x2,z) -> (x0,x1,z',z) and (x1,x2,z',z), z' = 5, tag 1: edges x0x1, x1x2
    const auto level2 = bisected_markings(level1[0], 5);
    EXPECT_EQ(sorted(level2[0].vertices[0], level2[0].vertices[1]), sorted(0, 1));
    EXPECT_EQ(sorted(level2[1].vertices[0], level2[1].vertices[1]), sorted(1, 2));
    for (const TetMarking& child : level2) EXPECT_EQ(tet_type(child), TetType::planar_flagged);
    // the new face {1,4,5} is marked 1-4 (cd), as Maubach's next step needs
    EXPECT_EQ(face_mark(level2[0], 0), sorted(1, 4));
    // tag 1 (x0,x1,z',z) -> (x0,z'',z',z), (x1,z'',z',z), z'' = 6, tag 3: edges x0-z, x1-z
    const auto level3 = bisected_markings(level2[0], 6);
    EXPECT_EQ(sorted(level3[0].vertices[0], level3[0].vertices[1]), sorted(0, 4));
    EXPECT_EQ(sorted(level3[1].vertices[0], level3[1].vertices[1]), sorted(1, 4));
    for (const TetMarking& child : level3) EXPECT_EQ(tet_type(child), TetType::adjacent);
    // Pf: the new face {5,4,6} is marked m-s = 6-4 (s = z, shared by the marks x0-z, x1-z)
    EXPECT_EQ(face_mark(level3[0], 0), sorted(4, 6));
    // the child (x0,z'',z',z) is again Maubach's tag 3 tuple: faces x0z''z' and z''z'z marked
    // x0-z' and z''-z
    EXPECT_EQ(face_mark(level3[0], 4), sorted(0, 5));
    EXPECT_EQ(face_mark(level3[0], 0), sorted(6, 4));
}

// Children of the types outside the cycle: O and M give Pu children.
TEST(TetBisection, OppositeAndMixedTypesGivePlanarChildren) {
    TetMarking opposite;
    opposite.vertices = {0, 1, 2, 3};
    opposite.acd_unmarked = 0;  // cd
    opposite.bcd_unmarked = 1;  // cd
    EXPECT_EQ(tet_type(opposite), TetType::opposite);
    for (const TetMarking& child : bisected_markings(opposite, 4)) {
        EXPECT_EQ(tet_type(child), TetType::planar_unflagged);
        EXPECT_EQ(sorted(child.vertices[0], child.vertices[1]), sorted(2, 3));
    }
    TetMarking mixed = opposite;
    mixed.bcd_unmarked = 3;  // bc
    EXPECT_EQ(tet_type(mixed), TetType::mixed);
    for (const TetMarking& child : bisected_markings(mixed, 4))
        EXPECT_EQ(tet_type(child), TetType::planar_unflagged);
}

// On a Kuhn mesh, the longest-edge marking and Maubach's tuples are the same marks.
TEST(TetBisection, KuhnTuplesEqualTheLongestEdgeMarking) {
    Mesh mesh = test::kuhn_cube(2);
    Mesh copy = mesh;
    auto kuhn = TetBisection::for_kuhn_mesh(mesh);
    ASSERT_TRUE(kuhn.ok()) << kuhn.reason();
    auto general = TetBisection::with_initial_marking(copy);
    ASSERT_TRUE(general.ok()) << general.reason();
    EXPECT_TRUE(kuhn->check_marking().ok());
    EXPECT_TRUE(general->check_marking().ok());
    for (ElementId t : elements(mesh)) {
        EXPECT_EQ(sorted(kuhn->refinement_edge(t)[0], kuhn->refinement_edge(t)[1]),
                  sorted(general->refinement_edge(t)[0], general->refinement_edge(t)[1]));
        for (VertexId v : mesh.simplex(t).vertices())
            EXPECT_EQ(face_mark(kuhn->marking(t), v), face_mark(general->marking(t), v));
        EXPECT_EQ(tet_type(kuhn->marking(t)), TetType::adjacent);
    }
}

// A Kuhn cube scaled by 0.1 (steps not exactly equal in floating point) is still Kuhn.
TEST(TetBisection, ScaledKuhnCubeIsKuhn) {
    Mesh mesh = test::kuhn_cube(3);
    for (VertexId v = 0; v < mesh.vertex_count(); ++v) {
        Point p = mesh.reference(v);
        for (double& c : p) c *= 0.1;
        mesh.set_reference(v, p);
        mesh.set_deformed(v, p);
    }
    auto state = TetBisection::for_kuhn_mesh(mesh);
    ASSERT_TRUE(state.ok()) << state.reason();
    const auto refined = refine_around_tetrahedra(*state, {0.11, 0.22, 0.05}, 0.01);
    ASSERT_TRUE(refined.ok()) << refined.reason();
    std::set<Signature> shapes;
    add_shapes(mesh, shapes);
    EXPECT_EQ(shapes.size(), 3u);
    expect_conforming(*state, 0.027, 0.54);
}

// ---- bisect_tetrahedron ---------------------------------------------------------------------------

// The main diagonal of kuhn_cube(1) is every tetrahedron's refinement edge: one split, twelve
// children around the centre, each with its Maubach tuple.
TEST(BisectTetrahedron, KuhnCubeDiagonalInOneSplit) {
    Mesh mesh = test::kuhn_cube(1);
    auto state = TetBisection::for_kuhn_mesh(mesh);
    ASSERT_TRUE(state.ok()) << state.reason();
    const auto bisected = bisect_tetrahedron(*state, 0);
    ASSERT_TRUE(bisected.ok()) << bisected.reason();
    EXPECT_EQ(*bisected, 1u);
    EXPECT_EQ(mesh.element_count(), 12u);
    EXPECT_EQ(mesh.reference(8), (Point{0.5, 0.5, 0.5}));
    for (ElementId t : elements(mesh)) {
        EXPECT_EQ(state->marking(t).generation, 1u);
        EXPECT_EQ(tet_type(state->marking(t)), TetType::planar_unflagged);
        // tag 2: the refinement edge is a face diagonal of the cube (length sqrt 2)
        const auto e = state->refinement_edge(t);
        const Point d = minus(mesh.reference(e[0]), mesh.reference(e[1]));
        EXPECT_DOUBLE_EQ(dot(d, d), 2.0);
    }
    expect_conforming(*state, 1.0, 6.0);
}

// Bisecting a tetrahedron whose refinement edge is not the one of its neighbours bisects them
// first: on kuhn_cube(2) the face diagonal of a tetrahedron of generation 1 is shared with the
// next cube, whose tetrahedra are of generation 0.
TEST(BisectTetrahedron, RecursesIntoNeighboursFirst) {
    Mesh mesh = test::kuhn_cube(2);
    auto state = TetBisection::for_kuhn_mesh(mesh);
    ASSERT_TRUE(state.ok()) << state.reason();
    ASSERT_TRUE(bisect_tetrahedron(*state, 0).ok());
    // a child whose refinement edge (a face diagonal of the first cube) is inside the domain
    ElementId child = invalid_id;
    for (ElementId t : elements(mesh)) {
        if (state->marking(t).generation != 1) continue;
        const auto e = state->refinement_edge(t);
        bool inside = true;
        for (std::size_t k = 0; k < 3; ++k) {
            const double middle = (mesh.reference(e[0])[k] + mesh.reference(e[1])[k]) / 2;
            if (middle == 0 || middle == 2) inside = false;
        }
        if (inside) child = t;
    }
    ASSERT_NE(child, invalid_id);
    const std::size_t before = mesh.element_count();
    const auto bisected = bisect_tetrahedron(*state, child);
    ASSERT_TRUE(bisected.ok()) << bisected.reason();
    EXPECT_GT(*bisected, 1u);  // the neighbouring cube's diagonal first
    EXPECT_GT(mesh.element_count(), before + 2);
    expect_conforming(*state, 8.0, 24.0);
}

// Uniform refinement of a Kuhn cube: every generation bisected in turn. All tetrahedra lie in
// three similarity classes (one per Maubach tag), generation 3 is similar to generation 0.
TEST(BisectTetrahedron, UniformRefinementOfAKuhnCubeHasThreeShapes) {
    Mesh mesh = test::kuhn_cube(2);
    auto state = TetBisection::for_kuhn_mesh(mesh);
    ASSERT_TRUE(state.ok()) << state.reason();
    std::set<Signature> shapes;
    add_shapes(mesh, shapes);
    EXPECT_EQ(shapes.size(), 1u);
    std::vector<std::set<Signature>> per_generation;
    for (std::uint32_t generation = 0; generation < 7; ++generation) {
        std::vector<ElementId> current;
        for (ElementId t : elements(mesh)) current.push_back(t);
        for (ElementId t : current)
            if (mesh.is_element(t) && state->marking(t).generation == generation) {
                const auto bisected = bisect_tetrahedron(*state, t);
                ASSERT_TRUE(bisected.ok()) << bisected.reason();
            }
        EXPECT_EQ(mesh.element_count(), 48u << (generation + 1));
        std::set<Signature> these;
        for (ElementId t : elements(mesh)) {
            EXPECT_EQ(state->marking(t).generation, generation + 1);
            these.insert(shape_signature(mesh, t));
        }
        EXPECT_EQ(these.size(), 1u) << "generation " << generation + 1;
        per_generation.push_back(these);
        shapes.insert(these.begin(), these.end());
        expect_conforming(*state, 8.0, 24.0);
    }
    std::cout << "uniform Maubach refinement, 7 generations: " << shapes.size()
              << " similarity classes\n";
    EXPECT_EQ(shapes.size(), 3u);
    // generation 3 is generation 0 at half the size
    std::set<Signature> start;
    add_shapes(test::kuhn_cube(1), start);
    EXPECT_EQ(per_generation[2], start);
    EXPECT_EQ(per_generation[5], start);
}

// ---- refine_around_tetrahedra -----------------------------------------------------------------------

// 10^4 random refine_around calls on a Kuhn cube with Maubach tuples.
TEST(RefineAroundTetrahedra, TenThousandRandomCallsOnAKuhnCube) {
    const std::uint64_t seed = seed_for("RefineAroundTetrahedra.TenThousandRandomCallsOnAKuhnCube");
    SCOPED_TRACE("SXK_SEED=" + std::to_string(seed));
    std::mt19937_64 random(seed);
    Mesh mesh = test::kuhn_cube(2);
    auto state = TetBisection::for_kuhn_mesh(mesh);
    ASSERT_TRUE(state.ok()) << state.reason();
    std::uniform_real_distribution<double> coordinate(0.0, 2.0);
    std::uniform_real_distribution<double> log_h(std::log(0.15), std::log(1.0));
    std::size_t bisections = 0;
    std::set<Signature> shapes;
    for (int call = 0; call < 10000; ++call) {
        const Point x{coordinate(random), coordinate(random), coordinate(random)};
        const double h = std::exp(log_h(random));
        const auto refined = refine_around_tetrahedra(*state, x, h);
        ASSERT_TRUE(refined.ok()) << refined.reason();
        bisections += *refined;
        const ElementId t = locate_tetrahedron(mesh, x, state->last_child());
        ASSERT_NE(t, invalid_id);
        const auto e = state->refinement_edge(t);
        const Point d = minus(mesh.reference(e[0]), mesh.reference(e[1]));
        ASSERT_LE(std::sqrt(dot(d, d)), h);
        if (call % 2500 == 2499) {
            expect_conforming(*state, 8.0, 24.0);
            add_shapes(mesh, shapes);
        }
    }
    std::cout << "10^4 refine_around calls: " << bisections << " bisections, "
              << mesh.element_count() << " tetrahedra, " << shapes.size()
              << " similarity classes (Maubach bound for the Kuhn cube: 3)\n";
    EXPECT_GT(bisections, 100u);
    EXPECT_LE(shapes.size(), 3u);
    expect_conforming(*state, 8.0, 24.0);
}

// Longest-edge bisection on a Delaunay mesh of random points: conformity after many calls; the
// number of shape classes is printed (no proven bound for longest-edge bisection in 3D).
TEST(RefineAroundTetrahedra, GeneralMarkingOnARandomDelaunayMesh) {
    const std::uint64_t seed = seed_for("RefineAroundTetrahedra.GeneralMarkingOnARandomDelaunayMesh");
    SCOPED_TRACE("SXK_SEED=" + std::to_string(seed));
    std::mt19937_64 random(seed);
    Mesh mesh = delaunay_mesh(60, random);
    ASSERT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
    ASSERT_TRUE(test::all_strictly_positive(mesh));
    const std::size_t initial = mesh.element_count();
    const double volume = total_volume(mesh), area = boundary_area(mesh);
    EXPECT_NEAR(volume, 1.0, 1e-12);
    auto state = TetBisection::with_initial_marking(mesh);
    ASSERT_TRUE(state.ok()) << state.reason();
    ASSERT_TRUE(state->check_marking().ok());
    std::uniform_real_distribution<double> coordinate(0.0, 1.0);
    std::uniform_real_distribution<double> log_h(std::log(0.06), std::log(0.5));
    std::size_t bisections = 0;
    std::set<Signature> shapes;
    add_shapes(mesh, shapes);
    for (int call = 0; call < 1000; ++call) {
        const Point x{coordinate(random), coordinate(random), coordinate(random)};
        const auto refined = refine_around_tetrahedra(*state, x, std::exp(log_h(random)));
        ASSERT_TRUE(refined.ok()) << refined.reason();
        bisections += *refined;
        if (call % 500 == 499) {
            expect_conforming(*state, volume, area);
            add_shapes(mesh, shapes);
        }
    }
    std::uint32_t deepest = 0;
    for (ElementId t : elements(mesh)) deepest = std::max(deepest, state->marking(t).generation);
    std::cout << "Delaunay mesh of " << initial << " tetrahedra, 1000 refine_around calls: "
              << bisections << " bisections, " << mesh.element_count() << " tetrahedra, deepest "
              << "generation " << deepest << ", " << shapes.size()
              << " similarity classes (longest-edge bisection: no proven bound in 3D)\n";
    expect_conforming(*state, volume, area);
}

// Deep refinement of single irregular tetrahedra by longest-edge bisection: terminates and stays
// conforming at depth > 12; the shape classes are printed (no proven bound in 3D).
TEST(RefineAroundTetrahedra, DeepRefinementOfOneIrregularTetrahedron) {
    const std::uint64_t seed = seed_for("RefineAroundTetrahedra.DeepRefinementOfOneIrregularTetrahedron");
    SCOPED_TRACE("SXK_SEED=" + std::to_string(seed));
    std::mt19937_64 random(seed);
    std::uniform_real_distribution<double> coordinate(-1.0, 1.0);
    std::uniform_real_distribution<double> inside(0.0, 1.0);
    for (int trial = 0; trial < 4; ++trial) {
        Mesh mesh(3, 3);
        for (int i = 0; i < 4; ++i) mesh.add_vertex({coordinate(random), coordinate(random), coordinate(random)});
        const Sign sign = orient3d(mesh.reference(0), mesh.reference(1), mesh.reference(2), mesh.reference(3));
        if (sign == Sign::zero) continue;
        const std::array<Simplex, 1> tet{Simplex(sign == Sign::positive ? +1 : -1, {0, 1, 2, 3})};
        ASSERT_TRUE(mesh.assign_elements(tet).ok());
        const double volume = total_volume(mesh), area = boundary_area(mesh);
        auto state = TetBisection::with_initial_marking(mesh);
        ASSERT_TRUE(state.ok()) << state.reason();
        for (int call = 0; call < 6; ++call) {
            // a random point inside by barycentric weights
            std::array<double, 4> w{inside(random), inside(random), inside(random), inside(random)};
            const double sum = w[0] + w[1] + w[2] + w[3];
            Point x{0, 0, 0};
            for (VertexId v = 0; v < 4; ++v)
                for (std::size_t k = 0; k < 3; ++k) x[k] += w[v] / sum * mesh.reference(v)[k];
            const auto refined = refine_around_tetrahedra(*state, x, 0.02);
            ASSERT_TRUE(refined.ok()) << refined.reason();
        }
        std::uint32_t deepest = 0;
        for (ElementId t : elements(mesh)) deepest = std::max(deepest, state->marking(t).generation);
        std::set<Signature> shapes;
        add_shapes(mesh, shapes);
        std::cout << "one tetrahedron, longest-edge, depth " << deepest << ", "
                  << mesh.element_count() << " tetrahedra: " << shapes.size()
                  << " similarity classes\n";
        EXPECT_GE(deepest, 12u);
        expect_conforming(*state, volume, area);
    }
}

// Deep refinement of a Kuhn cube: all descendants in Maubach's 3 similarity classes, with the
// Maubach tuples and with the longest-edge rule (which bisects the same edges on Kuhn meshes).
TEST(RefineAroundTetrahedra, DeepRefinementOfAKuhnCubeHasThreeShapes) {
    const std::uint64_t seed = seed_for("RefineAroundTetrahedra.DeepRefinementOfAKuhnCubeHasThreeShapes");
    SCOPED_TRACE("SXK_SEED=" + std::to_string(seed));
    for (const bool maubach : {true, false}) {
        std::mt19937_64 random(seed);
        std::uniform_real_distribution<double> coordinate(0.0, 1.0);
        Mesh mesh = test::kuhn_cube(1);
        auto state = maubach ? TetBisection::for_kuhn_mesh(mesh) : TetBisection::with_initial_marking(mesh);
        ASSERT_TRUE(state.ok()) << state.reason();
        for (int call = 0; call < 6; ++call) {
            const auto refined = refine_around_tetrahedra(
                *state, {coordinate(random), coordinate(random), coordinate(random)}, 0.01);
            ASSERT_TRUE(refined.ok()) << refined.reason();
        }
        std::uint32_t deepest = 0;
        for (ElementId t : elements(mesh)) deepest = std::max(deepest, state->marking(t).generation);
        std::set<Signature> shapes;
        add_shapes(mesh, shapes);
        std::cout << (maubach ? "Maubach" : "longest-edge") << " on the Kuhn cube, depth " << deepest
                  << ", " << mesh.element_count() << " tetrahedra: " << shapes.size()
                  << " similarity classes\n";
        EXPECT_GE(deepest, 18u);
        EXPECT_EQ(shapes.size(), 3u);
        expect_conforming(*state, 1.0, 6.0);
    }
}

// The convenience form for `sxk refine`: builds the marking itself.
TEST(RefineAroundTetrahedra, OnAMeshWithoutState) {
    Mesh mesh = test::kuhn_cube(2);
    const auto refined = refine_around_tetrahedra(mesh, {0.3, 0.7, 1.2}, 0.2);
    ASSERT_TRUE(refined.ok()) << refined.reason();
    EXPECT_GT(*refined, 5u);
    ASSERT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
    EXPECT_TRUE(test::all_strictly_positive(mesh));
    EXPECT_NEAR(total_volume(mesh), 8.0, 1e-12);
    EXPECT_NEAR(boundary_area(mesh), 24.0, 1e-12);
    // a corner of the domain is in the mesh too
    const auto corner = refine_around_tetrahedra(mesh, {0, 0, 0}, 0.3);
    ASSERT_TRUE(corner.ok()) << corner.reason();
    EXPECT_GT(*corner, 0u);
    ASSERT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
    // nothing to do where the mesh is already fine enough
    auto state = TetBisection::with_initial_marking(mesh);
    ASSERT_TRUE(state.ok()) << state.reason();
    ASSERT_TRUE(refine_around_tetrahedra(*state, {1.5, 0.25, 0.5}, 0.3).ok());
    const Mesh before = mesh;
    const auto again = refine_around_tetrahedra(*state, {1.5, 0.25, 0.5}, 0.3);
    ASSERT_TRUE(again.ok()) << again.reason();
    EXPECT_EQ(*again, 0u);
    expect_same_state(mesh, before);
    EXPECT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
}

// The state-less form is the longest-edge rule with marks computed when needed: the same calls
// give the same mesh, ids included, as one TetBisection::with_initial_marking session.
TEST(RefineAroundTetrahedra, StatelessCallsEqualALongestEdgeSession) {
    const std::uint64_t seed = seed_for("RefineAroundTetrahedra.StatelessCallsEqualALongestEdgeSession");
    SCOPED_TRACE("SXK_SEED=" + std::to_string(seed));
    std::mt19937_64 random(seed);
    Mesh with_state = jittered_kuhn_cube(2, random);
    Mesh without_state = with_state;
    auto state = TetBisection::with_initial_marking(with_state);
    ASSERT_TRUE(state.ok()) << state.reason();
    std::uniform_real_distribution<double> coordinate(0.0, 2.0);
    std::uniform_real_distribution<double> size(0.2, 0.8);
    std::size_t total = 0;
    for (int call = 0; call < 200; ++call) {
        const Point x{coordinate(random), coordinate(random), coordinate(random)};
        const double h = size(random);
        const auto one = refine_around_tetrahedra(*state, x, h);
        const auto other = refine_around_tetrahedra(without_state, x, h);
        ASSERT_TRUE(one.ok()) << one.reason();
        ASSERT_TRUE(other.ok()) << other.reason();
        ASSERT_EQ(*one, *other);
        total += *one;
    }
    EXPECT_GT(total, 50u);
    expect_same_state(with_state, without_state);
    ASSERT_TRUE(without_state.validate().ok()) << without_state.validate().reason();
}

// Longest-edge bisection of a jittered Kuhn cube (not Kuhn any more: for_kuhn_mesh refuses it).
TEST(RefineAroundTetrahedra, JitteredKuhnCube) {
    const std::uint64_t seed = seed_for("RefineAroundTetrahedra.JitteredKuhnCube");
    SCOPED_TRACE("SXK_SEED=" + std::to_string(seed));
    std::mt19937_64 random(seed);
    Mesh mesh = jittered_kuhn_cube(2, random);
    ASSERT_TRUE(test::all_strictly_positive(mesh));
    const double volume = total_volume(mesh), area = boundary_area(mesh);
    auto state = TetBisection::with_initial_marking(mesh);
    ASSERT_TRUE(state.ok()) << state.reason();
    std::uniform_real_distribution<double> coordinate(0.0, 2.0);
    for (int call = 0; call < 500; ++call) {
        const auto refined = refine_around_tetrahedra(
            *state, {coordinate(random), coordinate(random), coordinate(random)}, 0.15);
        ASSERT_TRUE(refined.ok()) << refined.reason();
    }
    expect_conforming(*state, volume, area);
}

// Point location on a non-convex domain: kuhn_cube(2) without the cubes of [1,2]x[1,2]x[0,2] (an
// L-shaped prism). A walk towards a point across the notch meets the boundary and falls back to
// the scan; points in the notch are in no element.
TEST(RefineAroundTetrahedra, LocatesAcrossANotch) {
    const Mesh cube = test::kuhn_cube(2);
    Mesh mesh(3, 3);
    for (VertexId v = 0; v < cube.vertex_count(); ++v) mesh.add_vertex(cube.reference(v));
    std::vector<Simplex> kept;
    for (ElementId t : elements(cube)) {
        Point centre{0, 0, 0};
        for (VertexId v : cube.simplex(t).vertices())
            for (std::size_t k = 0; k < 3; ++k) centre[k] += cube.reference(v)[k] / 4;
        if (!(centre[0] > 1 && centre[1] > 1)) kept.push_back(cube.simplex(t));
    }
    ASSERT_TRUE(mesh.assign_elements(kept).ok());
    ASSERT_EQ(mesh.element_count(), 36u);
    // start in the arm x > 1, y < 1; the point is in the arm x < 1, y > 1
    ElementId start = invalid_id;
    for (ElementId t : elements(mesh))
        if (mesh.reference(mesh.simplex(t).vertex(0))[0] >= 1 && mesh.reference(mesh.simplex(t).vertex(3))[1] <= 1)
            start = t;
    ASSERT_NE(start, invalid_id);
    const Point x{0.3, 1.8, 0.4};
    const ElementId found = locate_tetrahedron(mesh, x, start);
    ASSERT_NE(found, invalid_id);
    for (int i = 0; i < 4; ++i) {
        std::array<Point, 4> p{};
        for (int j = 0; j < 4; ++j)
            p[static_cast<std::size_t>(j)] = j == i ? x : mesh.reference(mesh.simplex(found).vertex(j));
        EXPECT_NE(static_cast<int>(orient3d(p[0], p[1], p[2], p[3])) * mesh.simplex(found).sign(), -1);
    }
    EXPECT_EQ(locate_tetrahedron(mesh, {1.5, 1.5, 1.0}, start), invalid_id);
    // and refine_around works there, from any start
    auto state = TetBisection::with_initial_marking(mesh);
    ASSERT_TRUE(state.ok()) << state.reason();
    const double volume = total_volume(mesh), area = boundary_area(mesh);
    ASSERT_TRUE(refine_around_tetrahedra(*state, {1.8, 0.2, 1.9}, 0.2).ok());
    const auto across = refine_around_tetrahedra(*state, x, 0.2);
    ASSERT_TRUE(across.ok()) << across.reason();
    EXPECT_GT(*across, 0u);
    const Mesh before = mesh;
    const auto notch = refine_around_tetrahedra(*state, {1.5, 1.5, 1.0}, 0.2);
    ASSERT_FALSE(notch.ok());
    EXPECT_EQ(notch.reason(), "refine_around_tetrahedra: point (1.5, 1.5, 1) is not in the mesh");
    EXPECT_EQ(notch.code(), RefusalCode::not_found);
    expect_same_state(mesh, before);
    expect_conforming(*state, volume, area);
}

// ---- refusals ---------------------------------------------------------------------------------------

// ---- a refused split in the middle of a recursion --------------------------------------------------

// kuhn_cube(2) with tetrahedron 0 bisected, and a child whose bisection recurses into the next
// cube first (as in RecursesIntoNeighboursFirst).
ElementId recursing_child(Mesh& mesh, TetBisection& state) {
    if (!bisect_tetrahedron(state, 0).ok()) return invalid_id;
    ElementId child = invalid_id;
    for (ElementId t : elements(mesh)) {
        if (state.marking(t).generation != 1) continue;
        const auto e = state.refinement_edge(t);
        bool inside = true;
        for (std::size_t k = 0; k < 3; ++k) {
            const double middle = (mesh.reference(e[0])[k] + mesh.reference(e[1])[k]) / 2;
            if (middle == 0 || middle == 2) inside = false;
        }
        if (inside) child = t;
    }
    return child;
}

bool same_marking(const TetMarking& p, const TetMarking& q) {
    return p.vertices == q.vertices && p.acd_unmarked == q.acd_unmarked &&
           p.bcd_unmarked == q.bcd_unmarked && p.flagged == q.flagged &&
           p.generation == q.generation;
}

// Moves the deformed position of the vertex a of `t`'s marking onto the plane of b, c, d (the
// reference positions stay): t is flat in the deformed positions, so splitting its refinement
// edge ab, which the recursion does LAST, is refused; the split of the neighbouring cube's
// diagonal before it is fine. Returns a.
VertexId flatten_deformed(Mesh& mesh, const TetMarking& marking) {
    const VertexId a = marking.vertices[0], b = marking.vertices[1];
    const VertexId c = marking.vertices[2], d = marking.vertices[3];
    // a' = b + (c - b) / 4 + (d - b) / 4: exactly on the plane (dyadic coordinates)
    Point moved{};
    for (std::size_t k = 0; k < 3; ++k)
        moved[k] = mesh.reference(b)[k] + (mesh.reference(c)[k] - mesh.reference(b)[k]) / 4 +
                   (mesh.reference(d)[k] - mesh.reference(b)[k]) / 4;
    mesh.set_deformed(a, moved);
    return a;
}

TEST(BisectTetrahedron, RefusalInTheMiddleOfTheRecursionChangesNothing) {
    // the same refinement without the flat element: how many splits, which vertex ids
    Mesh twin = test::kuhn_cube(2);
    auto twin_state = TetBisection::for_kuhn_mesh(twin);
    ASSERT_TRUE(twin_state.ok()) << twin_state.reason();
    const ElementId twin_child = recursing_child(twin, *twin_state);
    ASSERT_NE(twin_child, invalid_id);
    const std::size_t base = twin.vertex_count();
    const auto twin_bisected = bisect_tetrahedron(*twin_state, twin_child);
    ASSERT_TRUE(twin_bisected.ok()) << twin_bisected.reason();
    ASSERT_GE(*twin_bisected, 2u);  // the refused split below is not the first one

    Mesh mesh = test::kuhn_cube(2);
    auto state = TetBisection::for_kuhn_mesh(mesh);
    ASSERT_TRUE(state.ok()) << state.reason();
    const ElementId child = recursing_child(mesh, *state);
    ASSERT_EQ(child, twin_child);
    const TetMarking marking = state->marking(child);
    const VertexId moved = flatten_deformed(mesh, marking);
    const Point original = mesh.reference(moved);

    const Mesh before = mesh;
    std::vector<TetMarking> markings_before;
    for (ElementId t : elements(mesh)) markings_before.push_back(state->marking(t));
    test::CountingWatcher watcher;
    mesh.add_watcher(watcher);

    const auto refused = bisect_tetrahedron(*state, child);
    ASSERT_FALSE(refused.ok());
    // refused at the last split, of the child's own refinement edge 12-13 (after the
    // neighbouring cube's diagonal): its midpoint would be the last new vertex, 29
    EXPECT_EQ(base + *twin_bisected - 1, 29u);
    EXPECT_EQ(refused.reason(), "bisect_tetrahedron: split_edge: new element -<12,13,27,29> "
                                "would be flat in the deformed positions");
    EXPECT_EQ(refused.code(), RefusalCode::would_flatten);
    const auto a = marking.vertices[0], b = marking.vertices[1];
    const auto c = marking.vertices[2], d = marking.vertices[3];
    expect_same_state(mesh, before);
    EXPECT_FALSE(state->is_stale()) << state->stale_reason();
    std::size_t i = 0;
    for (ElementId t : elements(mesh)) EXPECT_TRUE(same_marking(state->marking(t), markings_before[i++]));
    EXPECT_EQ(watcher.inits, 1);
    EXPECT_EQ(watcher.removed + watcher.changed + watcher.added, 0);
    EXPECT_EQ(watcher.boundary_removed_count + watcher.boundary_changed_count +
                  watcher.boundary_added_count,
              0);

    // refine_around, with its many bisections, is one transaction too
    Point x{};
    for (VertexId v : {a, b, c, d})
        for (std::size_t k = 0; k < 3; ++k) x[k] += mesh.reference(v)[k] / 4;
    const auto refused_around = refine_around_tetrahedra(*state, x, 0.01);
    ASSERT_FALSE(refused_around.ok());
    EXPECT_EQ(refused_around.reason(), "refine_around_tetrahedra: " + refused.reason());
    EXPECT_EQ(refused_around.code(), refused.code());
    expect_same_state(mesh, before);
    EXPECT_FALSE(state->is_stale()) << state->stale_reason();
    i = 0;
    for (ElementId t : elements(mesh)) EXPECT_TRUE(same_marking(state->marking(t), markings_before[i++]));
    EXPECT_EQ(watcher.removed + watcher.changed + watcher.added, 0);

    // the state-less form (longest-edge marks, its own recursion) refuses untouched as well
    const auto refused_stateless = refine_around_tetrahedra(mesh, x, 0.01);
    ASSERT_FALSE(refused_stateless.ok());
    EXPECT_EQ(refused_stateless.reason().rfind("refine_around_tetrahedra: split_edge: new element ", 0), 0u)
        << refused_stateless.reason();
    EXPECT_NE(refused_stateless.reason().find(" would be flat in the deformed positions"),
              std::string::npos)
        << refused_stateless.reason();
    EXPECT_EQ(refused_stateless.code(), RefusalCode::would_flatten);
    expect_same_state(mesh, before);
    EXPECT_EQ(watcher.removed + watcher.changed + watcher.added, 0);

    // with the vertex back in place the bisection goes through and gives the twin's mesh
    mesh.set_deformed(moved, original);
    mesh.remove_watcher(watcher);
    const auto bisected = bisect_tetrahedron(*state, child);
    ASSERT_TRUE(bisected.ok()) << bisected.reason();
    EXPECT_EQ(*bisected, *twin_bisected);
    expect_same_state(mesh, twin);
    expect_conforming(*state, 8.0, 24.0);
}


TEST(RefineAroundTetrahedra, RefusesWithReasonAndUntouchedMesh) {
    Mesh mesh = test::kuhn_cube(1);
    auto state = TetBisection::for_kuhn_mesh(mesh);
    ASSERT_TRUE(state.ok()) << state.reason();
    const Mesh before = mesh;
    auto refused = refine_around_tetrahedra(*state, {2, 0.5, 0.5}, 0.1);
    ASSERT_FALSE(refused.ok());
    EXPECT_EQ(refused.reason(), "refine_around_tetrahedra: point (2, 0.5, 0.5) is not in the mesh");
    EXPECT_EQ(refused.code(), RefusalCode::not_found);
    expect_same_state(mesh, before);
    refused = refine_around_tetrahedra(*state, {0.5, 0.5, 0.5}, 0);
    ASSERT_FALSE(refused.ok());
    EXPECT_EQ(refused.reason(), "refine_around_tetrahedra: h = 0 is not positive");
    EXPECT_EQ(refused.code(), RefusalCode::bad_argument);
    refused = refine_around_tetrahedra(*state, {0.5, 0.5, 0.5}, -1);
    ASSERT_FALSE(refused.ok());
    EXPECT_EQ(refused.reason(), "refine_around_tetrahedra: h = -1 is not positive");
    EXPECT_EQ(refused.code(), RefusalCode::bad_argument);
    refused = refine_around_tetrahedra(*state, {0.5, 0.5, 0.5}, std::numeric_limits<double>::quiet_NaN());
    ASSERT_FALSE(refused.ok());
    EXPECT_EQ(refused.reason(), "refine_around_tetrahedra: h = nan is not positive");
    EXPECT_EQ(refused.code(), RefusalCode::bad_argument);
    refused = refine_around_tetrahedra(
        *state, {std::numeric_limits<double>::quiet_NaN(), 0.5, 0.5}, 0.1);
    ASSERT_FALSE(refused.ok());
    EXPECT_EQ(refused.reason(), "refine_around_tetrahedra: point (nan, 0.5, 0.5) is not in the mesh");
    EXPECT_EQ(refused.code(), RefusalCode::not_found);
    expect_same_state(mesh, before);
    EXPECT_FALSE(state->is_stale());

    // the state-less form refuses the same way
    refused = refine_around_tetrahedra(mesh, {-0.5, 0.5, 0.5}, 0.1);
    ASSERT_FALSE(refused.ok());
    EXPECT_EQ(refused.reason(), "refine_around_tetrahedra: point (-0.5, 0.5, 0.5) is not in the mesh");
    EXPECT_EQ(refused.code(), RefusalCode::not_found);
    expect_same_state(mesh, before);
}

// An edge whose tetrahedra are two fans joined only at the edge cannot be bisected (the midpoint's
// star would be pinched): refused before anything changes by both replays, the split_edge one of
// Maubach's rule and AMP's one replace_elements, which skips the star walks (a ProvenEdit) and
// checks the edges it bisects instead. The point is the edge's midpoint: the tetrahedron holding
// it holds the edge until the edge is bisected.
TEST(RefineAroundTetrahedra, RefusesToBisectAnEdgeWhoseTetrahedraAreTwoFans) {
    std::optional<test::TwoFanEdge> fans = test::two_fan_edge();
    ASSERT_TRUE(fans) << "no edge of the cube became two fans";
    Mesh& mesh = fans->mesh;
    const Point &a = mesh.reference(fans->a), &b = mesh.reference(fans->b);
    const Point x{(a[0] + b[0]) / 2, (a[1] + b[1]) / 2, (a[2] + b[2]) / 2};
    const std::string around = "the tetrahedra around " + to_text(Simplex(+1, {fans->a, fans->b})) +
                               " are 2 fans joined only at the edge: bisecting it would pinch the new vertex's star";
    const Mesh before = mesh;
    auto maubach = TetBisection::for_kuhn_mesh(mesh);
    ASSERT_TRUE(maubach.ok()) << maubach.reason();
    auto refused = refine_around_tetrahedra(*maubach, x, 0.01);
    ASSERT_FALSE(refused.ok());
    EXPECT_EQ(refused.code(), RefusalCode::pinched_star);
    EXPECT_EQ(refused.reason(), "refine_around_tetrahedra: " + around);
    expect_same_state(mesh, before);
    auto amp = TetBisection::with_amp_marking(mesh);
    ASSERT_TRUE(amp.ok()) << amp.reason();
    refused = refine_around_tetrahedra(*amp, x, 0.01);
    ASSERT_FALSE(refused.ok());
    EXPECT_EQ(refused.code(), RefusalCode::pinched_star);
    EXPECT_EQ(refused.reason(), "refine_around_tetrahedra: bisect_tetrahedron: " + around);
    expect_same_state(mesh, before);
    EXPECT_FALSE(amp->is_stale());
    // away from the edge (the centroid of the tetrahedron farthest from it) AMP refines, and the
    // mesh stays valid
    Point far = x;
    double farthest = 0;
    for (const ElementId t : elements(mesh)) {
        Point c{0, 0, 0};
        for (const VertexId v : mesh.simplex(t).vertices())
            for (int k = 0; k < 3; ++k) c[k] += mesh.reference(v)[k] / 4;
        const double d = std::hypot(c[0] - x[0], c[1] - x[1], c[2] - x[2]);
        if (d > farthest) farthest = d, far = c;
    }
    const auto refined = refine_around_tetrahedra(*amp, far, 0.1);
    ASSERT_TRUE(refined.ok()) << refined.reason();
    EXPECT_GT(*refined, 0u);
    EXPECT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
}

TEST(RefineAroundTetrahedra, RefusesTriangleMeshes) {
    Mesh mesh = test::unit_square();
    const Mesh before = mesh;
    const auto refused = refine_around_tetrahedra(mesh, {0.5, 0.5, 0}, 0.1);
    ASSERT_FALSE(refused.ok());
    EXPECT_EQ(refused.reason(), "refine_around_tetrahedra: the mesh has triangles, not tetrahedra");
    EXPECT_EQ(refused.code(), RefusalCode::wrong_dimension);
    expect_same_state(mesh, before);
    const auto state = TetBisection::with_initial_marking(mesh);
    ASSERT_FALSE(state.ok());
    EXPECT_EQ(state.reason(), "tet_bisection: the mesh has triangles, not tetrahedra");
    EXPECT_EQ(state.code(), RefusalCode::wrong_dimension);
    const auto kuhn = TetBisection::for_kuhn_mesh(mesh);
    ASSERT_FALSE(kuhn.ok());
    EXPECT_EQ(kuhn.reason(), "tet_bisection: the mesh has triangles, not tetrahedra");
    EXPECT_EQ(kuhn.code(), RefusalCode::wrong_dimension);
    expect_same_state(mesh, before);
}

TEST(TetBisection, ForKuhnMeshRefusesOtherMeshes) {
    std::mt19937_64 random(7);
    Mesh mesh = jittered_kuhn_cube(2, random);
    const Mesh before = mesh;
    const auto state = TetBisection::for_kuhn_mesh(mesh);
    ASSERT_FALSE(state.ok());
    // element 0 of kuhn_cube(2) has the vertex (1,1,1), which the jitter moved
    EXPECT_EQ(state.reason(), "tet_bisection: element 0 is not a Kuhn tetrahedron");
    EXPECT_EQ(state.code(), RefusalCode::not_applicable);
    expect_same_state(mesh, before);
}

TEST(BisectTetrahedron, RefusesAnUnknownElement) {
    Mesh mesh = test::kuhn_cube(1);
    auto state = TetBisection::for_kuhn_mesh(mesh);
    ASSERT_TRUE(state.ok()) << state.reason();
    const Mesh before = mesh;
    const auto refused = bisect_tetrahedron(*state, 999);
    ASSERT_FALSE(refused.ok());
    EXPECT_EQ(refused.reason(), "bisect_tetrahedron: 999 is not an element");
    EXPECT_EQ(refused.code(), RefusalCode::not_found);
    expect_same_state(mesh, before);
}

// An edit that does not come from the state makes it stale: refusals name why, nothing changes.
TEST(TetBisection, ForeignEditMakesTheStateStale) {
    Mesh mesh = test::kuhn_cube(1);
    auto state = TetBisection::for_kuhn_mesh(mesh);
    ASSERT_TRUE(state.ok()) << state.reason();
    ASSERT_TRUE(bisect_tetrahedron(*state, 0).ok());
    EXPECT_FALSE(state->is_stale());
    // someone else splits an edge
    ASSERT_TRUE(split_edge(mesh, 0, 1).ok());
    ASSERT_TRUE(state->is_stale());
    const std::string why = state->stale_reason();
    EXPECT_EQ(why.rfind("the mesh was edited outside the bisection (", 0), 0u) << why;
    const Mesh before = mesh;
    auto refused = refine_around_tetrahedra(*state, {0.5, 0.5, 0.5}, 0.1);
    ASSERT_FALSE(refused.ok());
    EXPECT_EQ(refused.reason(), "refine_around_tetrahedra: the bisection state is stale: " + why);
    EXPECT_EQ(refused.code(), RefusalCode::stale);
    ElementId any = *elements(mesh).begin();
    refused = bisect_tetrahedron(*state, any);
    ASSERT_FALSE(refused.ok());
    EXPECT_EQ(refused.reason(), "bisect_tetrahedron: the bisection state is stale: " + why);
    EXPECT_EQ(refused.code(), RefusalCode::stale);
    expect_same_state(mesh, before);

    // a fresh state works again
    auto fresh = TetBisection::with_initial_marking(mesh);
    ASSERT_TRUE(fresh.ok()) << fresh.reason();
    const auto refined = refine_around_tetrahedra(*fresh, {0.5, 0.5, 0.5}, 0.3);
    ASSERT_TRUE(refined.ok()) << refined.reason();
    expect_conforming(*fresh, 1.0, 6.0);
}

// Assigning another mesh's content goes through init: stale too. A moved state keeps watching.
TEST(TetBisection, AssignmentAndMovesAreTracked) {
    Mesh mesh = test::kuhn_cube(1);
    auto built = TetBisection::for_kuhn_mesh(mesh);
    ASSERT_TRUE(built.ok()) << built.reason();
    TetBisection state = std::move(*built);
    ASSERT_TRUE(bisect_tetrahedron(state, 0).ok());
    EXPECT_FALSE(state.is_stale());
    TetBisection moved = std::move(state);
    EXPECT_FALSE(moved.is_stale());
    ASSERT_TRUE(refine_around_tetrahedra(moved, {0.2, 0.2, 0.2}, 0.4).ok());
    EXPECT_FALSE(moved.is_stale());
    const Mesh other = test::kuhn_cube(1);
    mesh = other;  // copy assignment: the watchers are told through init
    ASSERT_TRUE(moved.is_stale());
    EXPECT_EQ(moved.stale_reason(), "the mesh was edited outside the bisection (its elements were assigned anew)");
    EXPECT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
}


// ---- Arnold-Mukherjee-Pouly: refinement to conformity on any mesh ---------------------------------
//
// with_amp_marking: AMP's initial marking (longest edges), children by AMP's rules, and AMP's own
// algorithm: bisect one tetrahedron at its refinement edge, then every tetrahedron with a hanging
// node at its own refinement edge until the mesh is conforming (planned on an overlay, replayed
// as one replace_elements):
//
//          c                      c                         c
//         /|\   bisect abcd       /|\   abce (below ab)     /|\   ... until no leaf has
//        / | \  at ab, only it   / | \  has the hanging    / | \  a midpoint on one of
//       a--d--b    ------->     a--m--b node m: bisect it a--m--b its edges (AMP prove
//        \ | /  (not abce)       \ | /  at ITS refinement  \ | /  that this ends)
//         \|/ e below             \|/   edge, say ae       n-e
//          e                       e                   (n = mid(a, e))
//
// Oracle of every AMP test: validate() (which also checks that face labels name faces), exact
// positive orientation in both position sets, check_marking(), total volume, boundary area and
// the area carried by each face label unchanged (relative 1e-12), and a vertex attribute equal
// to the x coordinate, bit for bit, at every vertex (midpoints interpolate it as their position).

// Labels on every boundary face (1, 2, 3 by face id) and on the first face of every seventh
// element when that face is inside (label 9: an interface between two materials).
void label_faces(Mesh& mesh) {
    for (FaceId f : mesh.boundary_faces())
        mesh.face_labels()[Simplex(+1, mesh.face_simplex(f).vertices())] = 1 + static_cast<int>(f % 3);
    for (ElementId t : elements(mesh))
        if (t % 7 == 0 && mesh.mate(mesh.face(t, 0)) != invalid_id)
            mesh.face_labels()[Simplex(+1, mesh.face_simplex(mesh.face(t, 0)).vertices())] = 9;
}

std::map<int, double> labelled_areas(const Mesh& mesh) {
    std::map<int, double> areas;
    for (const auto& [face, label] : mesh.face_labels()) {
        const Point& a = mesh.reference(face.vertex(0));
        const Point n = cross(minus(mesh.reference(face.vertex(1)), a), minus(mesh.reference(face.vertex(2)), a));
        areas[label] += std::sqrt(dot(n, n)) / 2;
    }
    return areas;
}

AttributeId add_x_attribute(Mesh& mesh) {
    const auto attribute = mesh.add_vertex_attribute("x", 1);
    EXPECT_TRUE(attribute.ok()) << attribute.reason();
    for (VertexId v = 0; v < mesh.vertex_count(); ++v) mesh.vertex_attribute(*attribute, v)[0] = mesh.reference(v)[0];
    return *attribute;
}

struct AmpStart {
    double volume = 0, area = 0;
    std::map<int, double> labelled;
};

AmpStart amp_start(const Mesh& mesh) { return {total_volume(mesh), boundary_area(mesh), labelled_areas(mesh)}; }

void expect_amp_oracle(const TetBisection& state, const AmpStart& start) {
    const Mesh& mesh = state.mesh();
    ASSERT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
    EXPECT_TRUE(test::all_strictly_positive(mesh));
    const auto marks = state.check_marking();
    EXPECT_TRUE(marks.ok()) << marks.reason();
    EXPECT_FALSE(state.is_stale()) << state.stale_reason();
    EXPECT_NEAR(total_volume(mesh), start.volume, 1e-12 * start.volume);
    EXPECT_NEAR(boundary_area(mesh), start.area, 1e-12 * start.area);
    const auto labelled = labelled_areas(mesh);
    ASSERT_EQ(labelled.size(), start.labelled.size());
    for (const auto& [label, area] : start.labelled) EXPECT_NEAR(labelled.at(label), area, 1e-12 * area) << "label " << label;
    const AttributeId x = mesh.find_vertex_attribute("x");
    if (x != invalid_id) {
        for (VertexId v = 0; v < mesh.vertex_count(); ++v)
            ASSERT_EQ(mesh.vertex_attribute(x, v)[0], mesh.reference(v)[0]) << "vertex " << v;
    }
}

// Uniform refinement: every element of the start of a round that is still an element when its
// turn comes (same id, same simplex: replace_elements reuses the ids it frees) is bisected,
// with its closure.
void refine_uniformly(TetBisection& state) {
    std::vector<std::pair<ElementId, Simplex>> current;
    for (ElementId t : elements(state.mesh())) current.emplace_back(t, state.mesh().simplex(t));
    for (const auto& [t, simplex] : current)
        if (state.mesh().is_element(t) && state.mesh().simplex(t) == simplex) {
            const auto bisected = bisect_tetrahedron(state, t);
            ASSERT_TRUE(bisected.ok()) << bisected.reason();
        }
}

// The bound on the similarity classes of the descendants of one initial tetrahedron (itself
// included). AMP prove a finite bound; 36 is the number we recall from their paper for a
// tetrahedron of the P/A cycle (not checked against the text here), and it is what the tests
// measure as a plateau for single random tetrahedra. A first bisection turns every type into Pu,
// and from there AMP's rules are Maubach's on an affine image of a Kuhn tetrahedron; the two
// children of an O or M tetrahedron start two such cycles that need not share shapes, so
// 1 + 2 * 36 for those (measured: up to 69).
constexpr std::size_t amp_cycle_classes = 36;
std::size_t amp_classes_bound(TetType initial_type) {
    return initial_type == TetType::opposite || initial_type == TetType::mixed ? 1 + 2 * amp_cycle_classes
                                                                              : amp_cycle_classes;
}

// The similarity classes seen so far below each initial tetrahedron (each element goes to the
// element of `initial` containing its centroid), accumulated over calls or rounds.
struct ClassesPerInitial {
    std::map<ElementId, std::set<Signature>> below;
    std::set<Signature> all;
};

void add_classes_per_initial(const Mesh& mesh, const Mesh& initial, ClassesPerInitial& seen) {
    ElementId hint = invalid_id;
    for (ElementId t : elements(mesh)) {
        Point centre{0, 0, 0};
        for (VertexId v : mesh.simplex(t).vertices())
            for (std::size_t k = 0; k < 3; ++k) centre[k] += mesh.reference(v)[k] / 4;
        hint = locate_tetrahedron(initial, centre, hint);
        ASSERT_NE(hint, invalid_id);
        seen.below[hint].insert(shape_signature(mesh, t));
        seen.all.insert(shape_signature(mesh, t));
    }
}

// Checks the classes seen below each initial tetrahedron against amp_classes_bound, and all
// classes against the sum of the bounds. Returns the largest count below one initial
// tetrahedron for the two groups of initial types: {P or A, O or M}.
std::array<std::size_t, 2> expect_amp_classes_bounded(const ClassesPerInitial& seen, const Mesh& initial) {
    std::array<std::size_t, 2> most{0, 0};
    std::size_t total_bound = 0;
    for (ElementId t : elements(initial)) {
        const std::size_t bound = amp_classes_bound(tet_type(longest_edge_marking(initial, t)));
        total_bound += bound;
        const auto below = seen.below.find(t);
        const std::size_t count = below == seen.below.end() ? 0 : below->second.size();
        EXPECT_LE(count, bound) << "below initial element " << t;
        const std::size_t group = bound == amp_cycle_classes ? 0 : 1;
        most[group] = std::max(most[group], count);
    }
    EXPECT_LE(seen.all.size(), total_bound);
    return most;
}

TEST(TetBisection, WithAmpMarkingIsTheLongestEdgeMarkingUnflagged) {
    std::mt19937_64 random(3);
    Mesh mesh = delaunay_mesh(30, random);
    Mesh copy = mesh;
    auto amp = TetBisection::with_amp_marking(mesh);
    ASSERT_TRUE(amp.ok()) << amp.reason();
    EXPECT_EQ(amp->rule(), BisectionRule::arnold_mukherjee_pouly);
    EXPECT_TRUE(amp->check_marking().ok()) << amp->check_marking().reason();
    for (ElementId t : elements(mesh)) {
        EXPECT_TRUE(same_marking(amp->marking(t), longest_edge_marking(copy, t)));
        EXPECT_FALSE(amp->marking(t).flagged);
    }
    Mesh triangles = test::unit_square();
    const auto refused = TetBisection::with_amp_marking(triangles);
    ASSERT_FALSE(refused.ok());
    EXPECT_EQ(refused.reason(), "tet_bisection: the mesh has triangles, not tetrahedra");
    EXPECT_EQ(refused.code(), RefusalCode::wrong_dimension);
}

// One bisection: the element and whatever the closure needs, children marked by AMP's rules
// (never by length), so the mesh is conforming, and a leaf's marks are bisected_markings of its
// parent's.
TEST(BisectTetrahedron, AmpBisectsOneElementAndClosesToConformity) {
    std::mt19937_64 random(5);
    Mesh mesh = delaunay_mesh(40, random);
    label_faces(mesh);
    add_x_attribute(mesh);
    const AmpStart start = amp_start(mesh);
    auto state = TetBisection::with_amp_marking(mesh);
    ASSERT_TRUE(state.ok()) << state.reason();
    const ElementId t = *elements(mesh).begin();
    const TetMarking parent = state->marking(t);
    const Simplex parent_simplex = mesh.simplex(t);
    const std::size_t vertices = mesh.vertex_count(), count = mesh.element_count();
    const auto bisected = bisect_tetrahedron(*state, t);
    ASSERT_TRUE(bisected.ok()) << bisected.reason();
    EXPECT_GE(*bisected, 1u);
    EXPECT_EQ(mesh.vertex_count(), vertices + *bisected);
    EXPECT_FALSE(mesh.is_element(t) && mesh.simplex(t) == parent_simplex);
    // the midpoint of t's refinement edge is vertex `vertices`, bit for bit
    const auto [reference, deformed] = mesh.interpolated_positions(
        std::array<VertexId, 2>{parent.vertices[0], parent.vertices[1]}, std::array<double, 2>{0.5, 0.5});
    EXPECT_EQ(mesh.reference(static_cast<VertexId>(vertices)), reference);
    // both children of t are elements with their AMP marks (the closure bisects no child of t
    // in a conforming start: its new edges have no midpoints, its old ones are t's)
    const auto halves = bisected_markings(parent, static_cast<VertexId>(vertices));
    std::size_t found = 0;
    for (ElementId u : elements(mesh))
        for (const TetMarking& half : halves) {
            auto mine = state->marking(u).vertices, theirs = half.vertices;
            std::sort(mine.begin(), mine.end());
            std::sort(theirs.begin(), theirs.end());
            if (mine != theirs) continue;
            ++found;
            EXPECT_TRUE(same_marking(state->marking(u), half));
        }
    EXPECT_EQ(found, 2u);
    EXPECT_GT(mesh.element_count(), count);
    EXPECT_GE(state->marking(state->last_child()).generation, 1u);
    expect_amp_oracle(*state, start);
}

// The marks AMP use, run through the split_edge recursion (the plan of the other two rules):
// on some of these meshes that recursion meets a cycle, which is why AMP was withdrawn before.
// The AMP rule refines the same meshes, the same calls, to conformity.
bool split_edge_recursion_cycles(const Mesh& mesh, std::uint64_t seed) {
    Mesh copy = mesh;
    std::vector<TetMarking> marks(copy.element_capacity());
    for (ElementId t : elements(copy)) marks[t] = longest_edge_marking(copy, t);
    std::mt19937_64 random(seed);
    std::uniform_real_distribution<double> coordinate(0.0, 1.0);
    std::uniform_real_distribution<double> log_h(std::log(0.06), std::log(0.5));
    for (int call = 0; call < 200; ++call) {
        const Point x{coordinate(random), coordinate(random), coordinate(random)};
        const double h = std::exp(log_h(random));
        const ElementId t = locate_tetrahedron(copy, x, invalid_id);
        detail::TetBisectionPlan plan(copy, BisectionRule::newest_vertex, [&](ElementId u) { return marks[u]; });
        bool did_not_end = false;
        const auto planned = detail::plan_refine_around(plan, t, x, h, did_not_end);
        if (did_not_end) return true;
        if (!planned.ok()) return false;
        // replay by hand (split_edge), marking the children as the plan did
        for (const auto& e : plan.splits()) {
            std::vector<TetMarking> parents;
            for (ElementId u : detail::elements_with_edge(copy, e[0], e[1])) parents.push_back(marks[u]);
            const auto split = split_edge(copy, e[0], e[1], 0.5);
            if (!split.ok()) return false;
            marks.resize(copy.element_capacity());
            for (ElementId child : split->elements)
                for (const TetMarking& p : parents)
                    if (copy.simplex(child).contains(p.vertices[2]) && copy.simplex(child).contains(p.vertices[3])) {
                        const auto halves = bisected_markings(p, split->vertex);
                        marks[child] = copy.simplex(child).contains(p.vertices[0]) ? halves[0] : halves[1];
                        break;
                    }
        }
    }
    return false;
}

// (a) Many random refine_around calls on random Delaunay meshes (seeds 1..12, the count of the
// study that withdrew AMP, and one random seed): every call succeeds (the closure's bound is
// never reached), and the oracle holds after every 250 calls. The similarity classes are
// printed beside longest-edge's for the same calls.
TEST(RefineAroundTetrahedra, AmpOnRandomDelaunayMeshes) {
    const std::uint64_t random_seed = seed_for("RefineAroundTetrahedra.AmpOnRandomDelaunayMeshes");
    std::vector<std::uint64_t> seeds{1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, random_seed};
    std::size_t cycled = 0, total_calls = 0;
    for (const std::uint64_t seed : seeds) {
        SCOPED_TRACE("mesh seed " + std::to_string(seed));
        std::mt19937_64 random(seed);
        const Mesh initial = delaunay_mesh(60, random);
        if (seed != random_seed && split_edge_recursion_cycles(initial, seed)) ++cycled;
        std::size_t classes[2] = {0, 0}, counts[2] = {0, 0};
        std::array<std::size_t, 2> most_per_initial{0, 0};
        for (const bool amp : {true, false}) {
            Mesh mesh = initial;
            label_faces(mesh);
            add_x_attribute(mesh);
            const AmpStart start = amp_start(mesh);
            auto state = amp ? TetBisection::with_amp_marking(mesh) : TetBisection::with_initial_marking(mesh);
            ASSERT_TRUE(state.ok()) << state.reason();
            std::mt19937_64 calls(seed * 7919 + 1);
            std::uniform_real_distribution<double> coordinate(0.0, 1.0);
            std::uniform_real_distribution<double> log_h(std::log(0.06), std::log(0.5));
            std::set<Signature> shapes;
            add_shapes(mesh, shapes);
            ClassesPerInitial seen;
            if (amp) add_classes_per_initial(mesh, initial, seen);
            for (int call = 0; call < 750; ++call) {
                const Point x{coordinate(calls), coordinate(calls), coordinate(calls)};
                const double h = std::exp(log_h(calls));
                const auto refined = refine_around_tetrahedra(*state, x, h);
                ASSERT_TRUE(refined.ok()) << refined.reason();
                if (amp) {
                    ++total_calls;
                    const ElementId t = locate_tetrahedron(mesh, x, state->last_child());
                    ASSERT_NE(t, invalid_id);
                    const auto e = state->refinement_edge(t);
                    const Point d = minus(mesh.reference(e[0]), mesh.reference(e[1]));
                    ASSERT_LE(std::sqrt(dot(d, d)), h);
                }
                if (call % 250 == 249) {
                    if (amp) {
                        expect_amp_oracle(*state, start);
                        add_classes_per_initial(mesh, initial, seen);
                    }
                    add_shapes(mesh, shapes);
                }
            }
            classes[amp ? 0 : 1] = shapes.size();
            counts[amp ? 0 : 1] = mesh.element_count();
            if (amp) most_per_initial = expect_amp_classes_bounded(seen, initial);
            EXPECT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
        }
        std::cout << "Delaunay seed " << seed << ", " << initial.element_count()
                  << " tetrahedra, 750 calls: AMP " << counts[0] << " tetrahedra, " << classes[0]
                  << " similarity classes (at most " << most_per_initial[0] << " / "
                  << most_per_initial[1] << " below one initial P or A / O or M tetrahedron); longest-edge " << counts[1] << " tetrahedra, "
                  << classes[1] << " classes\n";
    }
    std::cout << "the split_edge recursion with AMP's marks cycled on " << cycled
              << " of 12 seeds; AMP's closure ended on all, " << total_calls << " calls\n";
}

// (b) Uniform refinement: the classes stay below the bound per initial tetrahedron
// (amp_classes_bound). On single random tetrahedra (12 rounds) they stop growing: none new in
// the last three rounds (measured: the plateau, 36 for P/A and 69 for O/M, from round 7 on).
// On a small Delaunay mesh (7 rounds; its AMP closures make it grow ~2.5x a round) the bound is
// asserted and the counts printed. Longest-edge's counts on the same meshes are printed, not
// asserted (8 rounds: it grows fast).
TEST(BisectTetrahedron, AmpShapesStayBoundedUnderUniformRefinement) {
    const std::uint64_t seed = seed_for("BisectTetrahedron.AmpShapesStayBoundedUnderUniformRefinement");
    SCOPED_TRACE("SXK_SEED=" + std::to_string(seed));
    std::mt19937_64 random(seed);
    std::vector<Mesh> meshes;
    meshes.push_back(delaunay_mesh(1, random));
    std::uniform_real_distribution<double> coordinate(-1.0, 1.0);
    while (meshes.size() < 7) {
        Mesh mesh(3, 3);
        for (int i = 0; i < 4; ++i) mesh.add_vertex({coordinate(random), coordinate(random), coordinate(random)});
        const Sign sign = orient3d(mesh.reference(0), mesh.reference(1), mesh.reference(2), mesh.reference(3));
        if (sign == Sign::zero) continue;
        const std::array<Simplex, 1> tet{Simplex(sign == Sign::positive ? +1 : -1, {0, 1, 2, 3})};
        ASSERT_TRUE(mesh.assign_elements(tet).ok());
        meshes.push_back(std::move(mesh));
    }
    for (std::size_t which = 0; which < meshes.size(); ++which) {
        const Mesh& initial = meshes[which];
        std::vector<std::size_t> per_round[2];
        std::array<std::size_t, 2> most{0, 0};
        for (const bool amp : {true, false}) {
            const int rounds = which == 0 ? 7 : (amp ? 12 : 8);
            Mesh mesh = initial;
            label_faces(mesh);
            const AmpStart start = amp_start(mesh);
            auto state = amp ? TetBisection::with_amp_marking(mesh) : TetBisection::with_initial_marking(mesh);
            ASSERT_TRUE(state.ok()) << state.reason();
            std::set<Signature> shapes;
            add_shapes(mesh, shapes);
            ClassesPerInitial seen;
            if (amp) add_classes_per_initial(mesh, initial, seen);
            for (int round = 0; round < rounds; ++round) {
                refine_uniformly(*state);
                add_shapes(mesh, shapes);
                if (amp) add_classes_per_initial(mesh, initial, seen);
                per_round[amp ? 0 : 1].push_back(shapes.size());
            }
            if (amp) {
                expect_amp_oracle(*state, start);
                most = expect_amp_classes_bounded(seen, initial);
                // the plateau: every class seen after the last round was there three rounds before
                if (which > 0) {
                    EXPECT_EQ(per_round[0][static_cast<std::size_t>(rounds) - 4], per_round[0].back());
                }
            }
            EXPECT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
        }
        std::cout << (which == 0 ? "Delaunay mesh of " + std::to_string(initial.element_count()) + " tetrahedra"
                                 : std::string("one random tetrahedron"))
                  << ", classes seen after each uniform round: AMP";
        for (std::size_t n : per_round[0]) std::cout << ' ' << n;
        std::cout << " (at most " << most[0] << " / " << most[1]
                  << " below one initial P or A / O or M tetrahedron); longest-edge";
        for (std::size_t n : per_round[1]) std::cout << ' ' << n;
        std::cout << '\n';
    }
}

// (c) A refusal in the middle of a closure: an element the closure reaches, sharing no vertex
// with the element bisected, is made flat in the deformed positions (one vertex moved onto
// another; flatten_deformed's plane is exact only on dyadic grids). The call is refused and
// mesh, labels, attributes, state and watchers are exactly as before; with the vertex back, the
// same call gives the mesh of a run that never had the flat element.
TEST(BisectTetrahedron, AmpRefusalInTheMiddleOfTheClosureChangesNothing) {
    std::mt19937_64 random(11);
    Mesh initial = delaunay_mesh(60, random);
    label_faces(initial);
    add_x_attribute(initial);
    // find t and a far element u that t's closure bisects
    ElementId t = invalid_id, far = invalid_id;
    Mesh twin(3, 3);
    for (ElementId candidate : elements(initial)) {
        twin = initial;
        auto twin_state = TetBisection::with_amp_marking(twin);
        ASSERT_TRUE(twin_state.ok()) << twin_state.reason();
        ASSERT_TRUE(bisect_tetrahedron(*twin_state, candidate).ok());
        for (ElementId u : elements(initial)) {
            if (twin.is_element(u) && twin.simplex(u) == initial.simplex(u)) continue;  // kept
            bool shares = false;
            for (VertexId v : initial.simplex(u).vertices()) shares = shares || initial.simplex(candidate).contains(v);
            if (!shares) far = u;
        }
        if (far != invalid_id) {
            t = candidate;
            break;
        }
    }
    ASSERT_NE(far, invalid_id) << "no closure reached an element away from the one bisected";

    Mesh mesh = initial;
    auto state = TetBisection::with_amp_marking(mesh);
    ASSERT_TRUE(state.ok()) << state.reason();
    const TetMarking marking = state->marking(far);
    // a onto b in the deformed positions: `far` and its child keeping a are exactly flat there
    // (the midpoint of ab is then b, bit for bit)
    const Point original = mesh.deformed(marking.vertices[0]);
    mesh.set_deformed(marking.vertices[0], mesh.deformed(marking.vertices[1]));
    const Mesh before = mesh;
    std::vector<TetMarking> markings_before;
    for (ElementId u : elements(mesh)) markings_before.push_back(state->marking(u));
    const AttributeId x = mesh.find_vertex_attribute("x");
    test::CountingWatcher watcher;
    mesh.add_watcher(watcher);

    const auto refused = bisect_tetrahedron(*state, t);
    ASSERT_FALSE(refused.ok());
    EXPECT_EQ(refused.reason().rfind("bisect_tetrahedron: new element ", 0), 0u) << refused.reason();
    EXPECT_NE(refused.reason().find(" would be flat in the deformed positions"), std::string::npos)
        << refused.reason();
    EXPECT_EQ(refused.code(), RefusalCode::would_flatten);
    std::cout << "refused: " << refused.reason() << '\n';
    // the child named is one that has the moved vertex a (from far or another element around a)
    const std::string a = std::to_string(marking.vertices[0]);
    EXPECT_TRUE(refused.reason().find("<" + a + ",") != std::string::npos ||
                refused.reason().find("," + a + ",") != std::string::npos ||
                refused.reason().find("," + a + ">") != std::string::npos)
        << refused.reason();
    expect_same_state(mesh, before);
    EXPECT_EQ(mesh.vertex_attributes(), before.vertex_attributes());
    for (VertexId v = 0; v < mesh.vertex_count(); ++v)
        EXPECT_EQ(mesh.vertex_attribute(x, v)[0], before.vertex_attribute(x, v)[0]);
    EXPECT_FALSE(state->is_stale()) << state->stale_reason();
    std::size_t i = 0;
    for (ElementId u : elements(mesh)) EXPECT_TRUE(same_marking(state->marking(u), markings_before[i++]));
    EXPECT_EQ(watcher.inits, 1);
    EXPECT_EQ(watcher.removed + watcher.changed + watcher.added, 0);
    EXPECT_EQ(watcher.boundary_removed_count + watcher.boundary_changed_count + watcher.boundary_added_count, 0);

    // refine_around through the same element: one transaction, refused alike
    Point centre{};
    for (VertexId v : mesh.simplex(t).vertices())
        for (std::size_t k = 0; k < 3; ++k) centre[k] += mesh.reference(v)[k] / 4;
    const auto refused_around = refine_around_tetrahedra(*state, centre, 1e-3);
    ASSERT_FALSE(refused_around.ok());
    EXPECT_EQ(refused_around.reason().rfind("refine_around_tetrahedra: bisect_tetrahedron: new element ", 0), 0u)
        << refused_around.reason();
    EXPECT_EQ(refused_around.code(), refused.code());
    expect_same_state(mesh, before);
    EXPECT_FALSE(state->is_stale()) << state->stale_reason();
    EXPECT_EQ(watcher.removed + watcher.changed + watcher.added, 0);

    mesh.set_deformed(marking.vertices[0], original);
    mesh.remove_watcher(watcher);
    const auto bisected = bisect_tetrahedron(*state, t);
    ASSERT_TRUE(bisected.ok()) << bisected.reason();
    expect_same_state(mesh, twin);
    expect_amp_oracle(*state, amp_start(initial));
}

// (d) On a Kuhn mesh AMP's initial marking is Maubach's tuples (longest edges, type A,
// unflagged), so refinement to conformity gives the mesh the Maubach recursion gives: the same
// tetrahedra (by reference positions), in 3 similarity classes.
TEST(RefineAroundTetrahedra, AmpOnAKuhnCubeIsConformingAndMaubachs) {
    const std::uint64_t seed = seed_for("RefineAroundTetrahedra.AmpOnAKuhnCubeIsConformingAndMaubachs");
    SCOPED_TRACE("SXK_SEED=" + std::to_string(seed));
    Mesh amp_mesh = test::kuhn_cube(2);
    Mesh maubach_mesh = amp_mesh;
    label_faces(amp_mesh);
    add_x_attribute(amp_mesh);
    const AmpStart start = amp_start(amp_mesh);
    auto amp = TetBisection::with_amp_marking(amp_mesh);
    ASSERT_TRUE(amp.ok()) << amp.reason();
    auto maubach = TetBisection::for_kuhn_mesh(maubach_mesh);
    ASSERT_TRUE(maubach.ok()) << maubach.reason();
    std::mt19937_64 random(seed);
    std::uniform_real_distribution<double> coordinate(0.0, 2.0);
    std::uniform_real_distribution<double> log_h(std::log(0.1), std::log(1.0));
    for (int call = 0; call < 300; ++call) {
        const Point x{coordinate(random), coordinate(random), coordinate(random)};
        const double h = std::exp(log_h(random));
        const auto refined = refine_around_tetrahedra(*amp, x, h);
        ASSERT_TRUE(refined.ok()) << refined.reason();
        ASSERT_TRUE(refine_around_tetrahedra(*maubach, x, h).ok());
    }
    expect_amp_oracle(*amp, start);
    std::set<Signature> shapes;
    add_shapes(amp_mesh, shapes);
    EXPECT_EQ(shapes.size(), 3u);
    auto geometry = [](const Mesh& mesh) {
        std::vector<std::array<Point, 4>> all;
        for (ElementId t : elements(mesh)) {
            std::array<Point, 4> corners{};
            for (int j = 0; j < 4; ++j) corners[static_cast<std::size_t>(j)] = mesh.reference(mesh.simplex(t).vertex(j));
            std::sort(corners.begin(), corners.end());
            all.push_back(corners);
        }
        std::sort(all.begin(), all.end());
        return all;
    };
    EXPECT_EQ(amp_mesh.element_count(), maubach_mesh.element_count());
    EXPECT_TRUE(geometry(amp_mesh) == geometry(maubach_mesh));
    std::cout << "Kuhn cube, 300 calls: AMP " << amp_mesh.element_count() << " tetrahedra, Maubach "
              << maubach_mesh.element_count() << "\n";
}

}  // namespace
}  // namespace sxk
