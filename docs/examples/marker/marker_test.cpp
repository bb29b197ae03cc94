// The marker's tests, as a plug-in's tests are written (CONTRIBUTING.md): the plug-in loaded the
// way an application loads it, every mutation checked with validate(), refusals with their exact
// reason, and a random path under the tool oracle the fuzzers use (fuzz/tool_replay.hpp: every
// step completes or changes nothing, undo and redo give the mesh back bit for bit), its seed
// printed (tests/core/fixtures.hpp).
#include <gtest/gtest.h>

#include <random>

#include "core/fixtures.hpp"
#include "marker.hpp"
#include "sxk/generators.hpp"
#include "sxk/plugin_host.hpp"
#include "tool_replay.hpp"

namespace sxk::marker {
namespace {

// The host with the marker loaded from its file, as an application loads it.
PluginHost& host() {
    static PluginHost loaded = [] {
        PluginHost host;
        EXPECT_TRUE(host.load_file(SXK_MARKER_PLUGIN)) << host.diagnostics()[0].reason;
        return host;
    }();
    return loaded;
}

std::size_t labelled(const Mesh& mesh, int label) {
    std::size_t count = 0;
    for (const ElementId t : elements(mesh)) count += mesh.label(t) == label;
    return count;
}

TEST(Marker, MarksTheElementsNearTheToolAndUndoes) {
    Mesh mesh = make_kuhn_cube(4).value();
    const Mesh before = mesh;
    Options options;
    options.label = 7;
    options.radius = 0.5;
    auto session = host().begin_tool(mesh, options);
    ASSERT_TRUE(session) << session.reason();
    ToolPose pose;
    pose.position = {0, 0, 0};  // a corner of the cube: the elements at its corner vertex
    auto step = (*session)->step(pose);
    ASSERT_TRUE(step) << step.reason();
    EXPECT_TRUE(mesh.validate().ok());
    const std::size_t corner = labelled(mesh, 7);
    EXPECT_GT(corner, 0u);
    EXPECT_EQ(step->actions, std::vector<std::string>{"marked " + std::to_string(corner) + " elements"});
    pose.position = {4, 4, 4};
    ASSERT_TRUE((*session)->step(pose));
    EXPECT_GT(labelled(mesh, 7), corner);
    ASSERT_TRUE((*session)->undo_step());
    EXPECT_EQ(labelled(mesh, 7), corner);
    ASSERT_TRUE((*session)->cancel());
    EXPECT_TRUE(mesh.validate().ok());
    EXPECT_TRUE(ops_driver::snapshot(mesh) == ops_driver::snapshot(before));
}

TEST(Marker, RefusesOptionsWithTheReason) {
    Mesh mesh = make_kuhn_cube(1).value();
    Options options;
    options.radius = 0;
    const auto refused = host().begin_tool(mesh, options);
    ASSERT_FALSE(refused);
    EXPECT_EQ(refused.code(), RefusalCode::bad_argument);
    EXPECT_EQ(refused.reason(), "marker: radius 0 is not in (0, 1e+300]");
    EXPECT_TRUE(mesh.validate().ok());
}

// A random path of the tool over the cube, every odd second an undo and a redo: the oracle of the
// tool fuzzers. The seed is printed (test::seed_for); SXK_SEED=S repeats a run.
TEST(Marker, ARandomPathKeepsTheToolOracle) {
    std::mt19937_64 random(test::seed_for("Marker.ARandomPathKeepsTheToolOracle"));
    std::uniform_real_distribution<double> coordinate(-0.5, 4.5);
    const Mesh original = make_kuhn_cube(4).value();
    Mesh mesh = original;
    Options options;
    options.label = 3;
    options.radius = 0.7;
    auto session = host().begin_tool(mesh, options);
    ASSERT_TRUE(session) << session.reason();
    ToolPath path;
    path.columns = 3;
    for (int i = 0; i < 40; ++i)
        path.samples.push_back({0.5 * i, {coordinate(random), coordinate(random), coordinate(random)},
                                static_cast<std::size_t>(i + 1)});
    fuzz::replay_tool_path(**session, mesh, original, path, {.orientation = true}, [&](const ToolSample& sample) {
        ToolPose pose;
        pose.position = {sample.values[0], sample.values[1], sample.values[2]};
        return (*session)->step(pose);
    });
    EXPECT_TRUE(mesh.validate().ok());
}

}  // namespace
}  // namespace sxk::marker
