// sxk dissect --faces FILE: the cut, the face-file format (0-based ids, '#' comments) and its
// errors as "sxk: FILE:LINE: reason" with exit code 2; sxk convert --reorder.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "fifo_writer.hpp"
#include "run_sxk.hpp"

namespace sxk::test {
namespace {

// two_tetrahedra_mesh holds <0,1,2,3> and <1,2,3,4> in 0-based ids, glued along 1-2-3.
struct DissectFixture {
    ScratchFolder folder;
    fs::path mesh = folder / "two.mesh";
    fs::path faces = folder / "faces.txt";
    fs::path out = folder / "cut.mesh";
    DissectFixture() { write_file(mesh, two_tetrahedra_mesh); }
    ProcessResult run(const std::string& face_text) {
        write_file(faces, face_text);
        return sxk({"dissect", mesh.string(), out.string(), "--faces", faces.string()});
    }
};

TEST(SxkDissect, CutsTwoTetrahedraApart) {
    DissectFixture f;
    const ProcessResult run = f.run("# the shared triangle, seen from the second tetrahedron\n3 2 1\n\n");
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_EQ(run.out, f.mesh.string() + " -> " + f.out.string() + ": 1 cut faces, 3 new vertices, 2 boundary faces on the cut, 2 components\n");
    EXPECT_EQ(run.err, "");
    const ProcessResult info = sxk({"info", f.out.string(), "--json"});
    ASSERT_EQ(info.exit_code, 0) << info.err;
    const nlohmann::json json = nlohmann::json::parse(info.out);
    EXPECT_EQ(json["vertices"], 8);
    EXPECT_EQ(json["components"], 2);
    EXPECT_EQ(json["boundary_faces"], 8);
    EXPECT_EQ(sxk({"validate", f.out.string()}).exit_code, 0);
}

// The two triangles the cut makes are written with the cut label (Medit "Triangles" section:
// vertices 1-based, then the reference), beside the file's own labelled triangle; --cut-label
// picks the label, --no-cut-label leaves them unlabelled.
TEST(SxkDissect, TheCutFacesAreWrittenWithTheCutLabel) {
    DissectFixture f;
    write_file(f.faces, "1 2 3\n");
    auto triangles_of = [&](const std::vector<std::string>& extra) {
        std::vector<std::string> args{"dissect", f.mesh.string(), f.out.string(), "--faces", f.faces.string()};
        args.insert(args.end(), extra.begin(), extra.end());
        const ProcessResult run = sxk(args);
        EXPECT_EQ(run.exit_code, 0) << run.err;
        const std::string text = slurp(f.out);
        const auto at = text.find("Triangles");
        return at == std::string::npos ? std::string() : text.substr(at, text.find("\n\n", at) - at);
    };
    // the second tetrahedron got the copies 6, 7, 8 of 2, 3, 4; its side is seen from there
    EXPECT_EQ(triangles_of({}), "Triangles\n3\n2 1 3 7\n2 3 4 9999\n7 6 8 9999");
    EXPECT_EQ(triangles_of({"--cut-label", "5"}), "Triangles\n3\n2 1 3 7\n2 3 4 5\n7 6 8 5");
    EXPECT_EQ(triangles_of({"--no-cut-label"}), "Triangles\n1\n2 1 3 7");
}

TEST(SxkDissect, NotAVertexId) {
    DissectFixture f;
    const ProcessResult run = f.run("# comment\n1 2 x\n");
    EXPECT_EQ(run.exit_code, 2);
    EXPECT_EQ(run.err, "sxk: " + f.faces.string() + ":2: 'x' is not a vertex id\n");
    EXPECT_EQ(run.out, "");
    EXPECT_FALSE(fs::exists(f.out));
}

TEST(SxkDissect, WrongNumberOfIds) {
    DissectFixture f;
    const ProcessResult run = f.run("1 2   # an edge\n");
    EXPECT_EQ(run.exit_code, 2);
    EXPECT_EQ(run.err, "sxk: " + f.faces.string() + ":1: a face of a tetrahedron mesh has 3 vertices, this line has 2\n");
}

TEST(SxkDissect, UnknownVertex) {
    DissectFixture f;
    const ProcessResult run = f.run("1 2 5\n");
    EXPECT_EQ(run.exit_code, 2);
    EXPECT_EQ(run.err, "sxk: " + f.faces.string() +
                           ":1: vertex 5 does not exist (ids are 0-based, the mesh has 5 vertices)\n");
}

TEST(SxkDissect, NotAFaceOfTheMesh) {
    DissectFixture f;
    const ProcessResult run = f.run("1 2 3\n0 1 4\n");
    EXPECT_EQ(run.exit_code, 2);
    EXPECT_EQ(run.err, "sxk: " + f.faces.string() + ":2: dissect: cut face 1 +<0,1,4> is not a face of the mesh\n");
    EXPECT_FALSE(fs::exists(f.out));
}

TEST(SxkDissect, MissingFaceFile) {
    DissectFixture f;
    const ProcessResult run = sxk({"dissect", f.mesh.string(), f.out.string(), "--faces", (f.folder / "none.txt").string()});
    EXPECT_EQ(run.exit_code, 2);
    EXPECT_EQ(run.err, "sxk: " + (f.folder / "none.txt").string() + ":0: no such file\n");
}

// The face list is read as mesh files are: what is not a file of text is an input error, never
// an empty list that cuts nothing (a directory and /dev/null used to dissect along no faces).
TEST(SxkDissect, FaceFilesThatAreNoFilesAreRefused) {
    DissectFixture f;
    fs::create_directory(f.folder / "faces");
    const std::vector<std::pair<std::string, std::string>> cases = {
        {(f.folder / "faces").string(), "is a directory"},
        {"/dev/zero", "is a character device, not a file"},
        {"/dev/null", "is a character device, not a file"},
        // a regular file of size 0 whose first page cannot be read (EIO)
        {"/proc/self/mem", "cannot read: Input/output error"},
    };
    for (const auto& [faces, reason] : cases) {
        const ProcessResult run = sxk({"dissect", f.mesh.string(), f.out.string(), "--faces", faces});
        EXPECT_EQ(run.exit_code, 2) << faces;
        EXPECT_EQ(run.err, "sxk: " + faces + ":0: " + reason + "\n");
        EXPECT_EQ(run.out, "");
        EXPECT_FALSE(fs::exists(f.out));
    }
}

TEST(SxkDissect, BinaryFaceFileIsRefused) {
    DissectFixture f;
    const ProcessResult run = f.run(std::string("1 2 3\n1 2\0 4\n", 12));
    EXPECT_EQ(run.exit_code, 2);
    EXPECT_EQ(run.err, "sxk: " + f.faces.string() + ":2: binary data (byte 0x00)\n");
    EXPECT_FALSE(fs::exists(f.out));
}

TEST(SxkDissect, FaceFileWithAByteOrderMark) {
    DissectFixture f;
    const ProcessResult run = f.run("\xEF\xBB\xBF" "1 2 3\n");
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_EQ(run.out, f.mesh.string() + " -> " + f.out.string() + ": 1 cut faces, 3 new vertices, 2 boundary faces on the cut, 2 components\n");
}

// A FIFO (a shell's --faces <(...)) is read, up to the bound every input has (max_input_bytes).
TEST(SxkDissect, FaceListFromAFifo) {
    DissectFixture f;
    const fs::path fifo = f.folder / "faces.fifo";
    ProcessResult run;
    {
        FifoWriter writer(fifo, "# from a pipe\n1 2 3\n");
        run = sxk({"dissect", f.mesh.string(), f.out.string(), "--faces", fifo.string()});
    }
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_EQ(run.out, f.mesh.string() + " -> " + f.out.string() + ": 1 cut faces, 3 new vertices, 2 boundary faces on the cut, 2 components\n");
}

TEST(SxkDissect, FacesOptionIsRequired) {
    DissectFixture f;
    const ProcessResult run = sxk({"dissect", f.mesh.string(), f.out.string()});
    EXPECT_EQ(run.exit_code, 2);
    EXPECT_NE(run.err.find("--faces is required"), std::string::npos) << run.err;
}

TEST(SxkConvertReorder, ReportsBandwidthAndKeepsTheMesh) {
    ScratchFolder folder;
    const fs::path mesh = folder / "two.mesh", out = folder / "reordered.mesh";
    write_file(mesh, two_tetrahedra_mesh);
    const ProcessResult run = sxk({"convert", mesh.string(), out.string(), "--reorder"});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_EQ(run.out, mesh.string() + " -> " + out.string() + ": 5 vertices, 2 tetrahedra, bandwidth 3 -> 3\n");
    EXPECT_EQ(sxk({"validate", out.string()}).exit_code, 0);
    const nlohmann::json json = nlohmann::json::parse(sxk({"info", out.string(), "--json"}).out);
    EXPECT_EQ(json["elements"], 2);
    EXPECT_EQ(json["boundary_faces"], 6);
    EXPECT_EQ(json["face_labels"], nlohmann::json::array({7}));
}

}  // namespace
}  // namespace sxk::test
