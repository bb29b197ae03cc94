// The fast paths of the surface operations (core/src/ops/filtered_triangle_tests.hpp,
// edge_star.hpp, link_condition.hpp, core/src/star_walk.hpp; used by flip_edge, split_edge and
// collapse_edge) against the slow definitions they replace:
//
//   triangle_normal + collinear_filtered / normal_alignment_filtered   sxk::collinear,
//                                                                       sxk::normal_alignment
//   fan_has_edge(mesh, t0, c, d): both ways round c's fan from t0       edge_exists (star walk)
//   edge_elements_into(mesh, a, b): stops at the first triangle          star(a) filtered by b
//   collapse_edge on triangle meshes: ProvenEdit (no star walks)         validate() afterwards
//
//        c ------- x          fan of c from t0 = <a,b,c>: one walk leaves t0 across {b,c}, the
//       / \  t0   / \         other across {c,a}; they meet on a closed fan, or both stop at
//      y   a --- b   z        the boundary on an open one
//
// Randomised tests print their seed and honour SXK_SEED.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <random>
#include <string>
#include <vector>

#include "../../fuzz/ops_driver.hpp"
#include "core/fixtures.hpp"
#include "ops/edge_star.hpp"
#include "ops/filtered_triangle_tests.hpp"
#include "ops/link_condition.hpp"
#include "split_collapse_fixtures.hpp"
#include "sxk/ops/collapse_edge.hpp"
#include "sxk/ops/flip_edge.hpp"
#include "sxk/ops/split_edge.hpp"
#include "sxk/predicates.hpp"
#include "sxk/traversal.hpp"

namespace sxk {
namespace {

// Points that stress the filters: random reals; small integers (exact zeros: collinear points,
// perpendicular normals); collinear points nudged by one ulp; everything scaled by 2^k (exact),
// from tiny to huge (beyond the filters' range, where they must hand over to the exact test).
struct PointMaker {
    std::mt19937_64 rng;
    double scale = 1;

    double real() { return std::uniform_real_distribution<double>(-1, 1)(rng); }
    double small_integer() { return static_cast<double>(static_cast<int>(rng() % 7) - 3); }
    Point random_point(bool integer) {
        return integer ? Point{small_integer(), small_integer(), small_integer()}
                       : Point{real(), real(), real()};
    }
    // Three points: random, exactly collinear, or collinear with one coordinate one ulp off.
    std::array<Point, 3> triangle(int kind) {
        const bool integer = kind % 2 == 1;
        std::array<Point, 3> t{random_point(integer), random_point(integer), random_point(integer)};
        if (kind >= 2) {
            // r = p + 2 (q - p): exact in doubles for small integers and for these reals often
            for (std::size_t k = 0; k < 3; ++k) t[2][k] = t[0][k] + 2 * (t[1][k] - t[0][k]);
            if (kind >= 4) {
                const std::size_t k = rng() % 3;
                t[2][k] = std::nextafter(t[2][k], (rng() & 1) ? 1e300 : -1e300);
            }
        }
        for (Point& p : t)
            for (double& x : p) x *= scale;
        return t;
    }
};

TEST(SurfaceFastPaths, FilteredTriangleTestsAgreeWithTheExactPredicates) {
    const std::uint64_t seed = test::seed_for("SurfaceFastPaths.FilteredTriangleTestsAgreeWithTheExactPredicates");
    SCOPED_TRACE("SXK_SEED=" + std::to_string(seed));
    PointMaker maker{std::mt19937_64(seed)};
    int collinear_cases = 0, zero_alignments = 0;
    for (int exponent : {0, -40, 40, -600, 600, -1020, 900}) {
        maker.scale = std::ldexp(1.0, exponent);
        for (int i = 0; i < 6000; ++i) {
            const auto s = maker.triangle(static_cast<int>(maker.rng() % 6));
            auto t = maker.triangle(static_cast<int>(maker.rng() % 6));
            if (maker.rng() % 3 == 0) t[0] = s[1], t[1] = s[0];  // sharing an edge, as in a flip
            const detail::TriangleNormal ns = detail::triangle_normal(s[0], s[1], s[2]);
            const detail::TriangleNormal nt = detail::triangle_normal(t[0], t[1], t[2]);
            const bool exact_collinear = collinear(s[0], s[1], s[2]);
            collinear_cases += exact_collinear;
            ASSERT_EQ(detail::collinear_filtered(s[0], s[1], s[2], ns), exact_collinear)
                << "scale 2^" << exponent << " case " << i;
            const Sign exact = normal_alignment(s[0], s[1], s[2], t[0], t[1], t[2]);
            zero_alignments += exact == Sign::zero;
            ASSERT_EQ(detail::normal_alignment_filtered(s[0], s[1], s[2], ns, t[0], t[1], t[2], nt), exact)
                << "scale 2^" << exponent << " case " << i;
        }
    }
    // the families above must reach the interesting cases, or the test proves little
    EXPECT_GT(collinear_cases, 1000);
    EXPECT_GT(zero_alignments, 1000);
}

// Triangle meshes with open fans (grid: corners, sides), closed fans (octahedron) and a fan of
// degree 3 (the closed surface of a tetrahedron).
std::vector<Mesh> small_triangle_meshes() {
    std::vector<Mesh> meshes;
    meshes.push_back(test::unit_square());
    meshes.push_back(test::planar_grid(3));
    meshes.push_back(ops_driver::octahedron(1));
    Mesh tetrahedron(2, 3);
    for (const Point& p : {Point{0, 0, 0}, Point{1, 0, 0}, Point{0, 1, 0}, Point{0, 0, 1}}) tetrahedron.add_vertex(p);
    const std::vector<Simplex> faces{Simplex(+1, {0, 2, 1}), Simplex(+1, {0, 1, 3}), Simplex(+1, {0, 3, 2}),
                                     Simplex(+1, {1, 2, 3})};
    EXPECT_TRUE(tetrahedron.assign_elements(faces).ok());
    meshes.push_back(std::move(tetrahedron));
    return meshes;
}

// A grid whose fans were reshaped by flips: vertices of odd and even degree, open and closed.
Mesh flipped_grid() {
    Mesh flipped = test::planar_grid(4);
    for (FaceId f = 0; f < flipped.face_capacity(); f = f + 3)
        if (flipped.is_face(f)) (void)flip_edge(flipped, f);
    EXPECT_TRUE(flipped.validate().ok());
    return flipped;
}

TEST(SurfaceFastPaths, FanWalkFindsExactlyTheEdges) {
    std::vector<Mesh> meshes = small_triangle_meshes();
    meshes.push_back(flipped_grid());
    int edges = 0, non_edges = 0;
    for (const Mesh& mesh : meshes)
        for (const ElementId t0 : elements(mesh))
            for (const VertexId c : mesh.simplex(t0).vertices())
                for (VertexId d = 0; d < mesh.vertex_count(); ++d) {
                    const bool expected = detail::edge_exists(mesh, c, d);
                    (expected ? edges : non_edges) += 1;
                    EXPECT_EQ(detail::fan_has_edge(mesh, t0, c, d), expected)
                        << "element " << t0 << " c " << c << " d " << d;
                }
    EXPECT_GT(edges, 100);
    EXPECT_GT(non_edges, 100);
}

TEST(SurfaceFastPaths, StarsAndEdgeElementsComeInStarOrder) {
    std::vector<Mesh> meshes = small_triangle_meshes();
    meshes.push_back(flipped_grid());
    meshes.push_back(test::kuhn_cube(2));
    int odd_closed_fans = 0;
    for (const Mesh& mesh : meshes)
        for (VertexId a = 0; a < mesh.vertex_count(); ++a) {
            const std::vector<ElementId> around = star(mesh, a);
            detail::SmallVector<ElementId, 64> walked;
            detail::star_into(mesh, a, walked);
            EXPECT_EQ(std::vector<ElementId>(walked.begin(), walked.end()), around) << "star of " << a;
            odd_closed_fans += mesh.topological_dimension() == 2 && around.size() % 2 == 1 &&
                               std::none_of(around.begin(), around.end(), [&](ElementId t) {
                                   for (int i = 0; i < 3; ++i)
                                       if (mesh.simplex(t).vertex(i) != a && mesh.neighbor(t, i) == invalid_id) return true;
                                   return false;
                               });
            for (VertexId b = 0; b < mesh.vertex_count(); ++b) {
                std::vector<ElementId> expected;
                for (const ElementId t : around)
                    if (mesh.simplex(t).contains(b)) expected.push_back(t);
                detail::SmallVector<ElementId, 64> found;
                detail::edge_elements_into(mesh, a, b, found);
                EXPECT_EQ(std::vector<ElementId>(found.begin(), found.end()), expected) << a << "-" << b;
                EXPECT_EQ(detail::elements_with_edge(mesh, a, b), expected) << a << "-" << b;
            }
        }
    EXPECT_GT(odd_closed_fans, 0);  // the walks close differently on odd and even cycles
}

// Every ordered edge of `mesh`: the triangle-mesh link condition against the generic one.
// Returns how many edges violate it.
int compare_link_conditions(const Mesh& mesh) {
    int violations = 0;
    for (const ElementId t : elements(mesh))
        for (const VertexId from : mesh.simplex(t).vertices())
            for (const VertexId to : mesh.simplex(t).vertices()) {
                if (from == to) continue;
                const std::vector<ElementId> star_from = star(mesh, from), star_to = star(mesh, to);
                const bool generic = detail::link_condition_holds(mesh, star_from, star_to, from, to);
                violations += !generic;
                EXPECT_EQ(detail::link_condition_holds_2d(mesh, star_from, star_to, from, to), generic)
                    << from << "->" << to;
            }
    return violations;
}

TEST(SurfaceFastPaths, TriangleLinkConditionAgreesWithTheGenericOne) {
    const std::uint64_t seed = test::seed_for("SurfaceFastPaths.TriangleLinkConditionAgreesWithTheGenericOne");
    SCOPED_TRACE("SXK_SEED=" + std::to_string(seed));
    std::mt19937_64 rng(seed);
    int violations = 0;
    for (const Mesh& mesh : small_triangle_meshes()) violations += compare_link_conditions(mesh);
    // meshes reshaped by random flips, splits and collapses (topology only: geometry does not
    // enter the link condition)
    for (Mesh mesh : {test::planar_grid(3), ops_driver::octahedron(1)}) {
        for (int step = 0; step < 150; ++step) {
            std::vector<ElementId> live;
            for (const ElementId u : elements(mesh)) live.push_back(u);
            const ElementId t = live[rng() % live.size()];
            const Simplex tau = mesh.simplex(t);
            const VertexId a = tau.vertex(static_cast<int>(rng() % 3));
            const VertexId b = tau.vertex(static_cast<int>((a == tau.vertex(0) ? 1 : 0)));
            switch (rng() % 3) {
                case 0: (void)flip_edge(mesh, mesh.face(t, static_cast<int>(rng() % 3)), {.topology_only = true}); break;
                case 1: (void)split_edge(mesh, a, b); break;
                default: (void)collapse_edge(mesh, a, b); break;
            }
            ASSERT_TRUE(mesh.validate().ok()) << "step " << step << ": " << mesh.validate().reason();
            violations += compare_link_conditions(mesh);
            if (::testing::Test::HasFailure()) FAIL() << "step " << step;
        }
    }
    EXPECT_GT(violations, 50);
}

// collapse_edge on triangle meshes skips replace_elements' star walks (ProvenEdit, proof in
// collapse_edge.cpp): every collapse of every edge, both ways, of the small meshes either leaves
// a valid mesh holding exactly star(from) re-attached to `to`, or is refused with the mesh
// bit-for-bit as it was.
TEST(SurfaceFastPaths, EveryCollapseOfSmallTriangleMeshesKeepsThemValid) {
    int done = 0, refused = 0;
    std::vector<Mesh> meshes = small_triangle_meshes();
    Mesh jittered = test::planar_grid(3);
    for (VertexId v = 0; v < jittered.vertex_count(); ++v) {
        Point p = jittered.reference(v);
        if (p[0] > 0 && p[0] < 3 && p[1] > 0 && p[1] < 3) p[0] += 0.1 * (v % 3) - 0.1, p[1] += 0.05 * (v % 2);
        jittered.set_reference(v, p);
        jittered.set_deformed(v, p);
    }
    meshes.push_back(std::move(jittered));
    for (const Mesh& original : meshes)
        for (const ElementId t : elements(original))
            for (const VertexId from : original.simplex(t).vertices())
                for (const VertexId to : original.simplex(t).vertices()) {
                    if (from == to) continue;
                    Mesh mesh = original;
                    const auto result = collapse_edge(mesh, from, to);
                    if (!result.ok()) {
                        ++refused;
                        EXPECT_EQ(result.reason().rfind("collapse_edge: ", 0), 0u) << result.reason();
                        test::expect_same_state(mesh, original);
                        continue;
                    }
                    ++done;
                    ASSERT_TRUE(mesh.validate().ok()) << from << "->" << to << ": " << mesh.validate().reason();
                    std::vector<Simplex> expected;
                    for (const ElementId u : elements(original)) {
                        const Simplex& tau = original.simplex(u);
                        if (!tau.contains(from))
                            expected.push_back(tau);
                        else if (!tau.contains(to))
                            expected.push_back(tau.substituted(from, to));
                    }
                    std::sort(expected.begin(), expected.end());
                    EXPECT_EQ(test::sorted_simplexes(mesh), expected) << from << "->" << to;
                    EXPECT_TRUE(star(mesh, from).empty());
                }
    EXPECT_GT(done, 20);
    EXPECT_GT(refused, 20);
}

TEST(SurfaceFastPaths, TheClosedTetrahedronSurfaceRefusesEveryCollapse) {
    // each vertex has degree 3: from and to share both other vertices, and the triangle they
    // span is a face of both links, but no simplex of link(from-to)
    Mesh mesh = small_triangle_meshes()[3];
    const Mesh before = mesh;
    const auto result = collapse_edge(mesh, 0, 1);
    ASSERT_FALSE(result.ok());
    EXPECT_EQ(result.reason(), "collapse_edge: " + test::text(Simplex(+1, {0, 1})) +
                                   " violates the link condition (the result would not be a manifold)");
    EXPECT_EQ(result.code(), RefusalCode::link_condition);
    test::expect_same_state(mesh, before);
    EXPECT_TRUE(mesh.validate().ok());
}

}  // namespace
}  // namespace sxk
