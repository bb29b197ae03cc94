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
#include <random>
#include <set>
#include <string>
#include <vector>

#include "ops/split_collapse_fixtures.hpp"
#include "sxk/ops/refine_around_tetrahedra.hpp"
#include "sxk/ops/split_edge.hpp"
#include "sxk/ops/tet_bisection.hpp"
#include "sxk/predicates.hpp"

namespace sxk {
namespace {

using test::expect_same_state;
using Edge = std::array<VertexId, 2>;

std::uint64_t seed_for(const char* name) {
    std::uint64_t seed = std::random_device{}();
    if (const char* fixed = std::getenv("SXK_SEED")) seed = std::strtoull(fixed, nullptr, 10);
    std::cout << "[ seed     ] " << name << " SXK_SEED=" << seed << std::endl;
    return seed;
}

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

// Similarity signature: the six squared edge lengths, sorted, divided by the largest, rounded
// to 1e-7. Similar tetrahedra (mirror images included) have equal signatures.
using Signature = std::array<long long, 6>;
Signature shape_signature(const Mesh& mesh, ElementId t) {
    const Simplex& s = mesh.simplex(t);
    std::array<double, 6> lengths{};
    std::size_t next = 0;
    for (int i = 0; i < 4; ++i)
        for (int j = i + 1; j < 4; ++j) {
            const Point d = minus(mesh.reference(s.vertex(i)), mesh.reference(s.vertex(j)));
            lengths[next++] = dot(d, d);
        }
    std::sort(lengths.begin(), lengths.end());
    Signature signature{};
    for (std::size_t k = 0; k < 6; ++k) signature[k] = std::llround(lengths[k] / lengths[5] * 1e7);
    return signature;
}

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
    expect_same_state(mesh, before);
    refused = refine_around_tetrahedra(*state, {0.5, 0.5, 0.5}, 0);
    ASSERT_FALSE(refused.ok());
    EXPECT_EQ(refused.reason(), "refine_around_tetrahedra: h = 0 is not positive");
    refused = refine_around_tetrahedra(*state, {0.5, 0.5, 0.5}, -1);
    ASSERT_FALSE(refused.ok());
    EXPECT_EQ(refused.reason(), "refine_around_tetrahedra: h = -1 is not positive");
    refused = refine_around_tetrahedra(*state, {0.5, 0.5, 0.5}, std::numeric_limits<double>::quiet_NaN());
    ASSERT_FALSE(refused.ok());
    EXPECT_EQ(refused.reason(), "refine_around_tetrahedra: h = nan is not positive");
    refused = refine_around_tetrahedra(
        *state, {std::numeric_limits<double>::quiet_NaN(), 0.5, 0.5}, 0.1);
    ASSERT_FALSE(refused.ok());
    EXPECT_EQ(refused.reason(), "refine_around_tetrahedra: point (nan, 0.5, 0.5) is not in the mesh");
    expect_same_state(mesh, before);
    EXPECT_FALSE(state->is_stale());

    // the state-less form refuses the same way
    refused = refine_around_tetrahedra(mesh, {-0.5, 0.5, 0.5}, 0.1);
    ASSERT_FALSE(refused.ok());
    EXPECT_EQ(refused.reason(), "refine_around_tetrahedra: point (-0.5, 0.5, 0.5) is not in the mesh");
    expect_same_state(mesh, before);
}

TEST(RefineAroundTetrahedra, RefusesTriangleMeshes) {
    Mesh mesh = test::unit_square();
    const Mesh before = mesh;
    const auto refused = refine_around_tetrahedra(mesh, {0.5, 0.5, 0}, 0.1);
    ASSERT_FALSE(refused.ok());
    EXPECT_EQ(refused.reason(), "refine_around_tetrahedra: the mesh has triangles, not tetrahedra");
    expect_same_state(mesh, before);
    const auto state = TetBisection::with_initial_marking(mesh);
    ASSERT_FALSE(state.ok());
    EXPECT_EQ(state.reason(), "tet_bisection: the mesh has triangles, not tetrahedra");
    const auto kuhn = TetBisection::for_kuhn_mesh(mesh);
    ASSERT_FALSE(kuhn.ok());
    EXPECT_EQ(kuhn.reason(), "tet_bisection: the mesh has triangles, not tetrahedra");
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
    ElementId any = *elements(mesh).begin();
    refused = bisect_tetrahedron(*state, any);
    ASSERT_FALSE(refused.ok());
    EXPECT_EQ(refused.reason(), "bisect_tetrahedron: the bisection state is stale: " + why);
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

}  // namespace
}  // namespace sxk
