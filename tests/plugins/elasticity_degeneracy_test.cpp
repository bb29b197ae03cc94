// What degeneracy removal saves the relaxation (thesis §3.3, Figs. 3.14-3.16: a cut of the 3072-
// element cube left 143 degenerates and needed 2439 CG iterations; with them removed, 236). Here:
// the snapped cube of the degeneracy tests (a snap without a dissection: the snap cutter is a
// later plug-in), loaded as §3.3 loads its cube, solved to ||r|| < 1e-3 ||f|| before and after
// remove_degeneracies, and the unsnapped cube for reference. docs/elasticity.md has the figures.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

#include "elastic_body.hpp"
#include "remove_degeneracies.hpp"
#include "snapped_cube.hpp"
#include "solve.hpp"
#include "sxk/quality.hpp"

namespace sxk::elasticity {
namespace {

// The cube fixed at z = 0 and pulled outward on its side x = 8 (1 N a node), solved as §3.3.
SolveReport relax(const Mesh& mesh) {
    auto body = ElasticBody::make(mesh, {.young = 1e4, .poisson = 0.25});
    EXPECT_TRUE(body.ok()) << body.reason();
    if (!body.ok())
        return {};
    for (VertexId v = 0; v < mesh.vertex_count(); ++v) {
        if (mesh.vertex_element(v) == invalid_id)
            continue;
        const Point& p = mesh.reference(v);
        if (p[2] == 0) {
            EXPECT_TRUE(body->fix(v).ok());
        } else if (p[0] == 8) {
            EXPECT_TRUE(body->add_force(v, {1, 0, 0}).ok());
        }
    }
    const auto report = solve_linear_cg(
        *body, {.tolerance = 1e-3, .max_iterations = 20000, .stop = StopCriterion::external_force});
    EXPECT_TRUE(report.ok()) << report.reason();
    return report.ok() ? *report : SolveReport{};
}

std::size_t count_below(const Mesh& mesh, double threshold) {
    std::size_t n = 0;
    for (const ElementId t : elements(mesh))
        n += aspect_ratio(element_points(mesh, t, Positions::reference)) < threshold;
    return n;
}

TEST(ElasticityAfterDegeneracyRemoval, TheSnappedCubeRelaxesInFewerIterations) {
    const Mesh plain = make_kuhn_cube(8).value();
    degeneracy::SnapReport snap;
    Mesh mesh = test::snapped_thesis_cube(snap);
    const std::size_t degenerates = count_below(mesh, 0.01);
    ASSERT_GT(degenerates, 0u);
    const SolveReport unsnapped = relax(plain);
    const SolveReport before = relax(mesh);
    double least_before = 1;
    for (const ElementId t : elements(mesh))
        least_before =
            std::min(least_before, aspect_ratio(element_points(mesh, t, Positions::reference)));
    std::printf("[ figures  ] snapped cube: least aspect ratio %.3g\n", least_before);
    const auto removed = degeneracy::remove_degeneracies(mesh);
    ASSERT_TRUE(removed.ok()) << removed.reason();
    ASSERT_EQ(count_below(mesh, 0.01), 0u);
    const SolveReport after = relax(mesh);
    double least = 1;
    for (const ElementId t : elements(mesh))
        least = std::min(least, aspect_ratio(element_points(mesh, t, Positions::reference)));
    std::printf(
        "[ figures  ] cube, %zu degenerates: CG iterations unsnapped %zu, snapped %zu%s (|r| %.3g, "
        "needed %.3g), "
        "after removal %zu (%zu elements, least aspect ratio %.3g)\n",
        degenerates, unsnapped.iterations, before.iterations,
        before.converged ? "" : " without converging", before.residual, before.threshold,
        after.iterations, mesh.element_count(), least);
    EXPECT_TRUE(unsnapped.converged && after.converged);
    EXPECT_LT(after.iterations, before.iterations);
    EXPECT_TRUE(mesh.validate().ok());
}

}  // namespace
}  // namespace sxk::elasticity
