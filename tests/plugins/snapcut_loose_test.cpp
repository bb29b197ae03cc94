// Loose pieces (plugins/snapcut/loose_pieces.hpp: find_loose_pieces) on the 3 x 3 x 3 Kuhn
// cube: a tetrahedron of the centre cell cut out on all four faces is a piece that came loose,
// however the step's cut pairs reach the seeds around it.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "loose_pieces.hpp"
#include "snapcut_fixture.hpp"
#include "sxk/generators.hpp"
#include "sxk/ops/dissect.hpp"
#include "sxk/traversal.hpp"

namespace sxk::test {
namespace {

// The cube with a tetrahedron of its centre cell (all four faces interior) dissected on all four
// faces: `inside` is that tetrahedron; `near` and `far` are elements of the rest at the cube's
// opposite corners (they share no vertex, so the seeds around them are two groups).
struct CutOut {
    Mesh mesh;
    ElementId inside = invalid_id, near = invalid_id, far = invalid_id;
};

CutOut cut_out_a_centre_tetrahedron() {
    CutOut result{make_kuhn_cube(3).value()};
    Mesh& mesh = result.mesh;
    for (const ElementId t : elements(mesh)) {
        bool interior = true;
        for (int i = 0; i < 4; ++i) interior = interior && mesh.mate(mesh.face(t, i)) != invalid_id;
        const Simplex s = mesh.simplex(t);
        const bool centre = std::all_of(s.vertices().begin(), s.vertices().end(), [&](VertexId v) {
            const Point p = mesh.reference(v);
            return p[0] >= 1 && p[0] <= 2 && p[1] >= 1 && p[1] <= 2 && p[2] >= 1 && p[2] <= 2;
        });
        if (interior && centre && result.inside == invalid_id) result.inside = t;
        const Point first = mesh.reference(s.vertex(0));
        if (first[0] == 0 && first[1] == 0 && first[2] == 0 && result.near == invalid_id) result.near = t;
        const bool at_far_corner = std::any_of(s.vertices().begin(), s.vertices().end(), [&](VertexId v) {
            const Point p = mesh.reference(v);
            return p[0] == 3 && p[1] == 3 && p[2] == 3;
        });
        if (at_far_corner && result.far == invalid_id) result.far = t;
    }
    std::vector<Simplex> faces;
    for (int i = 0; i < 4; ++i) faces.push_back(mesh.face_simplex(mesh.face(result.inside, i)));
    const auto dissected = dissect(mesh, faces);
    EXPECT_TRUE(dissected) << dissected.reason();
    expect_valid(mesh);
    return result;
}

// The seeds round the tetrahedron are reached by no cut pair: the pairs of the step reach only
// the seeds at the corners (a degeneracy removal can do that: it may cut free the elements that
// held a piece on, and make no copy; a random through cut of the femur, SXK_SEED=3289562137
// cut 5, so left 5 elements floating as a third piece). The pairs reach one body, so the
// unreached seeds lie on it and race it.
TEST(SnapCutLoose, SeedsNoCutPairReachesRaceTheOneBodyThePairsReach) {
    const CutOut cut = cut_out_a_centre_tetrahedron();
    ASSERT_NE(cut.inside, invalid_id);
    ASSERT_NE(cut.near, invalid_id);
    ASSERT_NE(cut.far, invalid_id);
    const Mesh& mesh = cut.mesh;
    const std::vector<ElementId> seeds{cut.near, cut.far, cut.inside};
    // a pair from a corner of `near` to a corner of `far`: one body, as a dissection's pair says
    const std::vector<std::pair<VertexId, VertexId>> pairs{{mesh.simplex(cut.near).vertex(0), mesh.simplex(cut.far).vertex(0)}};
    const snapcut::LoosePieces loose = snapcut::find_loose_pieces(mesh, seeds, pairs);
    ASSERT_EQ(loose.pieces.size(), 1u);
    EXPECT_EQ(loose.pieces[0], std::vector<ElementId>{cut.inside});
    // with no pair at all every seed is on one body: the same piece
    const snapcut::LoosePieces unpaired = snapcut::find_loose_pieces(mesh, seeds, {});
    ASSERT_EQ(unpaired.pieces.size(), 1u);
    EXPECT_EQ(unpaired.pieces[0], std::vector<ElementId>{cut.inside});
}

// Without the tetrahedron's seed there is nothing loose to find: the two corners' searches meet.
TEST(SnapCutLoose, TheSeedsOfOneComponentFindNothingLoose) {
    const CutOut cut = cut_out_a_centre_tetrahedron();
    const Mesh& mesh = cut.mesh;
    const std::vector<ElementId> seeds{cut.near, cut.far};
    const std::vector<std::pair<VertexId, VertexId>> pairs{{mesh.simplex(cut.near).vertex(0), mesh.simplex(cut.far).vertex(0)}};
    EXPECT_TRUE(snapcut::find_loose_pieces(mesh, seeds, pairs).pieces.empty());
}

}  // namespace
}  // namespace sxk::test
