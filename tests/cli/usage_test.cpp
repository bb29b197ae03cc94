// sxk's own surface: --version, --help, unknown commands, usage errors (exit code 2).
#include <gtest/gtest.h>

#include "run_sxk.hpp"

namespace sxk::test {
namespace {

TEST(SxkUsage, VersionPrintsTheProjectVersion) {
    const ProcessResult run = sxk({"--version"});
    EXPECT_EQ(run.exit_code, 0);
    EXPECT_EQ(run.out, "sxk " SXK_VERSION "\n");
    EXPECT_EQ(run.err, "");
}

TEST(SxkUsage, HelpListsBuiltInAndPlugInCommands) {
    if (!SXK_HAVE_STATS) GTEST_SKIP() << "the stats plug-in is off";
    const ProcessResult run = sxk({"--help"});
    EXPECT_EQ(run.exit_code, 0);
    for (const char* command : {"info", "validate", "convert", "quality", "plugins"})
        EXPECT_NE(run.out.find(std::string("  ") + command), std::string::npos) << command;
    EXPECT_NE(run.out.find("Plug-in commands"), std::string::npos);
    EXPECT_NE(run.out.find("  stats "), std::string::npos);
    EXPECT_EQ(run.err, "");
}

TEST(SxkUsage, EveryCommandHasHelp) {
    for (const char* command : {"info", "validate", "convert", "quality", "plugins", "locate", "stats"}) {
        if (command == std::string("stats") && !SXK_HAVE_STATS) continue;
        const ProcessResult run = sxk({command, "--help"});
        EXPECT_EQ(run.exit_code, 0) << command;
        EXPECT_NE(run.out.find("Usage:"), std::string::npos) << command << ": " << run.out;
        EXPECT_EQ(run.err, "") << command;
    }
}

TEST(SxkUsage, NoCommandIsAUsageError) {
    const ProcessResult run = sxk({});
    EXPECT_EQ(run.exit_code, 2);
    EXPECT_EQ(run.out, "");
    EXPECT_EQ(run.err, "sxk: A subcommand is required\nRun 'sxk --help' for more information.\n");
}

TEST(SxkUsage, UnknownCommandIsAUsageError) {
    // the build's plug-in folder first, then SXK_PLUGIN_PATH's folders in order
    const std::string build_folder = std::string(SXK_BINARY_DIR) + "/lib/simplexkit/plugins";
    // (folders that exist and hold no plug-ins, so that nothing else is printed)
    const std::string docs = std::string(SXK_SOURCE_DIR) + "/docs", tools = std::string(SXK_SOURCE_DIR) + "/tools";
    const ProcessResult run = sxk({"frobnicate", "x.mesh"}, {{"SXK_PLUGIN_PATH", docs + ":" + tools}});
    EXPECT_EQ(run.exit_code, 2);
    EXPECT_EQ(run.err, "sxk: unknown command 'frobnicate' (see sxk --help and sxk plugins; plug-ins searched in " +
                           build_folder + ", " + docs + ", " + tools + ")\n");
}

TEST(SxkUsage, UnknownOptionNamesTheCommand) {
    const ProcessResult run = sxk({"info", "x.mesh", "--bogus"});
    EXPECT_EQ(run.exit_code, 2);
    EXPECT_EQ(run.err, "sxk: The following argument was not expected: --bogus\n"
                       "Run 'sxk info --help' for more information.\n");
}

TEST(SxkUsage, MissingOperand) {
    const ProcessResult run = sxk({"validate"});
    EXPECT_EQ(run.exit_code, 2);
    EXPECT_EQ(run.err, "sxk: MESH is required\nRun 'sxk validate --help' for more information.\n");
}

}  // namespace
}  // namespace sxk::test
