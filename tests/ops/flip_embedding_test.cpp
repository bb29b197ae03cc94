// TetFlipOptions::reference_is_embedding: on an embedded mesh the flips must behave exactly as
// with the search for an existing edge or triangle (the orientation tests prove it absent), and
// topology-only flips must keep searching.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <random>
#include <string>

#include "ops/tet_flip_fixtures.hpp"
#include "sxk/ops/flip_23.hpp"
#include "sxk/ops/flip_32.hpp"
#include "sxk/ops/flip_44.hpp"
#include "sxk/traversal.hpp"

namespace sxk {
namespace {

using test::expect_same_state;

// Same operations on two copies of a jittered Kuhn cube, one searching (default options), one
// trusting the embedding: every flip is accepted by both or refused by both, and after an
// accepted flip the two meshes are identical. The reference positions of jittered_kuhn_cube
// embed the mesh (positive tetrahedra, a simple boundary); the deformed ones are jittered more
// (the option is about the reference positions only).
TEST(FlipEmbedding, TrustingTheEmbeddingChangesNoOutcome) {
    const std::uint64_t seed = test::seed_for("FlipEmbedding.TrustingTheEmbeddingChangesNoOutcome");
    SCOPED_TRACE("SXK_SEED=" + std::to_string(seed));
    std::mt19937_64 random(seed);
    Mesh searching = test::jittered_kuhn_cube(3, random);
    ASSERT_TRUE(test::all_positive(searching));
    Mesh trusting = searching;
    TetFlipOptions trust;
    trust.reference_is_embedding = true;

    int accepted[3] = {0, 0, 0};
    int refused = 0;
    for (int attempt = 0; attempt < 6000; ++attempt) {
        const int kind = static_cast<int>(random() % 3);
        std::uniform_int_distribution<std::uint32_t> pick(0, static_cast<ElementId>(searching.element_capacity() - 1));
        ElementId t = pick(random);
        while (!searching.is_element(t)) t = pick(random);
        const FaceId entry = searching.face(t, static_cast<int>(random() % 4));
        const int j = static_cast<int>(random() % 3);
        const int diagonal = static_cast<int>(random() % 2);
        bool ok_searching = false, ok_trusting = false;
        if (kind == 0) {
            ok_searching = flip_23(searching, entry).ok();
            ok_trusting = flip_23(trusting, entry, trust).ok();
        } else if (kind == 1) {
            ok_searching = flip_32(searching, entry, j).ok();
            ok_trusting = flip_32(trusting, entry, j, trust).ok();
        } else {
            ok_searching = flip_44(searching, entry, j, diagonal).ok();
            ok_trusting = flip_44(trusting, entry, j, diagonal, trust).ok();
        }
        ASSERT_EQ(ok_searching, ok_trusting) << "attempt " << attempt << " kind " << kind;
        if (ok_searching) {
            ++accepted[kind];
        } else {
            ++refused;
        }
        expect_same_state(searching, trusting);
        if (::testing::Test::HasFailure()) FAIL() << "attempt " << attempt;
    }
    std::cout << "[ flips    ] 2-3: " << accepted[0] << ", 3-2: " << accepted[1]
              << ", 4-4: " << accepted[2] << ", refused: " << refused << "\n";
    EXPECT_GT(accepted[0], 0);
    EXPECT_GT(accepted[1], 0);
    ASSERT_TRUE(trusting.validate().ok()) << trusting.validate().reason();
    ASSERT_TRUE(test::all_positive(trusting));
}

// Without geometry there is no proof: a topology-only flip searches even when told to trust
// the embedding (thesis Fig. 5.9 in 3D, as in Flip23.RefusesAnExistingEdge).
TEST(FlipEmbedding, TopologyOnlyFlipsStillSearch) {
    Mesh mesh = test::two_tets();
    ASSERT_TRUE(flip_23(mesh, test::shared_face(mesh)).ok());
    const Mesh before = mesh;
    const FaceId inner = test::interior_face_with(mesh, Simplex(+1, {0, 1, 4}));
    ASSERT_NE(inner, invalid_id);
    TetFlipOptions options;
    options.topology_only = true;
    options.reference_is_embedding = true;
    const auto result = flip_23(mesh, inner, options);
    ASSERT_FALSE(result.ok());
    EXPECT_EQ(result.reason(), "flip_23: edge +<2,3> already exists");
    EXPECT_EQ(result.code(), RefusalCode::not_manifold);
    expect_same_state(mesh, before);
    ASSERT_TRUE(mesh.validate().ok());
}

}  // namespace
}  // namespace sxk
