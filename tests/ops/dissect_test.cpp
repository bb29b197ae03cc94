#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <random>
#include <set>
#include <vector>

#include <filesystem>

#include "core/fixtures.hpp"
#include "sxk/components.hpp"
#include "sxk/generators.hpp"
#include "sxk/io.hpp"
#include "sxk/ops/dissect.hpp"
#include "sxk/ops/split_edge.hpp"
#include "sxk/ops/split_face.hpp"

namespace sxk {
namespace {

using test::CountingWatcher;
using test::expect_same_state;

// The faces of each element as a set: a substituted simplex re-sorts its vertices, so a face
// may move to another slot (invariant 7.1), but it stays in its element with its FaceId.
std::vector<std::vector<FaceId>> all_faces(const Mesh& mesh) {
    std::vector<std::vector<FaceId>> faces;
    for (ElementId t : elements(mesh)) {
        faces.emplace_back(mesh.faces(t).begin(), mesh.faces(t).end());
        std::sort(faces.back().begin(), faces.back().end());
    }
    return faces;
}

std::vector<ElementId> all_elements(const Mesh& mesh) {
    std::vector<ElementId> ids;
    for (ElementId t : elements(mesh)) ids.push_back(t);
    return ids;
}

// Dissection edits without the kernel's star walks (ProvenEdit::change, core/src/mesh_checks.hpp):
// its proof that no face is represented twice and no star is pinched is held here against
// validate on random cut sets, boundary faces among them, one dissection after another on the
// same mesh (a Kuhn cube, a Delaunay mesh of random points and a planar grid).
TEST(Dissect, RandomCutSetsOneAfterAnotherLeaveAValidMesh) {
    const std::uint64_t seed = test::seed_for("Dissect.RandomCutSetsOneAfterAnotherLeaveAValidMesh");
    std::mt19937_64 random(seed);
    std::uniform_real_distribution<double> unit(0, 1);
    std::vector<Point> points(300);
    for (Point& p : points) p = {unit(random), unit(random), unit(random)};
    std::vector<Mesh> meshes;
    meshes.push_back(test::kuhn_cube(4));
    meshes.push_back(make_delaunay(points).value());
    meshes.push_back(test::planar_grid(8));
    for (Mesh& mesh : meshes) {
        std::size_t opened = 0;
        for (int round = 0; round < 40; ++round) {
            std::vector<Simplex> faces;
            for (const ElementId t : elements(mesh))
                for (const FaceId f : mesh.faces(t)) faces.push_back(mesh.face_simplex(f));
            std::shuffle(faces.begin(), faces.end(), random);
            std::vector<Simplex> cut(faces.begin(), faces.begin() + 1 + static_cast<std::ptrdiff_t>(unit(random) * 12));
            // every other round also every face at a random vertex in some element: its star falls apart
            if (round % 2 == 1) {
                const VertexId v = faces.back().vertex(0);
                for (const Simplex& sigma : faces)
                    if (sigma.contains(v)) cut.push_back(sigma);
            }
            faces = std::move(cut);
            const auto result = dissect(mesh, faces);
            ASSERT_TRUE(result.ok()) << result.reason() << " (seed " << seed << ")";
            opened += result->opened.size();
            const auto valid = mesh.validate({.orientation = true});
            ASSERT_TRUE(valid.ok()) << "round " << round << ": " << valid.reason() << " (seed " << seed << ")";
        }
        EXPECT_GT(opened, 0u) << "seed " << seed;
    }
}

//   3 ------- 2          3 ------ 2        2'         cut C = {0-2}: both end points have
//   |       / |          |      /         / |         two (v,C)-classes, so 0 and 2 get a
//   |  B  /   |   --->   |  B  /         /  A |       copy each (0' = 4, 2' = 5) and the
//   |   /  A  |          |   /          /     |       square falls into two triangles
//   | /       |          | /           /      |
//   0 ------- 1          0           0' ----- 1
TEST(Dissect, UnitSquareAlongItsDiagonal) {
    Mesh mesh = test::unit_square();
    CountingWatcher watcher;
    mesh.add_watcher(watcher);
    const auto element_ids = all_elements(mesh);
    const auto face_ids = all_faces(mesh);
    const std::size_t boundary_before = mesh.boundary_face_count();

    const std::vector<Simplex> cut{Simplex(+1, {2, 0})};
    const auto result = dissect(mesh, cut);
    ASSERT_TRUE(result.ok()) << result.reason();
    ASSERT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
    EXPECT_EQ(result->new_vertices.size(), 2u);
    EXPECT_EQ(mesh.vertex_count(), 6u);
    for (const auto& [original, copy] : result->new_vertices) {
        EXPECT_EQ(mesh.reference(copy), mesh.reference(original));
        EXPECT_EQ(mesh.deformed(copy), mesh.deformed(original));
    }
    EXPECT_EQ(result->new_vertices[0].first, 0u);
    EXPECT_EQ(result->new_vertices[1].first, 2u);
    EXPECT_EQ(mesh.boundary_face_count(), boundary_before + 2);
    EXPECT_EQ(all_elements(mesh), element_ids);
    EXPECT_EQ(all_faces(mesh), face_ids);
    EXPECT_EQ(connected_components(mesh).count, 2u);
    // one element changed (the class with the larger element id), two faces join the boundary
    EXPECT_EQ(watcher.changed, 1);
    EXPECT_EQ(watcher.removed + watcher.added, 0);
    EXPECT_EQ(watcher.boundary_added_count, 2);
    watcher.expect_in_step_with(mesh);
}

// Fig. 7.7: the interior edge (1,1)-(2,1) of a 4 x 4 grid cut on its own separates nothing:
// the rings around both end points stay joined through their other edges.
TEST(Dissect, NonSeparatingFaceStaysJoined) {
    Mesh mesh = test::planar_grid(4);
    CountingWatcher watcher;
    mesh.add_watcher(watcher);
    const Mesh before = mesh;
    const std::vector<Simplex> cut{Simplex(+1, {6, 7})};
    const auto result = dissect(mesh, cut);
    ASSERT_TRUE(result.ok()) << result.reason();
    ASSERT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
    EXPECT_TRUE(result->new_vertices.empty());
    EXPECT_EQ(mesh.boundary_face_count(), before.boundary_face_count());
    expect_same_state(mesh, before);
    EXPECT_EQ(watcher.changed, 0);
    watcher.expect_in_step_with(mesh);
}

// A 4 x 4 grid cut along the whole line x = 2 (vertices 2, 7, 12, 17, 22): two halves.
TEST(Dissect, PlanarGridAlongAGridLine) {
    Mesh mesh = test::planar_grid(4);
    CountingWatcher watcher;
    mesh.add_watcher(watcher);
    const std::size_t boundary_before = mesh.boundary_face_count();
    std::vector<Simplex> cut;
    for (VertexId j = 0; j < 4; ++j) cut.push_back(Simplex(+1, {2 + 5 * j, 2 + 5 * (j + 1)}));
    const auto result = dissect(mesh, cut);
    ASSERT_TRUE(result.ok()) << result.reason();
    ASSERT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
    EXPECT_EQ(result->new_vertices.size(), 5u);
    EXPECT_EQ(mesh.boundary_face_count(), boundary_before + 8);
    const Components components = connected_components(mesh);
    EXPECT_EQ(components.count, 2u);
    EXPECT_EQ(watcher.boundary_added_count, 8);
    watcher.expect_in_step_with(mesh);
}

// kuhn_cube(2) cut along the plane x = 1: the 9 vertices of the plane get one copy each.
TEST(Dissect, KuhnCubeAlongAPlane) {
    Mesh mesh = test::kuhn_cube(2);
    CountingWatcher watcher;
    mesh.add_watcher(watcher);
    const auto face_ids = all_faces(mesh);
    std::vector<Simplex> cut;
    for (ElementId t : elements(mesh))
        for (FaceId f : mesh.faces(t)) {
            if (mesh.mate(f) == invalid_id) continue;
            const Simplex sigma = mesh.face_simplex(f);
            bool on_plane = true;
            for (VertexId v : sigma.vertices()) on_plane = on_plane && mesh.reference(v)[0] == 1.0;
            if (on_plane) cut.push_back(sigma);  // both orientations: a face counts with its mate
        }
    ASSERT_EQ(cut.size(), 16u);  // 4 unit squares of 2 triangles, seen from both sides
    const std::size_t boundary_before = mesh.boundary_face_count();
    const auto result = dissect(mesh, cut);
    ASSERT_TRUE(result.ok()) << result.reason();
    ASSERT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
    EXPECT_EQ(result->new_vertices.size(), 9u);
    EXPECT_EQ(connected_components(mesh).count, 2u);
    EXPECT_EQ(mesh.boundary_face_count(), boundary_before + 16);
    EXPECT_EQ(all_faces(mesh), face_ids);
    EXPECT_EQ(watcher.boundary_added_count, 16);
    watcher.expect_in_step_with(mesh);
}

TEST(Dissect, RefusesAFaceOfTheWrongSize) {
    Mesh mesh = test::unit_square();
    const Mesh before = mesh;
    const std::vector<Simplex> cut{Simplex(+1, {0, 2}), Simplex(+1, {0, 1, 2})};
    const auto result = dissect(mesh, cut);
    ASSERT_FALSE(result.ok());
    EXPECT_EQ(result.reason(), "dissect: cut face 1 has 3 vertices, not 2");
    EXPECT_EQ(result.code(), RefusalCode::bad_argument);
    EXPECT_EQ(result.refusal().item, 1u);
    expect_same_state(mesh, before);
}

TEST(Dissect, RefusesAFaceNotInTheMesh) {
    Mesh mesh = test::unit_square();
    const Mesh before = mesh;
    const std::vector<Simplex> cut{Simplex(+1, {1, 3})};
    const auto result = dissect(mesh, cut);
    ASSERT_FALSE(result.ok());
    EXPECT_EQ(result.reason(), "dissect: cut face 0 +<1,3> is not a face of the mesh");
    EXPECT_EQ(result.code(), RefusalCode::not_found);
    expect_same_state(mesh, before);
}

TEST(Dissect, RefusesAnUnknownVertex) {
    Mesh mesh = test::unit_square();
    const Mesh before = mesh;
    const std::vector<Simplex> cut{Simplex(+1, {0, 9})};
    const auto result = dissect(mesh, cut);
    ASSERT_FALSE(result.ok());
    EXPECT_EQ(result.reason(), "dissect: cut face 0 +<0,9> has a repeated or unknown vertex");
    EXPECT_EQ(result.code(), RefusalCode::bad_argument);
    expect_same_state(mesh, before);
}


// The copies made by dissect take ALL of their original's data: both positions and every
// vertex attribute, bit for bit; element labels (two materials) do not change.
TEST(Dissect, CopiesCarryEveryAttributeAndLabelsStay) {
    Mesh mesh = test::unit_square();
    mesh.set_label(0, 7);
    mesh.set_label(1, 9);
    const AttributeId velocity = *mesh.add_vertex_attribute("velocity", 3);
    const AttributeId temperature = *mesh.add_vertex_attribute("temperature", 1);
    for (VertexId v = 0; v < 4; ++v) {
        for (std::size_t k = 0; k < 3; ++k) mesh.vertex_attribute(velocity, v)[k] = 0.1 * v + 0.01 * static_cast<double>(k);
        mesh.vertex_attribute(temperature, v)[0] = -0.0 - 3.0 * v;
    }
    mesh.set_deformed(2, {1.5, 1.25, 0});
    const std::vector<Simplex> cut{Simplex(+1, {2, 0})};
    const auto result = dissect(mesh, cut);
    ASSERT_TRUE(result.ok()) << result.reason();
    ASSERT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
    ASSERT_EQ(result->new_vertices.size(), 2u);
    for (const auto& [original, copy] : result->new_vertices) {
        EXPECT_EQ(mesh.deformed(copy), mesh.deformed(original));
        for (const AttributeId a : {velocity, temperature}) {
            const auto from = mesh.vertex_attribute(a, original);
            const auto to = mesh.vertex_attribute(a, copy);
            ASSERT_EQ(from.size(), to.size());
            for (std::size_t k = 0; k < from.size(); ++k)
                EXPECT_EQ(std::bit_cast<std::uint64_t>(to[k]), std::bit_cast<std::uint64_t>(from[k]));
        }
    }
    EXPECT_EQ(mesh.label(0), 7);
    EXPECT_EQ(mesh.label(1), 9);
}

// Face labels under dissect: cutting the unit square along its labelled diagonal 0-2 labels
// both boundary edges it becomes (0-2 and its copy 4-5); B = <0,2,3> gets the copies, so the
// label on its edge 2-3 moves to 5-3, and the label on A's 1-2 stays.
TEST(Dissect, FaceLabelsFollowTheCopies) {
    Mesh mesh = test::unit_square();
    mesh.face_labels()[Simplex(+1, {0, 2})] = 8;
    mesh.face_labels()[Simplex(+1, {2, 3})] = 9;
    mesh.face_labels()[Simplex(+1, {1, 2})] = 7;
    const std::vector<Simplex> cut{Simplex(+1, {0, 2})};
    const auto result = dissect(mesh, cut);
    ASSERT_TRUE(result.ok()) << result.reason();
    ASSERT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
    // element 0 = A keeps 0 and 2; B gets the copies 4 (of 0) and 5 (of 2)
    EXPECT_EQ(mesh.simplex(1).vertices()[0], 3u);
    EXPECT_EQ(mesh.face_labels(), (FaceLabels{{Simplex(+1, {0, 2}), 8}, {Simplex(+1, {4, 5}), 8},
                                              {Simplex(+1, {3, 5}), 9}, {Simplex(+1, {1, 2}), 7}}));
}

// The cut mark: the faces a dissection opens carry default_cut_label (both sides), are listed in
// `opened`, keep the label through a later split of one of them and are in a Medit file.
TEST(Dissect, OpenedFacesCarryTheCutLabelThroughLaterEditsAndFiles) {
    Mesh mesh = test::planar_grid(4);
    std::vector<Simplex> cut;
    for (VertexId j = 0; j < 4; ++j) cut.push_back(Simplex(+1, {2 + 5 * j, 2 + 5 * (j + 1)}));
    const std::vector<FaceId> boundary_before = mesh.boundary_faces();
    const auto result = dissect(mesh, cut);
    ASSERT_TRUE(result.ok()) << result.reason();
    ASSERT_EQ(result->opened.size(), 8u);
    EXPECT_TRUE(std::is_sorted(result->opened.begin(), result->opened.end()));
    FaceLabels expected;
    for (const FaceId f : result->opened) {
        EXPECT_EQ(mesh.mate(f), invalid_id);
        EXPECT_FALSE(std::binary_search(boundary_before.begin(), boundary_before.end(), f));
        expected[Simplex(+1, mesh.face_simplex(f).vertices())] = default_cut_label;
    }
    EXPECT_EQ(expected.size(), 8u);  // the two sides have different vertex sets
    EXPECT_EQ(mesh.face_labels(), expected);
    ASSERT_TRUE(mesh.validate().ok()) << mesh.validate().reason();

    // splitting an opened edge passes the mark to both halves
    const Simplex first = mesh.face_simplex(result->opened[0]);
    const auto split = split_edge(mesh, first.vertex(0), first.vertex(1));
    ASSERT_TRUE(split.ok()) << split.reason();
    EXPECT_FALSE(mesh.face_label(first));
    EXPECT_EQ(mesh.face_label(Simplex(+1, {first.vertex(0), split->vertex})), default_cut_label);
    EXPECT_EQ(mesh.face_label(Simplex(+1, {first.vertex(1), split->vertex})), default_cut_label);
    ASSERT_TRUE(mesh.validate().ok()) << mesh.validate().reason();

    const std::filesystem::path file = std::filesystem::path(SXK_BINARY_DIR) / "dissect-cut-label.mesh";
    write_mesh(mesh, file);
    const Mesh back = read_mesh(file);
    EXPECT_EQ(back.face_labels(), mesh.face_labels());
    std::filesystem::remove(file);
}

TEST(Dissect, ALabelledCutFaceKeepsItsLabelAndTheMarkCanBeLeftOut) {
    Mesh labelled = test::unit_square();
    labelled.face_labels()[Simplex(+1, {0, 2})] = 8;
    const std::vector<Simplex> cut{Simplex(+1, {0, 2})};
    const auto kept = dissect(labelled, cut);
    ASSERT_TRUE(kept.ok()) << kept.reason();
    EXPECT_EQ(kept->opened.size(), 2u);
    EXPECT_EQ(labelled.face_labels(), (FaceLabels{{Simplex(+1, {0, 2}), 8}, {Simplex(+1, {4, 5}), 8}}));

    Mesh other = test::unit_square();
    const auto custom = dissect(other, cut, DissectOptions{42});
    ASSERT_TRUE(custom.ok()) << custom.reason();
    EXPECT_EQ(other.face_labels(), (FaceLabels{{Simplex(+1, {0, 2}), 42}, {Simplex(+1, {4, 5}), 42}}));

    Mesh plain = test::unit_square();
    const auto unmarked = dissect(plain, cut, DissectOptions{std::nullopt});
    ASSERT_TRUE(unmarked.ok()) << unmarked.reason();
    EXPECT_EQ(unmarked->opened.size(), 2u);
    EXPECT_TRUE(plain.face_labels().empty());
    ASSERT_TRUE(plain.validate().ok());
}

// 3D: the 8 triangles of the plane x = 1 open into 16 marked boundary faces, and a split of a
// marked triangle marks its two pieces.
TEST(Dissect, KuhnCubeCutFacesAreMarkedOnBothSides) {
    Mesh mesh = test::kuhn_cube(2);
    std::vector<Simplex> cut;
    for (ElementId t : elements(mesh))
        for (int j = 0; j < 4; ++j) {
            const Simplex sigma = mesh.simplex(t).subn(j);
            bool on_plane = true;
            for (VertexId v : sigma.vertices()) on_plane = on_plane && mesh.reference(v)[0] == 1.0;
            if (on_plane) cut.push_back(sigma);
        }
    const auto result = dissect(mesh, cut);
    ASSERT_TRUE(result.ok()) << result.reason();
    EXPECT_EQ(result->opened.size(), 16u);
    EXPECT_EQ(mesh.face_labels().size(), 16u);
    for (const FaceId f : result->opened)
        EXPECT_EQ(mesh.face_label(mesh.face_simplex(f)), default_cut_label);
    const Simplex marked = mesh.face_simplex(result->opened.back());
    const std::array<double, 3> middle{1, 1, 1};
    const auto split = split_face(mesh, result->opened.back(), middle);
    ASSERT_TRUE(split.ok()) << split.reason();
    EXPECT_FALSE(mesh.face_label(marked));
    EXPECT_EQ(mesh.face_labels().size(), 18u);  // one marked triangle became three
    ASSERT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
}

}  // namespace
}  // namespace sxk
