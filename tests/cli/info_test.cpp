// sxk info: counts, components, dimensions, labels; --json; unreadable input.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <regex>

#include "run_sxk.hpp"

namespace sxk::test {
namespace {

TEST(SxkInfo, TwoTetrahedraAsText) {
    ScratchFolder folder;
    const fs::path mesh = folder / "two.mesh";
    write_file(mesh, two_tetrahedra_mesh);
    const ProcessResult run = sxk({"info", mesh.string()});
    EXPECT_EQ(run.exit_code, 0) << run.err;
    EXPECT_EQ(run.out, "file: " + mesh.string() +
                           "\n"
                           "vertices: 5\n"
                           "elements: 2 tetrahedra\n"
                           "boundary faces: 6\n"
                           "components: 1\n"
                           "topological dimension: 3\n"
                           "ambient dimension: 3\n"
                           "element labels: 1 2\n"
                           "face labels: 7\n");
    EXPECT_EQ(run.err, "");
}

// A box Gmsh meshed, its volume in group 7 "bone" and two sides in group 3 "sides"
// (tests/data/io/gmsh_made/make.py), saved in binary 4.1.
TEST(SxkInfo, NamesTheLabelsAFileNames) {
    const std::string box = std::string(SXK_TEST_DATA_DIR) + "/io/gmsh_made/box41_binary.msh";
    const ProcessResult text = sxk({"info", box});
    ASSERT_EQ(text.exit_code, 0) << text.err;
    EXPECT_NE(text.out.find("element labels: 7\nface labels: 3\nelement label names: 7 \"bone\"\n"
                            "face label names: 3 \"sides\"\n"),
              std::string::npos)
        << text.out;
    const ProcessResult json = sxk({"info", box, "--json"});
    ASSERT_EQ(json.exit_code, 0) << json.err;
    const auto parsed = nlohmann::json::parse(json.out);
    EXPECT_EQ(parsed["element_label_names"], nlohmann::json({{"7", "bone"}}));
    EXPECT_EQ(parsed["face_label_names"], nlohmann::json({{"3", "sides"}}));
}

TEST(SxkInfo, JsonIsOneObject) {
    ScratchFolder folder;
    const fs::path mesh = folder / "two.mesh";
    write_file(mesh, two_tetrahedra_mesh);
    const ProcessResult run = sxk({"info", mesh.string(), "--json"});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const auto json = nlohmann::json::parse(run.out);
    EXPECT_EQ(json["file"], mesh.string());
    EXPECT_EQ(json["vertices"], 5);
    EXPECT_EQ(json["elements"], 2);
    EXPECT_EQ(json["element_kind"], "tetrahedron");
    EXPECT_EQ(json["boundary_faces"], 6);
    EXPECT_EQ(json["components"], 1);
    EXPECT_EQ(json["topological_dimension"], 3);
    EXPECT_EQ(json["ambient_dimension"], 3);
    EXPECT_EQ(json["element_labels"], nlohmann::json::parse("[1, 2]"));
    EXPECT_EQ(json["face_labels"], nlohmann::json::parse("[7]"));
}

TEST(SxkInfo, CountsFaceConnectedComponents) {
    ScratchFolder folder;
    const fs::path separate = folder / "separate.mesh";
    write_file(separate, separate_tetrahedra_mesh);
    const auto separate_json = nlohmann::json::parse(sxk({"info", separate.string(), "--json"}).out);
    EXPECT_EQ(separate_json["components"], 2);
    EXPECT_EQ(separate_json["boundary_faces"], 8);
}

TEST(SxkInfo, PlanarTriangles) {
    ScratchFolder folder;
    const fs::path mesh = folder / "square.mesh";
    write_file(mesh, unit_square_mesh);
    const ProcessResult run = sxk({"info", mesh.string(), "--json"});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const auto json = nlohmann::json::parse(run.out);
    EXPECT_EQ(json["element_kind"], "triangle");
    EXPECT_EQ(json["elements"], 2);
    EXPECT_EQ(json["boundary_faces"], 4);
    EXPECT_EQ(json["components"], 1);
    EXPECT_EQ(json["topological_dimension"], 2);
    EXPECT_EQ(json["ambient_dimension"], 2);
    EXPECT_EQ(json["face_labels"], nlohmann::json::array());
}

TEST(SxkInfo, MissingFileIsAnInputError) {
    ScratchFolder folder;
    const fs::path mesh = folder / "missing.mesh";
    const ProcessResult run = sxk({"info", mesh.string()});
    EXPECT_EQ(run.exit_code, 2);
    EXPECT_EQ(run.out, "");
    EXPECT_TRUE(std::regex_match(run.err, std::regex("sxk: " + regex_escape(mesh.string()) + ":0: .+\n"))) << run.err;
}

TEST(SxkInfo, BrokenFileNamesFileAndLine) {
    ScratchFolder folder;
    const fs::path mesh = folder / "broken.mesh";
    // the vertex count promises 4 vertices, the file ends after 2
    write_file(mesh, "MeshVersionFormatted 2\nDimension 3\nVertices\n4\n0 0 0 0\n1 0 0 0\n");
    const ProcessResult run = sxk({"info", mesh.string(), "--json"});
    EXPECT_EQ(run.exit_code, 2);
    EXPECT_EQ(run.out, "");
    EXPECT_TRUE(std::regex_match(run.err, std::regex("sxk: " + regex_escape(mesh.string()) + ":[1-9][0-9]*: .+\n"))) << run.err;
}

}  // namespace
}  // namespace sxk::test
