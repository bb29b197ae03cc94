// sxk plugins and plug-in commands through the binary: listing, refusals printed as
// "sxk: warning: PATH: reason" while sxk goes on, duplicates, dispatch to `sxk stats`.
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>

#include <nlohmann/json.hpp>

#include "run_sxk.hpp"

namespace sxk::test {
namespace {

const fs::path bad_plugins = fs::path(SXK_BAD_PLUGIN_DIR);
const fs::path stats_plugin = fs::path(SXK_PLUGIN_BUILD_DIR) / "stats.so";

std::string warning(const fs::path& path, const std::string& reason) {
    return "sxk: warning: " + path.string() + ": " + reason + "\n";
}

TEST(SxkPlugins, ListsTheStatsPlugin) {
    const ProcessResult run = sxk({"plugins"});
    EXPECT_EQ(run.exit_code, 0);
    EXPECT_EQ(run.err, "");
    // plug-ins are listed in name order; stats is one of them
    EXPECT_NE(run.out.find("stats 0.1.0  histograms of element quality\n  file: " + stats_plugin.string() +
                           "\n  sxk stats  histograms of aspect ratio, radius ratio and dihedral angles\n"),
              std::string::npos)
        << run.out;
    EXPECT_EQ(run.out.find("refused:"), std::string::npos);
}

TEST(SxkPlugins, JsonListing) {
    const ProcessResult run = sxk({"plugins", "--json"});
    ASSERT_EQ(run.exit_code, 0);
    const auto json = nlohmann::json::parse(run.out);
    std::size_t built = 0;  // one .so per plug-in the build made
    for (const auto& entry : fs::directory_iterator(SXK_PLUGIN_BUILD_DIR)) built += entry.path().extension() == ".so";
    ASSERT_EQ(json["plugins"].size(), built);
    const auto stats = std::find_if(json["plugins"].begin(), json["plugins"].end(),
                                    [](const nlohmann::json& plugin) { return plugin["name"] == "stats"; });
    ASSERT_NE(stats, json["plugins"].end());
    EXPECT_EQ((*stats)["version"], "0.1.0");
    EXPECT_EQ((*stats)["path"], stats_plugin.string());
    EXPECT_EQ((*stats)["commands"][0]["name"], "stats");
    EXPECT_EQ(json["refused"], nlohmann::json::array());
    EXPECT_EQ(json["search_path"][0], fs::path(SXK_PLUGIN_BUILD_DIR).string());
}

TEST(SxkPlugins, RefusesBadPluginsAndGoesOn) {
    ScratchFolder folder;
    // not even an ELF file
    write_file(folder / "garbage.so", std::string(200, 'x'));
    const ProcessResult run = sxk({"plugins"}, {{"SXK_PLUGIN_PATH", bad_plugins.string() + ":" + folder.path().string()}});
    EXPECT_EQ(run.exit_code, 0);
    const fs::path unresolved = bad_plugins / "unresolved.so";
    const std::string expected_start =
        warning(bad_plugins / "no_entry.so", "not a simplexkit plug-in: no entry point sxk_plugin_entry") +
        "sxk: warning: " + unresolved.string() + ": cannot load: " + unresolved.string() +
        ": undefined symbol: sxk_test_undefined_function";
    EXPECT_EQ(run.err.rfind(expected_start, 0), 0u) << run.err;
    EXPECT_NE(run.err.find("\n" + warning(bad_plugins / "wrong_abi.so", "plug-in ABI version 999, this host needs 4") +
                           "sxk: warning: " + (folder / "garbage.so").string() + ": cannot load: "),
              std::string::npos)
        << run.err;
    EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 4);
    // the good plug-in is still there, and the refusals are listed
    EXPECT_NE(run.out.find("stats 0.1.0"), std::string::npos) << run.out;
    EXPECT_NE(run.out.find("refused:\n  " + (bad_plugins / "no_entry.so").string() + ": not a simplexkit plug-in"),
              std::string::npos)
        << run.out;
}

TEST(SxkPlugins, PluginCommandsStillRunBesideBadPlugins) {
    ScratchFolder folder;
    write_file(folder / "two.mesh", two_tetrahedra_mesh);
    const ProcessResult run = sxk({"stats", (folder / "two.mesh").string(), "--json"}, {{"SXK_PLUGIN_PATH", bad_plugins.string()}});
    EXPECT_EQ(run.exit_code, 0);
    EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 3) << run.err;
    EXPECT_EQ(nlohmann::json::parse(run.out)["elements"], 2);
}

TEST(SxkPlugins, BuiltInCommandsDoNotLoadPlugins) {
    ScratchFolder folder;
    write_file(folder / "two.mesh", two_tetrahedra_mesh);
    const ProcessResult run = sxk({"info", (folder / "two.mesh").string()}, {{"SXK_PLUGIN_PATH", bad_plugins.string()}});
    EXPECT_EQ(run.exit_code, 0);
    EXPECT_EQ(run.err, "");
}

TEST(SxkPlugins, SecondPluginOfTheSameNameIsRefused) {
    ScratchFolder folder;
    fs::copy_file(stats_plugin, folder / "stats_copy.so");
    const ProcessResult run = sxk({"plugins"}, {{"SXK_PLUGIN_PATH", folder.path().string()}});
    EXPECT_EQ(run.exit_code, 0);
    EXPECT_EQ(run.err, warning(folder / "stats_copy.so", "plug-in 'stats' is already loaded from " +
                                                             stats_plugin.string() + "; this one is ignored"));
}

TEST(SxkPlugins, SameFolderTwiceLoadsOnce) {
    const ProcessResult run = sxk({"plugins"}, {{"SXK_PLUGIN_PATH", std::string(SXK_PLUGIN_BUILD_DIR) + "::" SXK_PLUGIN_BUILD_DIR "/"}});
    EXPECT_EQ(run.exit_code, 0);
    EXPECT_EQ(run.err, "");
}

TEST(SxkPlugins, MissingFolderInThePathIsReported) {
    ScratchFolder folder;
    const fs::path missing = folder / "missing";
    const ProcessResult run = sxk({"plugins"}, {{"SXK_PLUGIN_PATH", missing.string()}});
    EXPECT_EQ(run.exit_code, 0);
    EXPECT_EQ(run.err, warning(missing, "no such plug-in folder"));
}

TEST(SxkStats, HistogramsAsJson) {
    ScratchFolder folder;
    const fs::path mesh = folder / "two.mesh";
    write_file(mesh, two_tetrahedra_mesh);
    const ProcessResult run = sxk({"stats", mesh.string(), "--bins", "4", "--json"});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_EQ(run.err, "");
    const auto json = nlohmann::json::parse(run.out);
    EXPECT_EQ(json["elements"], 2);
    EXPECT_EQ(json["bins"], 4);
    auto total = [](const nlohmann::json& histogram) {
        const auto counts = histogram["counts"].get<std::vector<std::size_t>>();
        EXPECT_EQ(counts.size(), 4u);
        return std::accumulate(counts.begin(), counts.end(), std::size_t{0});
    };
    EXPECT_EQ(total(json["aspect_ratio"]), 2u);
    EXPECT_EQ(total(json["radius_ratio"]), 2u);
    EXPECT_EQ(total(json["dihedral_angles"]), 12u);
    EXPECT_EQ(json["dihedral_angles"]["unit"], "radian");
}

TEST(SxkStats, TextBars) {
    ScratchFolder folder;
    const fs::path mesh = folder / "square.mesh";
    write_file(mesh, unit_square_mesh);
    const ProcessResult run = sxk({"stats", mesh.string(), "--bins", "3"});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    // two right isosceles triangles: angles 45, 45, 90 twice
    const std::string count4 = "         4 ", count2 = "         2 ", count0 = "         0 ";
    EXPECT_NE(run.out.find("angles, degrees (6 values)\n"
                           "  [0.0, 60.0)    " + count4 + std::string(40, '#') + "\n"
                           "  [60.0, 120.0)  " + count2 + std::string(20, '#') + "\n"
                           "  [120.0, 180.0] " + count0 + "\n"),
              std::string::npos)
        << run.out;
    EXPECT_EQ(run.out.rfind("file: " + mesh.string() + " (2 triangles)\naspect ratio (2 values)\n", 0), 0u) << run.out;
}

TEST(SxkStats, UsageAndInputErrors) {
    const ProcessResult no_mesh = sxk({"stats"});
    EXPECT_EQ(no_mesh.exit_code, 2);
    EXPECT_EQ(no_mesh.err, "sxk: stats: MESH is required\nRun 'sxk stats --help' for more information.\n");
    ScratchFolder folder;
    const ProcessResult missing = sxk({"stats", (folder / "missing.mesh").string()});
    EXPECT_EQ(missing.exit_code, 2);
    EXPECT_EQ(missing.err.rfind("sxk: " + (folder / "missing.mesh").string() + ":0: ", 0), 0u) << missing.err;
    write_file(folder / "two.mesh", two_tetrahedra_mesh);
    const std::string hint = "\nRun 'sxk stats --help' for more information.\n";
    for (const char* bins : {"0", "1001", "nan", "2.5"}) {
        const ProcessResult run = sxk({"stats", (folder / "two.mesh").string(), "--bins", bins});
        EXPECT_EQ(run.exit_code, 2) << bins;
        EXPECT_EQ(run.err, "sxk: stats: --bins: '" + std::string(bins) + "' is not a whole number in 1..1000" + hint);
    }
}

}  // namespace
}  // namespace sxk::test
