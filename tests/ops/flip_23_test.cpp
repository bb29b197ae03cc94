#include <gtest/gtest.h>

#include <iostream>
#include <sstream>
#include <random>

#include "ops/tet_flip_fixtures.hpp"
#include "sxk/ops/flip_23.hpp"
#include "sxk/ops/flip_32.hpp"

namespace sxk {
namespace {

using test::CountingWatcher;
using test::expect_same_state;

//                 0                                0
//                /|\  p                           /|\    three tetrahedra around the
//     (0,1,0) 2 / | \ 1 (1,0,0)      --->      2 / | \ 1  new edge 0-4; the hull (six
//              \  |  /                            \ | /    triangles) keeps its FaceIds
//               3 (-1,-1,0)                         3|
//                 |  q                               |
//                 4                                  4
TEST(Flip23, TwoTetsBecomeThreeAroundTheNewEdgeAndBack) {
    Mesh mesh = test::two_tets();
    CountingWatcher watcher;
    mesh.add_watcher(watcher);
    const std::vector<FaceId> hull = mesh.boundary_faces();
    const auto before_sets = test::vertex_sets(mesh);

    const auto three = flip_23(mesh, test::shared_face(mesh));
    ASSERT_TRUE(three.ok()) << three.reason();
    ASSERT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
    EXPECT_EQ(mesh.element_count(), 3u);
    EXPECT_TRUE(test::all_positive(mesh));
    EXPECT_EQ(mesh.boundary_faces(), hull);
    for (ElementId t : *three) {
        EXPECT_TRUE(mesh.simplex(t).contains(0));
        EXPECT_TRUE(mesh.simplex(t).contains(4));
    }
    // watchers: exactly two removed, three added, nothing on the boundary
    EXPECT_EQ(watcher.removed, 2);
    EXPECT_EQ(watcher.added, 3);
    EXPECT_EQ(watcher.changed, 0);
    EXPECT_EQ(watcher.boundary_added_count + watcher.boundary_removed_count +
                  watcher.boundary_changed_count,
              0);
    watcher.expect_in_step_with(mesh);

    // inverse identity: flip_32 on the new edge 0-4 restores the vertex sets and hull ids
    watcher.reset_counts();
    const auto [entry, j] = test::edge_entry(mesh, 0, 4);
    ASSERT_NE(entry, invalid_id);
    const auto two = flip_32(mesh, entry, j);
    ASSERT_TRUE(two.ok()) << two.reason();
    ASSERT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
    EXPECT_EQ(test::vertex_sets(mesh), before_sets);
    // first the tetrahedron containing a = 0, then the one containing b = 4, as before
    EXPECT_EQ(mesh.simplex((*two)[0]), Simplex(+1, {1, 2, 3, 0}));
    EXPECT_EQ(mesh.simplex((*two)[1]), Simplex(-1, {1, 2, 3, 4}));
    EXPECT_EQ(mesh.boundary_faces(), hull);
    EXPECT_TRUE(test::all_positive(mesh));
    EXPECT_EQ(watcher.removed, 3);
    EXPECT_EQ(watcher.added, 2);
    EXPECT_EQ(watcher.boundary_added_count + watcher.boundary_removed_count +
                  watcher.boundary_changed_count,
              0);
    watcher.expect_in_step_with(mesh);
}

TEST(Flip23, RefusesABoundaryFace) {
    Mesh mesh = test::two_tets();
    const Mesh before = mesh;
    const FaceId hull_face = mesh.boundary_faces().front();
    const auto result = flip_23(mesh, hull_face);
    ASSERT_FALSE(result.ok());
    EXPECT_EQ(result.reason(), "flip_23: face " + std::to_string(hull_face) + " " +
                                   [&] {
                                       std::ostringstream out;
                                       out << mesh.face_simplex(hull_face);
                                       return out.str();
                                   }() +
                                   " is on the boundary");
    EXPECT_EQ(result.code(), RefusalCode::not_applicable);
    expect_same_state(mesh, before);
    ASSERT_TRUE(mesh.validate().ok());
}

// q moved to (2,2,-1): the segment 0-q meets z = 0 at (1,1), outside triangle 1,2,3, so one of
// the three new tetrahedra would be inverted.
TEST(Flip23, RefusesANonConvexPair) {
    Mesh mesh = test::two_tets({2, 2, -1});
    ASSERT_TRUE(test::all_positive(mesh));
    CountingWatcher watcher;
    mesh.add_watcher(watcher);
    const Mesh before = mesh;
    const auto result = flip_23(mesh, test::shared_face(mesh));
    ASSERT_FALSE(result.ok());
    EXPECT_EQ(result.reason(),
              "flip_23: new tetrahedron -<0,1,2,4> would be inverted in the reference positions");
    EXPECT_EQ(result.code(), RefusalCode::would_invert);
    expect_same_state(mesh, before);
    EXPECT_EQ(watcher.removed + watcher.added, 0);
    ASSERT_TRUE(mesh.validate().ok());

    // topology_only skips the geometric test: the flip goes through (and is inverted)
    const auto forced = flip_23(mesh, test::shared_face(mesh), {.topology_only = true});
    ASSERT_TRUE(forced.ok()) << forced.reason();
    ASSERT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
    EXPECT_FALSE(test::all_positive(mesh));
}

TEST(Flip23, RefusesWhenOnlyTheDeformedPairIsNonConvex) {
    Mesh mesh = test::two_tets();
    mesh.set_deformed(4, {2, 2, -1});
    const Mesh before = mesh;
    const auto result = flip_23(mesh, test::shared_face(mesh));
    ASSERT_FALSE(result.ok());
    EXPECT_EQ(result.reason(),
              "flip_23: new tetrahedron -<0,1,2,4> would be inverted in the deformed positions");
    EXPECT_EQ(result.code(), RefusalCode::would_invert);
    expect_same_state(mesh, before);
    ASSERT_TRUE(mesh.validate().ok());
}

// Thesis Fig. 5.9 in 3D: after the 2-3 flip, the interior face <0,4,1> has apexes 2 and 3,
// whose edge 2-3 is already on the hull: flipping would represent it twice.
TEST(Flip23, RefusesAnExistingEdge) {
    Mesh mesh = test::two_tets();
    ASSERT_TRUE(flip_23(mesh, test::shared_face(mesh)).ok());
    const Mesh before = mesh;
    const FaceId inner = test::interior_face_with(mesh, Simplex(+1, {0, 1, 4}));
    ASSERT_NE(inner, invalid_id);
    const auto result = flip_23(mesh, inner, {.topology_only = true});
    ASSERT_FALSE(result.ok());
    EXPECT_EQ(result.reason(), "flip_23: edge +<2,3> already exists");
    EXPECT_EQ(result.code(), RefusalCode::not_manifold);
    expect_same_state(mesh, before);
    ASSERT_TRUE(mesh.validate().ok());
}

// t0 and t1 of different materials: the 2-3 flip would move the interface triangle 1,2,3.
TEST(Flip23, RefusesAMaterialInterface) {
    Mesh mesh = test::two_tets();
    mesh.set_label(1, 5);
    CountingWatcher watcher;
    mesh.add_watcher(watcher);
    const Mesh before = mesh;
    const auto result = flip_23(mesh, test::shared_face(mesh));
    ASSERT_FALSE(result.ok());
    EXPECT_EQ(result.reason(), "flip_23: elements have different labels (a material interface)");
    EXPECT_EQ(result.code(), RefusalCode::label_conflict);
    expect_same_state(mesh, before);
    EXPECT_EQ(watcher.removed + watcher.added, 0);
    ASSERT_TRUE(mesh.validate().ok());

    mesh.set_label(0, 5);
    const auto three = flip_23(mesh, test::shared_face(mesh));
    ASSERT_TRUE(three.ok()) << three.reason();
    for (ElementId t : *three) EXPECT_EQ(mesh.label(t), 5);
    ASSERT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
}

// The shared triangle carries a face label: the 2-3 flip would remove it, so it is refused.
TEST(Flip23, RefusesALabelledFace) {
    Mesh mesh = test::two_tets();
    const Simplex shared = mesh.face_simplex(test::shared_face(mesh));
    mesh.face_labels()[Simplex(+1, shared.vertices())] = 4;
    ASSERT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
    const Mesh before = mesh;
    const auto result = flip_23(mesh, test::shared_face(mesh));
    ASSERT_FALSE(result.ok());
    EXPECT_EQ(result.reason(), "flip_23: face " + to_text(Simplex(+1, shared.vertices())) +
                                   " carries label 4 (a constraint: an interface or a boundary "
                                   "patch)");
    EXPECT_EQ(result.code(), RefusalCode::label_conflict);
    expect_same_state(mesh, before);
    ASSERT_TRUE(mesh.validate().ok());
}

TEST(Flip23, RefusesATriangleMesh) {
    Mesh mesh = test::unit_square();
    const Mesh before = mesh;
    const auto result = flip_23(mesh, mesh.face(0, 0));
    ASSERT_FALSE(result.ok());
    EXPECT_EQ(result.reason(), "flip_23: needs a tetrahedral mesh");
    EXPECT_EQ(result.code(), RefusalCode::wrong_dimension);
    expect_same_state(mesh, before);
    ASSERT_TRUE(mesh.validate().ok());
}

// Random 2-3 flips on interior faces and 3-2 flips on degree-3 edges of a Kuhn cube whose
// deformed positions are jittered: every accepted flip leaves a valid mesh with every element
// exactly positive in both positions; every refused one leaves the mesh exactly as it was.
TEST(Flip23, RandomTwoThreeAndThreeTwoFlipsOnAJitteredKuhnCube) {
    const std::uint64_t seed = test::seed_for("Flip23.RandomTwoThreeAndThreeTwoFlipsOnAJitteredKuhnCube");
    SCOPED_TRACE("SXK_SEED=" + std::to_string(seed));
    std::mt19937_64 random(seed);
    Mesh mesh = test::jittered_kuhn_cube(3, random);
    ASSERT_TRUE(test::all_positive(mesh));  // jitter well below the unit edge keeps it valid

    int accepted_23 = 0, accepted_32 = 0, refused = 0;
    for (int attempt = 0; attempt < 10000; ++attempt) {
        const Mesh before = mesh;
        bool ok = false;
        if (random() % 2 == 0) {
            // a random interior face
            std::uniform_int_distribution<std::uint32_t> pick(0, static_cast<FaceId>(mesh.face_capacity() - 1));
            FaceId f = pick(random);
            while (!mesh.is_face(f) || mesh.mate(f) == invalid_id) f = pick(random);
            const auto result = flip_23(mesh, f);
            ok = result.ok();
            accepted_23 += ok;
        } else {
            // a random edge of degree 3 (tried a few times; otherwise whatever edge was drawn)
            std::uniform_int_distribution<std::uint32_t> pick(0, static_cast<ElementId>(mesh.element_capacity() - 1));
            FaceId entry = invalid_id;
            int j = 0;
            for (int tries = 0; tries < 40; ++tries) {
                ElementId t = pick(random);
                while (!mesh.is_element(t)) t = pick(random);
                entry = mesh.face(t, static_cast<int>(random() % 4));
                j = static_cast<int>(random() % 3);
                if (cycle_around(mesh, entry, j).size() == 3) break;
            }
            const auto result = flip_32(mesh, entry, j);
            ok = result.ok();
            accepted_32 += ok;
        }
        if (ok) {
            ASSERT_TRUE(mesh.validate().ok()) << "attempt " << attempt << ": " << mesh.validate().reason();
            ASSERT_TRUE(test::all_positive(mesh)) << "attempt " << attempt;
            ASSERT_EQ(mesh.boundary_faces(), before.boundary_faces()) << "attempt " << attempt;
        } else {
            ++refused;
            expect_same_state(mesh, before);
            if (::testing::Test::HasFailure()) FAIL() << "attempt " << attempt;
        }
    }
    std::cout << "[ flips    ] 2-3: " << accepted_23 << ", 3-2: " << accepted_32
              << ", refused: " << refused << "\n";
    EXPECT_GT(accepted_23, 0);
    EXPECT_GT(accepted_32, 0);
    ASSERT_TRUE(mesh.validate().ok());
}

}  // namespace
}  // namespace sxk
