// The readers' parallel paths (docs/architecture.md "Threads"): a file gives the same mesh, byte
// for byte and id for id, and a soup the same refusal, whatever the number of threads; the
// files of a TetGen set, read side by side, report their problems in file order.
#include <gtest/gtest.h>

#include <tbb/global_control.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "io_fixtures.hpp"
#include "sxk/generators.hpp"
#include "sxk/io.hpp"
#include "sxk/mesh.hpp"

namespace sxk {
namespace {

using test::scratch_dir;

// 1 is the single-threaded reference; 3 and 7 cut the vertex and element ranges unevenly, and
// more slots than cores still split the work into that many parts.
constexpr int thread_counts[] = {1, 2, 3, 4, 7};

// Runs `work` with exactly `threads` threads, more than the machine's cores if asked (TBB
// otherwise caps its workers at the core count).
template <class Work>
auto in_arena(int threads, Work&& work) {
    tbb::global_control workers(tbb::global_control::max_allowed_parallelism,
                                static_cast<std::size_t>(threads));
    tbb::task_arena arena(threads);
    return arena.execute(work);
}

std::string bytes_of(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream bytes;
    bytes << in.rdbuf();
    return bytes.str();
}

// Everything a read decides beyond the file's contents: element and face ids, mates, anchors and
// the boundary map's faces.
struct Ids {
    std::vector<ElementId> anchors;
    std::vector<std::array<FaceId, 4>> faces;
    std::vector<FaceId> mates;
    std::vector<FaceId> boundary;
    bool operator==(const Ids&) const = default;
};

Ids ids_of(const Mesh& mesh) {
    Ids ids;
    for (VertexId v = 0; v < mesh.vertex_count(); ++v) ids.anchors.push_back(mesh.vertex_element(v));
    for (ElementId t : elements(mesh)) {
        std::array<FaceId, 4> faces{invalid_id, invalid_id, invalid_id, invalid_id};
        for (int j = 0; j <= mesh.topological_dimension(); ++j)
            faces[static_cast<std::size_t>(j)] = mesh.face(t, j);
        ids.faces.push_back(faces);
    }
    for (std::size_t f = 0; f < mesh.face_capacity(); ++f) ids.mates.push_back(mesh.mate(static_cast<FaceId>(f)));
    ids.boundary = mesh.boundary_faces();
    return ids;
}

// A labelled Kuhn cube: element labels by octant, boundary faces labelled by their lowest vertex.
Mesh labelled_cube(int n) {
    Mesh mesh = make_kuhn_cube(n).value();
    for (ElementId t : elements(mesh)) mesh.set_label(t, static_cast<int>(t.value() % 5));
    for (FaceId f : mesh.boundary_faces()) {
        const Simplex face = mesh.face_simplex(f);
        mesh.face_labels()[Simplex(+1, face.vertices())] = 10 + static_cast<int>(face.vertex(0) % 3);
    }
    return mesh;
}

TEST(ParallelRead, EveryFormatGivesTheSameMeshWhateverTheNumberOfThreads) {
    const std::filesystem::path dir = scratch_dir();
    const Mesh original = labelled_cube(10);  // 6,000 tetrahedra
    std::filesystem::create_directories(dir / "reference");
    std::filesystem::create_directories(dir / "again");
    for (const char* name : {"cube.mesh", "cube.1.ele", "cube.msh", "surface.off"}) {
        SCOPED_TRACE(name);
        write_mesh(original, dir / name);
        const Mesh reference = in_arena(1, [&] { return read_mesh(dir / name); });
        ASSERT_TRUE(reference.validate().ok()) << reference.validate().reason();
        write_mesh(reference, dir / "reference" / name);
        for (int threads : thread_counts) {
            SCOPED_TRACE(threads);
            const Mesh mesh = in_arena(threads, [&] { return read_mesh(dir / name); });
            EXPECT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
            EXPECT_EQ(ids_of(mesh), ids_of(reference));
            test::expect_same_mesh(reference, mesh);
            write_mesh(mesh, dir / "again" / name);
            EXPECT_EQ(bytes_of(dir / "again" / name), bytes_of(dir / "reference" / name));
        }
    }
}

// A soup with several problems in different vertex and element ranges: every thread count names
// the problem of the smallest element index, with the same words.
TEST(ParallelRead, ASoupIsRefusedForTheSameElementWhateverTheNumberOfThreads) {
    const Mesh cube = make_kuhn_cube(8).value();  // 3,072 tetrahedra
    std::vector<Simplex> soup;
    for (ElementId t : elements(cube)) soup.push_back(cube.simplex(t));
    // element 2900 turned over (inconsistent with its neighbours), and element 1500 repeated at
    // the end: the inconsistency of 2900 has the smaller index
    soup[2900] = soup[2900].mate();
    soup.push_back(soup[1500]);
    std::vector<Point> points(cube.reference_positions().begin(), cube.reference_positions().end());
    auto refusal_with = [&](int threads) {
        return in_arena(threads, [&] {
            Mesh mesh(3, 3);
            for (const Point& p : points) mesh.add_vertex(p);
            Outcome<Done> built = mesh.assign_elements(soup);
            EXPECT_EQ(mesh.element_count(), 0u);
            EXPECT_TRUE(mesh.validate().ok());
            return built ? Refusal{RefusalCode::internal_error, "accepted"} : built.refusal();
        });
    };
    const Refusal reference = refusal_with(1);
    EXPECT_EQ(reference.code, RefusalCode::not_manifold);
    EXPECT_EQ(reference.item, 2900u);
    EXPECT_NE(reference.reason.find("with the same orientation (inconsistently oriented)"), std::string::npos)
        << reference.reason;
    for (int threads : thread_counts) {
        SCOPED_TRACE(threads);
        const Refusal refusal = refusal_with(threads);
        EXPECT_EQ(refusal.code, reference.code);
        EXPECT_EQ(refusal.item, reference.item);
        EXPECT_EQ(refusal.reason, reference.reason);
    }
}

// Two cubes sharing only a corner: the shared vertex's star is two fans (pinched); with the
// cubes' vertices interleaved, the star check's vertex ranges all hold some of its elements.
TEST(ParallelRead, APinchedVertexIsFoundWhateverTheNumberOfThreads) {
    const Mesh cube = make_kuhn_cube(3).value();
    const VertexId corner = static_cast<VertexId>(cube.vertex_count() - 1);  // (3,3,3)
    std::vector<Point> points;
    for (const Point& p : cube.reference_positions()) points.push_back(p);
    for (const Point& p : cube.reference_positions()) points.push_back({p[0] + 3, p[1] + 3, p[2] + 3});
    std::vector<Simplex> soup;
    for (ElementId t : elements(cube)) soup.push_back(cube.simplex(t));
    for (ElementId t : elements(cube)) {
        // the second cube's vertex 0 is the first cube's corner
        std::array<VertexId, 4> moved{};
        for (int j = 0; j < 4; ++j) {
            const VertexId v = cube.simplex(t).vertex(j);
            moved[static_cast<std::size_t>(j)] = v == 0 ? corner : v + static_cast<VertexId>(cube.vertex_count());
        }
        soup.push_back(Simplex(cube.simplex(t).sign(), moved));
    }
    for (int threads : thread_counts) {
        SCOPED_TRACE(threads);
        const Refusal refusal = in_arena(threads, [&] {
            Mesh mesh(3, 3);
            for (const Point& p : points) mesh.add_vertex(p);
            Outcome<Done> built = mesh.assign_elements(soup);
            return built ? Refusal{RefusalCode::internal_error, "accepted"} : built.refusal();
        });
        EXPECT_EQ(refusal.code, RefusalCode::pinched_star);
        EXPECT_EQ(refusal.reason, "star connectivity: the elements around vertex " +
                                      std::to_string(corner) +
                                      " are not connected through faces (the mesh is pinched there)");
    }
}

// Appends a line to a file of the set.
void append_line(const std::filesystem::path& path, const std::string& line) {
    std::ofstream(path, std::ios::app) << line << '\n';
}

std::size_t line_count(const std::filesystem::path& path) {
    const std::string bytes = bytes_of(path);
    return static_cast<std::size_t>(std::count(bytes.begin(), bytes.end(), '\n'));
}

std::string read_error(const std::filesystem::path& path, int threads) {
    try {
        in_arena(threads, [&] { return read_mesh(path); });
    } catch (const InputError& error) {
        return error.what();
    }
    return "no error";
}

// .node, .ele and .face are read side by side; with a problem in several, the first file's is
// the one reported, as a reading in order would.
TEST(ParallelRead, TetgenFilesReportTheirProblemsInFileOrder) {
    const std::filesystem::path dir = scratch_dir();
    const Mesh original = labelled_cube(3);
    write_mesh(original, dir / "set.ele");
    const std::filesystem::path node = dir / "set.node", ele = dir / "set.ele", face = dir / "set.face";
    const std::string node_extra = node.string() + ":" + std::to_string(line_count(node) + 1) +
                                   ": more nodes than the 64 the header declares";
    const std::string ele_extra = ele.string() + ":" + std::to_string(line_count(ele) + 1) +
                                  ": more elements than the 162 the header declares";
    const std::string face_extra = face.string() + ":" + std::to_string(line_count(face) + 1) +
                                   ": more faces than the 108 the header declares";
    append_line(face, "999 1 2 3 4");
    for (int threads : thread_counts) EXPECT_EQ(read_error(ele, threads), face_extra) << threads;
    append_line(ele, "999 1 2 3 4");
    for (int threads : thread_counts) EXPECT_EQ(read_error(ele, threads), ele_extra) << threads;
    append_line(node, "999 1 2 3");
    for (int threads : thread_counts) EXPECT_EQ(read_error(ele, threads), node_extra) << threads;
}

}  // namespace
}  // namespace sxk
