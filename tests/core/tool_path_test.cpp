// Tool paths (sxk/tool_path.hpp): what a recorded scalpel or needle path may hold, and every
// refusal with its exact message.
#include <gtest/gtest.h>

#include <array>
#include <filesystem>
#include <fstream>
#include <string>

#include "sxk/io.hpp"
#include "sxk/tool_path.hpp"

namespace sxk {
namespace {

constexpr std::array<int, 1> scalpel{6};
constexpr std::array<int, 2> needle_or_point{2, 4};

TEST(ToolPath, ReadsSamplesCommentsAndBlankLines) {
    const ToolPath path = parse_tool_path(
        "# time hx hy hz tx ty tz\n"
        "0 0 0 1 0 0 0.2   # the scalpel above the mesh\n"
        "\r\n"
        "0.5 +0.1 0 1 0.1 0 -2e-1\r\n"
        "0.5 0.2 0 1 0.2 0 -0.2\n",
        "cut.path", scalpel);
    EXPECT_EQ(path.columns, 6);
    ASSERT_EQ(path.samples.size(), 3u);
    EXPECT_EQ(path.samples[0].time, 0);
    EXPECT_EQ(path.samples[1].time, 0.5);
    EXPECT_EQ(path.samples[2].time, 0.5);  // equal times are allowed
    EXPECT_EQ(path.samples[1].values[0], 0.1);
    EXPECT_EQ(path.samples[1].values[5], -0.2);
    EXPECT_EQ(path.samples[0].values[2], 1);
}

TEST(ToolPath, TheFirstSampleDecidesBetweenTheAcceptedCounts) {
    EXPECT_EQ(parse_tool_path("0 0 0\n1 1 1\n", "p", needle_or_point).columns, 2);
    EXPECT_EQ(parse_tool_path("0 0 0 1 1\n1 1 1 2 2\n", "p", needle_or_point).columns, 4);
}

std::string refusal(const std::string& text, std::span<const int> columns) {
    try {
        parse_tool_path(text, "cut.path", columns);
    } catch (const InputError& e) {
        return e.what();
    }
    return "(accepted)";
}

TEST(ToolPath, RefusesWhatIsNotAPathWithTheLine) {
    EXPECT_EQ(refusal("0 0 0 1 0 0 0\n1 0 0 1 x 0 0\n", scalpel),
              "cut.path:2: expected a coordinate, found 'x'");
    EXPECT_EQ(refusal("0 0 0 1 0 0 0\n1 0 0 1 nan 0 0\n", scalpel),
              "cut.path:2: coordinate is not finite");
    EXPECT_EQ(refusal("# header\ninf 0 0 1 0 0 0\n1 0 0 1 0 0 0\n", scalpel),
              "cut.path:2: time is not finite");
    EXPECT_EQ(refusal("t 0 0 1 0 0 0\n", scalpel), "cut.path:1: expected a time, found 't'");
    EXPECT_EQ(refusal("0 0 0 1 0 0\n1 0 0 1 0 0\n", scalpel),
              "cut.path:1: 5 values after the time; expected 6");
    EXPECT_EQ(refusal("0 0 0 0\n", needle_or_point),
              "cut.path:1: 3 values after the time; expected 2 or 4");
    EXPECT_EQ(refusal("0 0 0 1 0 0 0\n1 0 0 1 0 0\n", scalpel),
              "cut.path:2: 5 values after the time; the first sample has 6");
    EXPECT_EQ(refusal("0 1 2 3 4 5 6 7\n", scalpel),
              "cut.path:1: more than 6 values after the time");
    EXPECT_EQ(refusal("1 0 0 1 0 0 0\n0.5 0 0 1 0 0 0\n", scalpel),
              "cut.path:2: time 0.5 is before the previous sample's 1");
    EXPECT_EQ(refusal("0 0 0 1 0 0 0\n", scalpel),
              "cut.path:0: 1 sample; a path needs at least 2 (a tool moves from one to the next)");
    EXPECT_EQ(refusal("# nothing\n\n", scalpel),
              "cut.path:0: 0 samples; a path needs at least 2 (a tool moves from one to the next)");
}

TEST(ToolPath, ReadsAFileAndRefusesBinaryData) {
    const std::filesystem::path file =
        std::filesystem::temp_directory_path() / "sxk_tool_path_test.path";
    {
        std::ofstream out(file, std::ios::binary);
        out << "0 0 0\n1 1 1\n";
    }
    EXPECT_EQ(read_tool_path(file, needle_or_point).samples.size(), 2u);
    {
        std::ofstream out(file, std::ios::binary);
        out << "0 0 0\n1 1\0 1\n";
        out.write("\0", 1);
    }
    EXPECT_THROW(read_tool_path(file, needle_or_point), InputError);
    std::filesystem::remove(file);
    EXPECT_THROW(read_tool_path(file, needle_or_point), InputError);  // missing
}

}  // namespace
}  // namespace sxk
