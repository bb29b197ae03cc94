// sxk under a file-size limit (RLIMIT_FSIZE, `ulimit -f`): the write fails with a message and
// exit 1, the old output stays and no temporary is left (sxk ignores SIGXFSZ, which would
// otherwise kill it mid-write: exit 153, silence, a stray ".OUT.sxk-PID-N.tmp").
#include <gtest/gtest.h>

#include <algorithm>

#include "run_sxk.hpp"

namespace sxk::test {
namespace {

std::vector<std::string> names_in(const fs::path& folder) {
    std::vector<std::string> names;
    for (const fs::directory_entry& entry : fs::directory_iterator(folder))
        names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

TEST(SxkFileSizeLimit, AWriteOverTheLimitFailsWithAMessageAndLeavesNoTemporary) {
    ScratchFolder folder;
    const fs::path cube = folder / "cube.mesh", out = folder / "out.msh";
    // about 100 KB in .msh, far above the 1 KiB limit below; cube.mesh is written without one
    ASSERT_EQ(sxk({"generate", cube.string(), "--cells", "6"}).exit_code, 0);
    write_file(out, "the user's old file\n");
    const std::vector<std::string> before = names_in(folder.path());
    // bash sets the limit (in KiB) and replaces itself with sxk, which inherits it
    const ProcessResult run = run_program(
        "/bin/bash", {"-c", "ulimit -f 1 && exec \"$0\" \"$@\"", SXK_EXE, "convert", cube.string(), out.string()});
    EXPECT_EQ(run.exit_code, 1) << run.err;
    EXPECT_EQ(run.err, "sxk: " + out.string() + ":0: cannot write: File too large\n");
    EXPECT_EQ(run.out, "");
    EXPECT_EQ(slurp(out), "the user's old file\n");
    EXPECT_EQ(names_in(folder.path()), before);
}

}  // namespace
}  // namespace sxk::test
