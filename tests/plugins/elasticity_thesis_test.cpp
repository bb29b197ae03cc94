// The thesis' elasticity experiments of §3.3.
//
// Table 3.1: the cantilever beam, l x h x d = 1.2 x 0.2 x 0.3 m, E = 1e6 Pa, nu = 0,
// fixed at x = 0, a total load of 3 N at x = l shared equally by the tip's nodes, solved to
// ||r|| < 1e-8 ||f||; the error of each tip node's deflection against the analytic 4 F / (E d)
// (l / h)^3 = 8.64e-3 m. Each box cell is cut into its 6 Kuhn tetrahedra (make_kuhn_box), as
// the thesis' generated cubes are cut into 6 (§3.3: 1728 nodes, 7986 elements = 11^3 cubes of
// 6); the thesis does not say how its beams were cut. Our errors are smaller than the thesis'
// (docs/elasticity.md has both tables, and those of two other cuts); asserted: each below the
// thesis' figure, falling as the mesh is refined, the same on every tip node within a point.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include <Eigen/Core>

#include "elastic_body.hpp"
#include "solve.hpp"
#include "sxk/generators.hpp"

namespace sxk::elasticity {
namespace {

struct TableRow {
    int cells;  // along h and d; 4 times that along l
    int iterations;
    double average_error, maximum_error;  // percent
};

constexpr double length = 1.2, height = 0.2, depth = 0.3, young = 1e6, load = 3;

struct Measured {
    std::size_t nodes = 0, elements = 0, iterations = 0;
    double average_error = 0, maximum_error = 0;
    bool converged = false;
    double seconds = 0;
};

// Table 3.1 as the thesis prints it.
constexpr TableRow thesis[] = {{4, 377, 29.0, 29.3},
                               {6, 561, 15.1, 15.3},
                               {8, 723, 8.6, 8.8},
                               {10, 882, 5.2, 5.3},
                               {12, 1044, 3.2, 3.3}};

Measured cantilever(int n, double poisson = 0) {
    auto mesh = make_kuhn_box({4 * n, n, n}, {length / (4 * n), height / n, depth / n});
    EXPECT_TRUE(mesh.ok()) << mesh.reason();
    auto body = ElasticBody::make(*mesh, {.young = young, .poisson = poisson});
    EXPECT_TRUE(body.ok()) << body.reason();
    std::vector<VertexId> tip;
    for (VertexId v = 0; v < mesh->vertex_count(); ++v) {
        const Point& p = mesh->reference(v);
        if (p[0] == 0) {
            EXPECT_TRUE(body->fix(v).ok());
        }
        if (std::abs(p[0] - length) < 1e-12)
            tip.push_back(v);
    }
    for (const VertexId v : tip)
        EXPECT_TRUE(body->add_force(v, {0, -load / static_cast<double>(tip.size()), 0}).ok());
    const auto report =
        solve_linear_cg(*body, {.tolerance = 1e-8, .stop = StopCriterion::external_force});
    EXPECT_TRUE(report.ok()) << report.reason();
    Measured m;
    m.maximum_error = -std::numeric_limits<double>::infinity();
    m.nodes = mesh->vertex_count();
    m.elements = mesh->element_count();
    m.iterations = report->iterations;
    m.converged = report->converged;
    m.seconds = report->seconds;
    const double exact = 4 * load / (young * depth) * std::pow(length / height, 3);
    for (const VertexId v : tip) {
        const double error = 100 * (exact - -body->displacement(v)[1]) / exact;
        m.average_error += error / static_cast<double>(tip.size());
        m.maximum_error = std::max(m.maximum_error, error);
    }
    return m;
}

TEST(ElasticityThesisBeam, ReproducesTable31) {
    std::printf("%-12s %6s %8s | %10s %9s %9s | %10s %9s %9s\n", "cells", "nodes", "elements",
                "iterations", "avg err %", "max err %", "thesis it", "avg err %", "max err %");
    double previous = std::numeric_limits<double>::infinity();
    for (const TableRow& row : thesis) {
        const Measured m = cantilever(row.cells);
        std::printf("%2dx%2dx%-6d %6zu %8zu | %10zu %9.2f %9.2f | %10d %9.1f %9.1f  (%.2f s)\n",
                    4 * row.cells, row.cells, row.cells, m.nodes, m.elements, m.iterations,
                    m.average_error, m.maximum_error, row.iterations, row.average_error,
                    row.maximum_error, m.seconds);
        // the thesis prints 8181 nodes for 48 x 12 x 12, which has 49 * 13 * 13 = 8281
        EXPECT_EQ(m.nodes, static_cast<std::size_t>((4 * row.cells + 1) * (row.cells + 1) *
                                                    (row.cells + 1)));
        EXPECT_TRUE(m.converged);
        EXPECT_GT(m.average_error, 0) << row.cells;  // linear tetrahedra are too stiff
        EXPECT_LE(m.average_error, row.average_error) << row.cells;
        EXPECT_LT(m.average_error, previous) << row.cells;
        EXPECT_LT(m.maximum_error - m.average_error, 1.0) << row.cells;
        previous = m.average_error;
    }
}

// The same beams with nu = 1/4, the material of the thesis' other chapter 3 experiments: the CG
// iteration counts come out within 3% of Table 3.1's (ours 389, 564, 728, 887, 1046), closer
// than with the nu = 0 the table states (7-11% below), which suggests the thesis' beams had
// nu = 1/4. The errors are still smaller than the table's (24.1, 12.3, 7.1, 4.4, 2.9%: within a
// point on the two finest meshes only). docs/elasticity.md discusses it.
TEST(ElasticityThesisBeam, IterationCountsMatchTable31WithAQuarterPoissonRatio) {
    for (const TableRow& row : thesis) {
        const Measured m = cantilever(row.cells, 0.25);
        std::printf(
            "nu = 1/4, %2dx%2dx%-2d: %5zu iterations (thesis %4d), average error %5.2f%% (thesis "
            "%4.1f%%), "
            "maximum %5.2f%% (thesis %4.1f%%)\n",
            4 * row.cells, row.cells, row.cells, m.iterations, row.iterations, m.average_error,
            row.average_error, m.maximum_error, row.maximum_error);
        EXPECT_TRUE(m.converged);
        EXPECT_NEAR(static_cast<double>(m.iterations), row.iterations, 0.05 * row.iterations)
            << row.cells;
        EXPECT_GT(m.average_error, 0) << row.cells;
        EXPECT_LE(m.average_error, row.average_error) << row.cells;
    }
}

// §3.3: "a procedurally generated object with 1728 nodes and 7986 elements" (11^3 cubes of 6
// tetrahedra), nu = 1/4, ||r|| < 1e-3 ||f||: "between 100 and 300 iterations are needed". The
// loads are "dilating forces applied to the side" (Figure 3.12), with the back face fixed
// (Figure 3.14); the thesis gives no more, and the iteration count depends on the load's shape
// (not on its scale nor on E), so five readings of it are solved: none may need more than the
// thesis' 300. docs/elasticity.md has the counts.
TEST(ElasticityThesisCube, SolvesInAtMost300Iterations) {
    auto mesh = make_kuhn_cube(11, 1.0 / 11);
    ASSERT_TRUE(mesh.ok()) << mesh.reason();
    ASSERT_EQ(mesh->vertex_count(), 1728u);
    ASSERT_EQ(mesh->element_count(), 7986u);
    struct Load {
        const char* name;
        bool side;  // on the face x = 1 (else on the front face z = 1)
        Vector3 (*force)(const Point& p);
    };
    const Load loads[] = {
        {"side x = 1, in-plane radial", true,
         [](const Point& p) {
             return Vector3{0, p[1] - 0.5, p[2] - 0.5};
         }},
        {"side x = 1, outward normal", true,
         [](const Point&) {
             return Vector3{1, 0, 0};
         }},
        {"front z = 1, in-plane radial", false,
         [](const Point& p) {
             return Vector3{p[0] - 0.5, p[1] - 0.5, 0};
         }},
        {"front z = 1, outward normal", false,
         [](const Point&) {
             return Vector3{0, 0, 1};
         }},
        {"front z = 1, radial from the centre", false,
         [](const Point& p) {
             return Vector3{p[0] - 0.5, p[1] - 0.5, 0.5};
         }},
    };
    for (const Load& load : loads) {
        auto body = ElasticBody::make(*mesh, {.young = 1e4, .poisson = 0.25});
        ASSERT_TRUE(body.ok()) << body.reason();
        for (VertexId v = 0; v < mesh->vertex_count(); ++v) {
            const Point& p = mesh->reference(v);
            if (p[2] == 0) {
                ASSERT_TRUE(body->fix(v).ok());
            } else if ((load.side ? p[0] : p[2]) > 1 - 1e-12) {
                ASSERT_TRUE(body->add_force(v, load.force(p)).ok());
            }
        }
        const auto report =
            solve_linear_cg(*body, {.tolerance = 1e-3, .stop = StopCriterion::external_force});
        ASSERT_TRUE(report.ok()) << report.reason();
        std::printf("7986-element cube, %-36s %4zu iterations in %.4f s (%.0f iterations/s)\n",
                    load.name, report->iterations, report->seconds,
                    static_cast<double>(report->iterations) / report->seconds);
        EXPECT_TRUE(report->converged) << load.name;
        EXPECT_LE(report->iterations, 300u) << load.name;
    }
}

// §4.5: linear against neo-Hookean elasticity on chapter 4's test object, a soft rod fixed at one
// end sagging under its own weight (Table 4.1: g = 9.8 m/s^2, rho = 1000 kg/m^3, E = 1e4 Pa,
// nu = 0.3; Table 4.2: length 0.1 m, radius 0.03 m). The thesis meshes a cylinder by Delaunay;
// here a box of the cylinder's width, 0.1 x 0.06 x 0.06 m in 10 x 6 x 6 Kuhn cells (2,160
// tetrahedra; the thesis' small mesh has 1,230). The tip sags by about half the length, far
// outside small strains. Asserted: both converge; the linear sag lies between the beam formulas
// without and with shear (Euler-Bernoulli q l^4 / (8 E I) = 4.1 cm, Timoshenko adds
// q l^2 / (2 kappa G A) = 1.5 cm for this stout rod); the neo-Hookean tip swings back towards
// the wall (a bent rod keeps its length; linear elasticity lets it stretch along the arc) and
// the two solutions differ by more than 5% of the largest displacement. docs/elasticity.md has
// the figures.
TEST(ElasticityThesisRod, LinearAndNeoHookeanPartUnderLargeSag) {
    constexpr double rod = 0.1, width = 0.06, g = 9.8, density = 1000, young = 1e4, nu = 0.3;
    auto mesh = make_kuhn_box({10, 6, 6}, {rod / 10, width / 6, width / 6});
    ASSERT_TRUE(mesh.ok()) << mesh.reason();
    struct Result {
        Eigen::VectorXd u;
        Vector3 tip{0, 0, 0};  // the mean displacement of the vertices at x = l
        SolveReport report;
    };
    auto sag = [&](Model model) {
        Result r;
        auto body = ElasticBody::make(*mesh, {.young = young, .poisson = nu}, {.model = model});
        EXPECT_TRUE(body.ok()) << body.reason();
        for (VertexId v = 0; v < mesh->vertex_count(); ++v) {
            if (mesh->reference(v)[0] == 0) {
                EXPECT_TRUE(body->fix(v).ok());
            }
        }
        EXPECT_TRUE(body->add_body_force({0, -density * g, 0}).ok());
        const auto report =
            solve(*body, {.tolerance = 1e-8, .stop = StopCriterion::external_force});
        EXPECT_TRUE(report.ok()) << report.reason();
        r.report = *report;
        r.u = body->displacements();
        int tip = 0;
        for (VertexId v = 0; v < mesh->vertex_count(); ++v)
            if (std::abs(mesh->reference(v)[0] - rod) < 1e-12) {
                for (std::size_t k = 0; k < 3; ++k)
                    r.tip[k] += body->displacement(v)[k];
                ++tip;
            }
        for (double& x : r.tip)
            x /= tip;
        return r;
    };
    const Result linear = sag(Model::linear);
    const Result rubber = sag(Model::neohookean);
    const double q = density * g * width * width, inertia = std::pow(width, 4) / 12;
    const double bending = q * std::pow(rod, 4) / (8 * young * inertia);
    const double shear = q * rod * rod / (2 * (5.0 / 6) * young / (2 * (1 + nu)) * width * width);
    double largest = 0, difference = 0;
    for (Eigen::Index v = 0; v + 2 < linear.u.size(); v += 3) {
        largest = std::max(largest, linear.u.segment<3>(v).norm());
        difference = std::max(difference, (linear.u.segment<3>(v) - rubber.u.segment<3>(v)).norm());
    }
    std::printf(
        "[ figures  ] rod under its weight: tip (x, y) linear (%.4f, %.4f) m in %zu iterations, "
        "neo-Hookean "
        "(%.4f, %.4f) m in %zu iterations (%zu force evaluations); largest difference %.4f m = "
        "%.1f%% of the "
        "largest linear displacement; beam formulas: bending %.4f m, + shear %.4f m\n",
        linear.tip[0], linear.tip[1], linear.report.iterations, rubber.tip[0], rubber.tip[1],
        rubber.report.iterations, rubber.report.evaluations, difference, 100 * difference / largest,
        bending, bending + shear);
    EXPECT_TRUE(linear.report.converged);
    EXPECT_TRUE(rubber.report.converged);
    EXPECT_GT(-linear.tip[1], bending);
    EXPECT_LT(-linear.tip[1], bending + shear);
    EXPECT_LT(rubber.tip[0], linear.tip[0] - 0.05 * -linear.tip[1]);
    EXPECT_GT(difference, 0.05 * largest);
}

}  // namespace
}  // namespace sxk::elasticity
