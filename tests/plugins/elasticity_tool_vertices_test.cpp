// The elasticity service's vertices a tool holds (sxk/simulation.hpp; the needle's
// stick-slip friction): hold, hold_on_line, release, set_tool_force, forces_at and
// displacements_from_mesh on the thesis' slab, with the refusals for the vertices the options hold.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "body_words.hpp"
#include "simulation.hpp"
#include "sxk/generators.hpp"

namespace sxk::elasticity {
namespace {

struct Slab {
    Mesh mesh = *make_triangle_grid({4, 4}, {0.025, 0.025});
    std::unique_ptr<Simulation> body;
    Slab() {
        const std::vector<std::string> words{"--fix", "x>0.0999", "--E", "34e3", "--nu", "0.34", "--thickness",
                                             "0.01", "--tol", "1e-10"};
        auto made = simulate(mesh, sxk::cli::body_options(words).value());
        EXPECT_TRUE(made.ok()) << made.reason();
        body = std::move(*made);
    }
};

TEST(ElasticityToolVertices, HeldVerticesBalanceTheFixedSide) {
    Slab slab;
    // vertex (0, 2) pulled 1 mm along -x and held; the reactions of all held vertices balance
    const VertexId pulled = 2 * 5 + 0;
    ASSERT_TRUE(slab.body->hold(pulled, {-0.001, 0, 0}).ok());
    auto relaxed = slab.body->relax(100000);
    ASSERT_TRUE(relaxed.ok() && relaxed->converged) << relaxed.reason();
    EXPECT_EQ(slab.body->displacement(pulled)[0], -0.001);
    std::vector<VertexId> held{pulled};
    for (VertexId v = 0; v < slab.mesh.vertex_count(); ++v)
        if (slab.mesh.reference(v)[0] > 0.0999) held.push_back(v);
    auto forces = slab.body->forces_at(held);
    ASSERT_TRUE(forces.ok()) << forces.reason();
    double sum_x = 0, sum_y = 0;
    for (const auto& f : *forces) {
        sum_x -= f.elastic[0] + f.loaded[0];
        sum_y -= f.elastic[1] + f.loaded[1];
    }
    const double pull = -((*forces)[0].elastic[0] + (*forces)[0].loaded[0]);
    EXPECT_LT(pull, 0);  // the tool pulls towards -x
    EXPECT_NEAR(sum_x, 0, 1e-6 * std::abs(pull));
    EXPECT_NEAR(sum_y, 0, 1e-6 * std::abs(pull));

    // slipping along y with a force along the line: it moves along y only
    ASSERT_TRUE(slab.body->hold_on_line(pulled, {0, 1, 0}, {-0.001, 0, 0}).ok());
    ASSERT_TRUE(slab.body->set_tool_force(pulled, {0, 0.05, 0}).ok());
    ASSERT_TRUE(slab.body->relax(100000).ok());
    EXPECT_EQ(slab.body->displacement(pulled)[0], -0.001);
    EXPECT_GT(slab.body->displacement(pulled)[1], 0);
    // released and unloaded: it goes back
    ASSERT_TRUE(slab.body->release(pulled).ok());
    ASSERT_TRUE(slab.body->set_tool_force(pulled, {0, 0, 0}).ok());
    ASSERT_TRUE(slab.body->relax(100000).ok());
    EXPECT_NEAR(slab.body->displacement(pulled)[0], 0, 1e-9);
    EXPECT_NEAR(slab.body->displacement(pulled)[1], 0, 1e-9);
}

TEST(ElasticityToolVertices, DisplacementsComeBackFromTheMesh) {
    Slab slab;
    ASSERT_TRUE(slab.body->hold(0, {0.002, 0.001, 0}).ok());
    ASSERT_TRUE(slab.body->relax(100000).ok());
    const Mesh shown = slab.mesh;
    const auto u = slab.body->displacement(7);
    ASSERT_TRUE(slab.body->hold(0, {0, 0, 0}).ok());
    ASSERT_TRUE(slab.body->relax(100000).ok());
    slab.mesh = shown;  // the mesh taken back, as an undo does
    ASSERT_TRUE(slab.body->displacements_from_mesh().ok());
    for (int k = 0; k < 2; ++k)
        EXPECT_NEAR(slab.body->displacement(7)[k], u[k], 1e-15);
}

TEST(ElasticityToolVertices, TheOptionsVerticesAreNotTheTools) {
    Slab slab;
    const VertexId fixed = 4;  // (0.1, 0)
    EXPECT_EQ(slab.body->hold(fixed, {0, 0, 0}).reason(), "hold: vertex 4 is held by the body's options");
    EXPECT_EQ(slab.body->hold_on_line(fixed, {1, 0, 0}, {0, 0, 0}).reason(),
              "hold_on_line: vertex 4 is held by the body's options");
    EXPECT_EQ(slab.body->release(fixed).refusal().code, RefusalCode::bad_argument);
    EXPECT_EQ(slab.body->hold_on_line(0, {0, 0, 0}, {0, 0, 0}).refusal().code, RefusalCode::bad_argument);
}

}  // namespace
}  // namespace sxk::elasticity
