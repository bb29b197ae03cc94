// sxk quality: text and JSON summaries, thresholds.
#include <gtest/gtest.h>

#include <cmath>
#include <numeric>

#include <nlohmann/json.hpp>

#include "run_sxk.hpp"

namespace sxk::test {
namespace {

constexpr double pi = 3.14159265358979323846;

TEST(SxkQuality, JsonSummaryOfTwoTetrahedra) {
    ScratchFolder folder;
    const fs::path mesh = folder / "two.mesh";
    write_file(mesh, two_tetrahedra_mesh);
    const ProcessResult run = sxk({"quality", mesh.string(), "--json"});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_EQ(run.err, "");
    const auto json = nlohmann::json::parse(run.out);
    EXPECT_EQ(json["elements"], 2);
    EXPECT_EQ(json["element_kind"], "tetrahedron");
    EXPECT_EQ(json["angle_kind"], "dihedral");
    EXPECT_EQ(json["inverted"], 0);
    EXPECT_EQ(json["flat"], 0);
    EXPECT_EQ(json["degenerate"], 0);
    for (const char* name : {"needle", "spindle", "sliver", "cap"}) EXPECT_EQ(json["degenerate_by_class"][name], 0) << name;
    const auto histogram = json["aspect_histogram"].get<std::vector<std::size_t>>();
    EXPECT_EQ(histogram.size(), 10u);
    EXPECT_EQ(std::accumulate(histogram.begin(), histogram.end(), std::size_t{0}), 2u);
    EXPECT_GT(json["min_aspect_ratio"].get<double>(), 0.0);
    EXPECT_LE(json["min_aspect_ratio"].get<double>(), json["max_aspect_ratio"].get<double>());
    // the corner tetrahedron has right dihedral angles at the origin
    EXPECT_NEAR(json["max_angle"].get<double>(), pi / 2, 1e-9);
    EXPECT_NEAR(json["thresholds"]["aspect_ratio"].get<double>(), 0.01, 1e-12);
}

TEST(SxkQuality, AThresholdAboveEveryElementMakesAllDegenerate) {
    ScratchFolder folder;
    const fs::path mesh = folder / "two.mesh";
    write_file(mesh, two_tetrahedra_mesh);
    const ProcessResult run = sxk({"quality", mesh.string(), "--json", "--aspect", "0.99", "--angle", "3"});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const auto json = nlohmann::json::parse(run.out);
    EXPECT_EQ(json["degenerate"], 2);
    std::size_t classified = 0;
    for (const char* name : {"needle", "spindle", "sliver", "cap"}) classified += json["degenerate_by_class"][name].get<std::size_t>();
    EXPECT_EQ(classified, 2u);
}

TEST(SxkQuality, PlanarTriangleAngles) {
    ScratchFolder folder;
    const fs::path mesh = folder / "square.mesh";
    write_file(mesh, unit_square_mesh);
    const ProcessResult run = sxk({"quality", mesh.string(), "--json"});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const auto json = nlohmann::json::parse(run.out);
    EXPECT_EQ(json["angle_kind"], "triangle");
    EXPECT_NEAR(json["min_angle"].get<double>(), pi / 4, 1e-9);
    EXPECT_NEAR(json["max_angle"].get<double>(), pi / 2, 1e-9);
    EXPECT_EQ(json["degenerate_by_class"], nlohmann::json::object());
}

TEST(SxkQuality, TextNamesEveryFigure) {
    ScratchFolder folder;
    const fs::path mesh = folder / "two.mesh";
    write_file(mesh, two_tetrahedra_mesh);
    const ProcessResult run = sxk({"quality", mesh.string()});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    for (const char* line : {"elements: 2 tetrahedra\n", "aspect ratio: min ", "radius ratio: min ",
                             "dihedral angles: min ", " deg  max 90.00 deg\n", "inverted: 0\n", "flat: 0\n",
                             "degenerate (aspect ratio < 0.01): 0\n", "  needle 0 spindle 0 sliver 0 cap 0",
                             "aspect ratio histogram:\n"})
        EXPECT_NE(run.out.find(line), std::string::npos) << line << "\n" << run.out;
}

TEST(SxkQuality, RefusesThresholdsOutOfRange) {
    ScratchFolder folder;
    const fs::path mesh = folder / "two.mesh";
    write_file(mesh, two_tetrahedra_mesh);
    const std::string hint = "\nRun 'sxk quality --help' for more information.\n";
    ProcessResult run = sxk({"quality", mesh.string(), "--aspect", "2"});
    EXPECT_EQ(run.exit_code, 2);
    EXPECT_EQ(run.err, "sxk: --aspect: '2' is not in [0, 1]" + hint);
    run = sxk({"quality", mesh.string(), "--angle", "4"});
    EXPECT_EQ(run.exit_code, 2);
    EXPECT_EQ(run.err, "sxk: --angle: '4' is not in [0, pi]" + hint);
    run = sxk({"quality", mesh.string(), "--angle", "wide"});
    EXPECT_EQ(run.exit_code, 2);
    EXPECT_EQ(run.err, "sxk: --angle: expected a finite number, found 'wide'" + hint);
}

// NaN passed every range check (a comparison with NaN is false): the degenerate count was 0
// while the classes counted both elements as needles. Every numeric option now refuses it.
TEST(SxkQuality, RefusesNanAndInfiniteThresholds) {
    ScratchFolder folder;
    const fs::path mesh = folder / "two.mesh";
    write_file(mesh, two_tetrahedra_mesh);
    const std::string hint = "\nRun 'sxk quality --help' for more information.\n";
    for (const char* option : {"--aspect", "--angle"})
        for (const char* value : {"nan", "NaN", "-nan", "inf", "-inf", "infinity", "1e400"}) {
            const ProcessResult run = sxk({"quality", mesh.string(), "--json", option, value});
            EXPECT_EQ(run.exit_code, 2) << option << ' ' << value;
            EXPECT_EQ(run.err, "sxk: " + std::string(option) + ": expected a finite number, found '" + value + "'" + hint);
            EXPECT_EQ(run.out, "");
        }
    // a leading '+' is a number, as in the mesh files
    const ProcessResult run = sxk({"quality", mesh.string(), "--json", "--aspect", "+0.5"});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_EQ(nlohmann::json::parse(run.out)["thresholds"]["aspect_ratio"], 0.5);
}

}  // namespace
}  // namespace sxk::test
