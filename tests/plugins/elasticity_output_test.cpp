// What the elasticity plug-in gives back to the mesh and takes from the user: the solution
// written as deformed positions (one event, refused when it would invert an element), and the
// vertex selectors of `sxk deform`.
#include <gtest/gtest.h>

#include "elastic_body.hpp"
#include "solve.hpp"
#include "sxk/generators.hpp"
#include "sxk/watcher.hpp"
#include "vertex_selector.hpp"

namespace sxk::elasticity {
namespace {

struct MoveCounter : Watcher {
    int calls = 0;
    std::size_t vertices = 0;
    void vertices_moved(const Mesh&, std::span<const VertexId> moved, PositionSet which) override {
        ++calls;
        vertices += moved.size();
        EXPECT_EQ(which, PositionSet::deformed);
    }
};

TEST(ElasticityOutput, WritesTheSolutionAsDeformedPositionsInOneEvent) {
    Mesh mesh = *make_kuhn_cube(3, 1.0 / 3);
    auto body = ElasticBody::make(mesh, {.young = 1e3, .poisson = 0.3});
    ASSERT_TRUE(body.ok()) << body.reason();
    for (VertexId v = 0; v < mesh.vertex_count(); ++v) {
        if (mesh.reference(v)[2] == 0) {
            ASSERT_TRUE(body->fix(v).ok());
        } else if (mesh.reference(v)[2] == 1) {
            ASSERT_TRUE(body->add_force(v, {1, 0, 0}).ok());
        }
    }
    ASSERT_TRUE(solve_linear_cg(*body, {.tolerance = 1e-10})->converged);
    MoveCounter counter;
    {
        ScopedWatcher watching(mesh, counter);
        const auto written = body->write_deformed(mesh);
        ASSERT_TRUE(written.ok()) << written.reason();
    }
    EXPECT_EQ(counter.calls, 1);
    EXPECT_EQ(counter.vertices, mesh.vertex_count());
    for (VertexId v = 0; v < mesh.vertex_count(); ++v) {
        const Vector3 u = body->displacement(v);
        const Point& x = mesh.reference(v);
        EXPECT_EQ(mesh.deformed(v), (Point{x[0] + u[0], x[1] + u[1], x[2] + u[2]})) << v;
    }
    EXPECT_GT(mesh.deformed(mesh.vertex_count() - 1)[0], 1.0);  // the top moved along x
    EXPECT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
}

TEST(ElasticityOutput, RefusesASolutionThatInvertsAnElement) {
    Mesh mesh = *make_kuhn_cube(2, 0.5);
    auto body = ElasticBody::make(mesh, {});
    ASSERT_TRUE(body.ok()) << body.reason();
    // the centre vertex pushed through the far face
    const VertexId centre = 13;
    ASSERT_EQ(mesh.reference(centre), (Point{0.5, 0.5, 0.5}));
    body->displacements()[3 * centre] = 2;
    const auto written = body->write_deformed(mesh);
    EXPECT_EQ(written.code(), RefusalCode::would_invert);
    EXPECT_EQ(written.reason().rfind("elasticity: the solution cannot be shown: element ", 0), 0u)
        << written.reason();
    EXPECT_TRUE(mesh.is_element(static_cast<ElementId>(written.refusal().item)));
    for (VertexId v = 0; v < mesh.vertex_count(); ++v)
        EXPECT_EQ(mesh.deformed(v), mesh.reference(v)) << v;

    Mesh other = *make_kuhn_cube(2, 0.5);
    EXPECT_EQ(body->write_deformed(other).reason(),
              "elasticity: write_deformed: not the mesh of this body");
    EXPECT_TRUE(mesh.validate().ok());
}

TEST(ElasticitySelector, SelectsWhatItSays) {
    const Mesh mesh = *make_kuhn_cube(2, 0.5);  // 27 vertices, the centre 13 the only interior one
    auto count = [&](const char* text) {
        const auto selector = parse_vertex_selector(text);
        EXPECT_TRUE(selector.ok()) << text << ": " << selector.reason();
        return selector.ok() ? select_vertices(mesh, *selector).size() : std::size_t{999};
    };
    EXPECT_EQ(count("x<0.001"), 9u);
    EXPECT_EQ(count("x = 0 & y=0"), 3u);
    EXPECT_EQ(count(" x <= 0.5 & boundary "), 17u);  // 18 with x <= 0.5, less the centre
    EXPECT_EQ(count("boundary"), 26u);
    EXPECT_EQ(count("label=0"), 27u);
    EXPECT_EQ(count("label=5"), 0u);
    EXPECT_EQ(count("z>=1&x>0.7&y>0.7"), 1u);
    EXPECT_EQ(select_vertices(mesh, *parse_vertex_selector("z>=1&x>0.7&y>0.7")),
              std::vector<VertexId>{26});
}

TEST(ElasticitySelector, RefusesWhatDoesNotParse) {
    const auto bad = parse_vertex_selector("x<0.1&w>2");
    EXPECT_EQ(bad.code(), RefusalCode::bad_argument);
    EXPECT_EQ(bad.reason(),
              "selector 'x<0.1&w>2': term 'w>2': expected x, y or z compared with a number, "
              "label=N or boundary");
    EXPECT_EQ(parse_vertex_selector("y=>1").reason(),
              "selector 'y=>1': term 'y=>1': expected a number after '=', found '>1'");
    EXPECT_EQ(parse_vertex_selector("z<inf").reason(),
              "selector 'z<inf': term 'z<inf': expected a number after '<', found 'inf'");
    EXPECT_EQ(parse_vertex_selector("label 3").reason(),
              "selector 'label 3': term 'label 3': expected '=' after 'label'");
    EXPECT_EQ(
        parse_vertex_selector("").reason(),
        "selector '': term '': expected x, y or z compared with a number, label=N or boundary");
}

}  // namespace
}  // namespace sxk::elasticity
