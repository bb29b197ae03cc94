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

Measured cantilever(int n) {
    auto mesh = make_kuhn_box({4 * n, n, n}, {length / (4 * n), height / n, depth / n});
    EXPECT_TRUE(mesh.ok()) << mesh.reason();
    auto body = ElasticBody::make(*mesh, {.young = young, .poisson = 0});
    EXPECT_TRUE(body.ok()) << body.reason();
    std::vector<VertexId> tip;
    for (VertexId v = 0; v < mesh->vertex_count(); ++v) {
        const Point& p = mesh->reference(v);
        if (p[0] == 0) {
            EXPECT_TRUE(body->fix(v).ok());
        }
        if (std::abs(p[0] - length) < 1e-12) tip.push_back(v);
    }
    for (const VertexId v : tip) EXPECT_TRUE(body->add_force(v, {0, -load / static_cast<double>(tip.size()), 0}).ok());
    const auto report = solve_linear_cg(*body, {.tolerance = 1e-8, .stop = StopCriterion::external_force});
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
    constexpr TableRow thesis[] = {
        {4, 377, 29.0, 29.3}, {6, 561, 15.1, 15.3}, {8, 723, 8.6, 8.8}, {10, 882, 5.2, 5.3}, {12, 1044, 3.2, 3.3}};
    std::printf("%-12s %6s %8s | %10s %9s %9s | %10s %9s %9s\n", "cells", "nodes", "elements", "iterations",
                "avg err %", "max err %", "thesis it", "avg err %", "max err %");
    double previous = std::numeric_limits<double>::infinity();
    for (const TableRow& row : thesis) {
        const Measured m = cantilever(row.cells);
        std::printf("%2dx%2dx%-6d %6zu %8zu | %10zu %9.2f %9.2f | %10d %9.1f %9.1f  (%.2f s)\n", 4 * row.cells, row.cells,
                    row.cells, m.nodes, m.elements, m.iterations, m.average_error, m.maximum_error, row.iterations,
                    row.average_error, row.maximum_error, m.seconds);
        // the thesis prints 8181 nodes for 48 x 12 x 12, which has 49 * 13 * 13 = 8281
        EXPECT_EQ(m.nodes, static_cast<std::size_t>((4 * row.cells + 1) * (row.cells + 1) * (row.cells + 1)));
        EXPECT_TRUE(m.converged);
        EXPECT_GT(m.average_error, 0) << row.cells;  // linear tetrahedra are too stiff
        EXPECT_LE(m.average_error, row.average_error) << row.cells;
        EXPECT_LT(m.average_error, previous) << row.cells;
        EXPECT_LT(m.maximum_error - m.average_error, 1.0) << row.cells;
        previous = m.average_error;
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
        {"side x = 1, in-plane radial", true, [](const Point& p) { return Vector3{0, p[1] - 0.5, p[2] - 0.5}; }},
        {"side x = 1, outward normal", true, [](const Point&) { return Vector3{1, 0, 0}; }},
        {"front z = 1, in-plane radial", false, [](const Point& p) { return Vector3{p[0] - 0.5, p[1] - 0.5, 0}; }},
        {"front z = 1, outward normal", false, [](const Point&) { return Vector3{0, 0, 1}; }},
        {"front z = 1, radial from the centre", false, [](const Point& p) { return Vector3{p[0] - 0.5, p[1] - 0.5, 0.5}; }},
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
        const auto report = solve_linear_cg(*body, {.tolerance = 1e-3, .stop = StopCriterion::external_force});
        ASSERT_TRUE(report.ok()) << report.reason();
        std::printf("7986-element cube, %-36s %4zu iterations in %.4f s (%.0f iterations/s)\n", load.name,
                    report->iterations, report->seconds, static_cast<double>(report->iterations) / report->seconds);
        EXPECT_TRUE(report->converged) << load.name;
        EXPECT_LE(report->iterations, 300u) << load.name;
    }
}

}  // namespace
}  // namespace sxk::elasticity
