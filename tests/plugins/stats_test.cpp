// The stats plug-in in-process through its static library: histograms and both entry routes
// (a mesh file, a mesh in memory).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numeric>
#include <sstream>

#include <nlohmann/json.hpp>

#include "stats.hpp"
#include "sxk/plugin_host.hpp"
#include "sxk/quality.hpp"

namespace sxk::test {
namespace {

//        3
//       /|\         the regular tetrahedron: aspect ratio sqrt(2/3), radius ratio 1, all six
//      / | \        dihedral angles acos(1/3) ~ 70.53 degrees
//     0--|--2
//      \ | /
//        1
Mesh regular_tetrahedron() {
    Mesh mesh(3, 3);
    mesh.add_vertex({1, 1, 1});
    mesh.add_vertex({-1, 1, -1});
    mesh.add_vertex({1, -1, -1});
    mesh.add_vertex({-1, -1, 1});
    const std::array<Simplex, 1> tetrahedron{Simplex(+1, {0, 1, 2, 3})};
    EXPECT_TRUE(mesh.assign_elements(tetrahedron).ok());
    EXPECT_EQ(element_orientation(mesh, 0), Sign::positive);
    return mesh;
}

TEST(StatsHistogram, ClampsAndCountsUndefined) {
    stats::Histogram histogram(0, 1, 4);
    for (double value : {0.0, 0.1, 0.25, 0.99, 1.0, 1.2, -0.5, std::nan("")}) histogram.add(value);
    EXPECT_EQ(histogram.counts, (std::vector<std::size_t>{3, 1, 0, 3}));
    EXPECT_EQ(histogram.undefined, 1u);
    EXPECT_EQ(histogram.total(), 8u);
}

TEST(StatsHistogram, RegularTetrahedron) {
    const Mesh mesh = regular_tetrahedron();
    const stats::QualityHistograms histograms = stats::quality_histograms(mesh, 10);
    EXPECT_EQ(histograms.elements, 1u);
    EXPECT_EQ(histograms.aspect_ratio.counts[8], 1u);  // sqrt(2/3) = 0.816
    EXPECT_EQ(histograms.radius_ratio.counts[9], 1u);  // 1, the last bin is closed
    // acos(1/3) = 70.5 degrees: bin 3 of ten 18-degree bins
    EXPECT_EQ(histograms.angles.counts[3], 6u);
    EXPECT_EQ(histograms.angles.total(), 6u);
}

sxk::PluginCommand& stats_command(PluginHost& host) {
    EXPECT_TRUE(host.add_static(sxk_plugin_entry_stats(), "static"));
    const std::vector<std::string> name{"stats"};
    const FoundCommand found = host.find_command(name);
    EXPECT_NE(found.command, nullptr);
    return *found.command;
}

TEST(StatsCommand, RunsOnAMeshInMemory) {
    PluginHost host;
    PluginCommand& command = stats_command(host);
    EXPECT_TRUE(command.accepts_mesh());
    const Mesh mesh = regular_tetrahedron();
    std::ostringstream out, err;
    const std::vector<std::string> args{"--json", "--bins", "5"};
    EXPECT_EQ(command.run_on_mesh(mesh, "regular", args, out, err), 0);
    EXPECT_EQ(err.str(), "");
    const auto json = nlohmann::json::parse(out.str());
    EXPECT_EQ(json["file"], "regular");
    EXPECT_EQ(json["elements"], 1);
    EXPECT_EQ(json["dihedral_angles"]["counts"], nlohmann::json::parse("[0, 6, 0, 0, 0]"));
    EXPECT_EQ(json["radius_ratio"]["counts"], nlohmann::json::parse("[0, 0, 0, 0, 1]"));
}

TEST(StatsCommand, UsageErrorsExitTwo) {
    PluginHost host;
    PluginCommand& command = stats_command(host);
    std::ostringstream out, err;
    const std::vector<std::string> args{"a.mesh", "--bins", "many"};
    EXPECT_EQ(command.run(args, out, err), 2);
    EXPECT_EQ(out.str(), "");
    EXPECT_EQ(err.str().rfind("sxk: stats: --bins: ", 0), 0u) << err.str();
}

TEST(StatsCommand, MissingFileIsAnInputError) {
    PluginHost host;
    PluginCommand& command = stats_command(host);
    std::ostringstream out, err;
    const std::vector<std::string> args{"/nonexistent/a.mesh"};
    EXPECT_EQ(command.run(args, out, err), 2);
    EXPECT_EQ(err.str().rfind("sxk: /nonexistent/a.mesh:0: ", 0), 0u) << err.str();
}

}  // namespace
}  // namespace sxk::test
