// PluginHost in-process: loading the stats plug-in, refusing bad ones with exact reasons while
// going on, duplicates, static registration, command lookup.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string_view>

#include "sxk/plugin_host.hpp"
#if SXK_HAVE_STATS
#include "stats.hpp"
#endif

namespace sxk::test {
namespace {

namespace fs = std::filesystem;

const fs::path plugin_folder = SXK_PLUGIN_BUILD_DIR;
const fs::path bad_folder = SXK_BAD_PLUGIN_DIR;

// The plug-ins the build made (stats, degeneracy, ...): the folder holds one .so each.
std::size_t built_plugins() {
    std::size_t n = 0;
    for (const auto& entry : fs::directory_iterator(plugin_folder)) n += entry.path().extension() == ".so";
    return n;
}

// The loaded plug-in called `name`, or nullptr.
const LoadedPlugin* loaded(const PluginHost& host, std::string_view name) {
    for (const LoadedPlugin& plugin : host.plugins())
        if (plugin.name == name) return &plugin;
    return nullptr;
}

std::string describe(std::span<const PluginDiagnostic> diagnostics) {
    std::string text;
    for (const auto& diagnostic : diagnostics) text += diagnostic.path.string() + ": " + diagnostic.reason + "\n";
    return text;
}

TEST(PluginHost, StartsEmpty) {
    const PluginHost host;
    EXPECT_TRUE(host.plugins().empty());
    EXPECT_TRUE(host.diagnostics().empty());
    EXPECT_EQ(host.find("stats"), nullptr);
    const std::vector<std::string> args{"stats"};
    EXPECT_EQ(host.find_command(args).command, nullptr);
}

TEST(PluginHost, DefaultFolderIsTheBuildFolderInTheBuildTree) {
    const auto folders = PluginHost::default_folders();
    ASSERT_EQ(folders.size(), 1u);
    EXPECT_EQ(folders.front(), plugin_folder);
}

#if SXK_HAVE_STATS
TEST(PluginHost, LoadsTheStatsPlugin) {
    PluginHost host;
    EXPECT_EQ(host.load_folder(plugin_folder), built_plugins());
    EXPECT_EQ(describe(host.diagnostics()), "");
    ASSERT_EQ(host.plugins().size(), built_plugins());
    ASSERT_NE(loaded(host, "stats"), nullptr);
    const LoadedPlugin& stats = *loaded(host, "stats");
    EXPECT_EQ(stats.name, "stats");
    EXPECT_EQ(stats.version, "0.1.0");
    EXPECT_EQ(stats.summary, "histograms of element quality");
    EXPECT_EQ(stats.path, plugin_folder / "stats.so");
    EXPECT_EQ(host.find("stats"), stats.plugin);

    const std::vector<std::string> args{"stats", "x.mesh", "--json"};
    const FoundCommand found = host.find_command(args);
    ASSERT_NE(found.command, nullptr);
    EXPECT_EQ(found.command->name(), "stats");
    EXPECT_EQ(found.words, 1u);
    EXPECT_EQ(found.plugin->name, "stats");
}
#endif

TEST(PluginHost, RefusesBadPluginsWithExactReasonsAndGoesOn) {
    PluginHost host;
    EXPECT_EQ(host.load_folder(bad_folder), 0u);
#if SXK_HAVE_STATS
    EXPECT_EQ(host.load_folder(plugin_folder), built_plugins());
#endif
    const auto diagnostics = host.diagnostics();
    ASSERT_EQ(diagnostics.size(), 3u) << describe(diagnostics);
    // files are visited in name order
    EXPECT_EQ(diagnostics[0].path, bad_folder / "no_entry.so");
    EXPECT_EQ(diagnostics[0].reason, "not a simplexkit plug-in: no entry point sxk_plugin_entry");
    EXPECT_EQ(diagnostics[1].path, bad_folder / "unresolved.so");
    EXPECT_EQ(diagnostics[1].reason, "cannot load: " + (bad_folder / "unresolved.so").string() +
                                         ": undefined symbol: sxk_test_undefined_function");
    EXPECT_EQ(diagnostics[2].path, bad_folder / "wrong_abi.so");
    EXPECT_EQ(diagnostics[2].reason, "plug-in ABI version 999, this host needs 4");
#if SXK_HAVE_STATS
    ASSERT_EQ(host.plugins().size(), built_plugins());
    EXPECT_NE(loaded(host, "stats"), nullptr);
#endif
}

TEST(PluginHost, RefusesAFileThatIsNotASharedObject) {
    const fs::path garbage = fs::temp_directory_path() / ("sxk-garbage-" + std::to_string(::getpid()) + ".so");
    std::ofstream(garbage) << std::string(200, 'x');
    PluginHost host;
    EXPECT_FALSE(host.load_file(garbage));
    fs::remove(garbage);
    ASSERT_EQ(host.diagnostics().size(), 1u);
    EXPECT_EQ(host.diagnostics()[0].reason.rfind("cannot load: " + fs::weakly_canonical(garbage).string() + ": ", 0), 0u)
        << host.diagnostics()[0].reason;
}

#if SXK_HAVE_STATS
TEST(PluginHost, FirstPluginOfANameWins) {
    PluginHost host;
    ASSERT_TRUE(host.add_static(sxk_plugin_entry_stats(), "linked-in stats"));
    EXPECT_EQ(host.load_folder(plugin_folder), built_plugins() - 1);
    ASSERT_EQ(host.diagnostics().size(), 1u);
    EXPECT_EQ(host.diagnostics()[0].path, plugin_folder / "stats.so");
    EXPECT_EQ(host.diagnostics()[0].reason,
              "plug-in 'stats' is already loaded from linked-in stats; this one is ignored");
    ASSERT_EQ(host.plugins().size(), built_plugins());
    EXPECT_EQ(loaded(host, "stats")->path, "linked-in stats");
}
#endif

#if SXK_HAVE_STATS
TEST(PluginHost, TheSameFileLoadsOnce) {
    PluginHost host;
    EXPECT_EQ(host.load_folder(plugin_folder), built_plugins());
    EXPECT_EQ(host.load_folder(plugin_folder / "."), 0u);
    EXPECT_FALSE(host.load_file(plugin_folder / "stats.so"));
    EXPECT_TRUE(host.diagnostics().empty());
    EXPECT_EQ(host.plugins().size(), built_plugins());
}
#endif

TEST(PluginHost, MissingFolderIsReported) {
    PluginHost host;
    EXPECT_EQ(host.load_folder(bad_folder / "missing"), 0u);
    ASSERT_EQ(host.diagnostics().size(), 1u);
    EXPECT_EQ(host.diagnostics()[0].reason, "no such plug-in folder");
}

#if SXK_HAVE_STATS
TEST(PluginHost, EnvironmentPathIsSearched) {
    ::setenv("SXK_PLUGIN_PATH", (bad_folder.string() + "::" + (bad_folder / "missing").string()).c_str(), 1);
    PluginHost host;
    host.load_default_folders();
    ::unsetenv("SXK_PLUGIN_PATH");
    EXPECT_EQ(host.plugins().size(), built_plugins());  // stats and the others, from the build folder
    ASSERT_EQ(host.diagnostics().size(), 4u) << describe(host.diagnostics());
    EXPECT_EQ(host.diagnostics()[3].path, bad_folder / "missing");
}
#endif

#if SXK_HAVE_STATS
TEST(PluginHost, RefusesStaticInfoWithAnotherAbi) {
    sxk_plugin_info info = *sxk_plugin_entry_stats();
    info.abi_version = SXK_PLUGIN_ABI_VERSION + 1;
    PluginHost host;
    EXPECT_FALSE(host.add_static(&info, "patched"));
    ASSERT_EQ(host.diagnostics().size(), 1u);
    EXPECT_EQ(host.diagnostics()[0].reason, "plug-in ABI version 5, this host needs 4");
    EXPECT_FALSE(host.add_static(nullptr, "null"));
}
#endif

#if SXK_HAVE_STATS
TEST(PluginHost, MovesKeepPluginsLoaded) {
    PluginHost host;
    ASSERT_EQ(host.load_folder(plugin_folder), built_plugins());
    PluginHost moved(std::move(host));
    ASSERT_EQ(moved.plugins().size(), built_plugins());
    const std::vector<std::string> args{"stats", "--help"};
    const FoundCommand found = moved.find_command(args);
    ASSERT_NE(found.command, nullptr);
    std::ostringstream out, err;
    EXPECT_EQ(found.command->run(std::span(args).subspan(1), out, err), 0);
    EXPECT_NE(out.str().find("--bins"), std::string::npos);
}
#endif

}  // namespace
}  // namespace sxk::test
