// One message style for the numbers in options (docs/cli.md "Numbers in options"): whole numbers
// checked by cli/command_line.hpp's whole_number and whole_number_in, not CLI11's own
// conversion or range messages, which issue 47 found on `dissect --cut-label nan` and
// `needle --iterations 0`.
#include <gtest/gtest.h>

#include "run_sxk.hpp"

namespace sxk::test {
namespace {

TEST(SxkOptionMessages, DissectCutLabelIsAWholeNumber) {
    ScratchFolder folder;
    const fs::path in = folder / "two.mesh", faces = folder / "faces", out = folder / "out.mesh";
    write_file(in, two_tetrahedra_mesh);
    write_file(faces, "1 2 3\n");
    for (const std::string label : {"nan", "1.5", "1e3"}) {
        const ProcessResult run =
            sxk({"dissect", in.string(), out.string(), "--faces", faces.string(), "--cut-label", label});
        EXPECT_EQ(run.exit_code, 2) << label;
        EXPECT_EQ(run.err, "sxk: --cut-label: '" + label +
                               "' is not a whole number\nRun 'sxk dissect --help' for more information.\n");
        EXPECT_FALSE(fs::exists(out));
    }
}

TEST(SxkOptionMessages, NeedleIterationsAreAWholeNumberInRange) {
    if (sxk({"plugins"}).out.find("needle ") == std::string::npos) GTEST_SKIP() << "no needle plug-in";
    ScratchFolder folder;
    const fs::path slab = folder / "slab.mesh", out = folder / "out.mesh";
    ASSERT_EQ(sxk({"generate", slab.string(), "--shape", "square", "--cells", "8", "--spacing", "0.0125"}).exit_code,
              0);
    for (const std::string iterations : {"0", "nan", "1e3"}) {
        const ProcessResult run = sxk({"needle", slab.string(), SXK_SOURCE_DIR "/tests/data/paths/slab-insertion.path",
                                       out.string(), "--iterations", iterations});
        EXPECT_EQ(run.exit_code, 2) << iterations;
        EXPECT_EQ(run.err, "sxk: needle: --iterations: '" + iterations +
                               "' is not a whole number in 1..100000000\nRun 'sxk needle --help' for more "
                               "information.\n");
        EXPECT_FALSE(fs::exists(out));
    }
}

}  // namespace
}  // namespace sxk::test
