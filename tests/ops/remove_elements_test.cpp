// remove_elements (sxk/ops/remove_elements.hpp): elements go, labels of faces that went with
// them go, labels of faces that stay stay; refusals leave the mesh as it was.
#include <gtest/gtest.h>

#include "core/fixtures.hpp"
#include "sxk/edit_journal.hpp"
#include "sxk/ops/dissect.hpp"
#include "sxk/ops/remove_elements.hpp"
#include "sxk/traversal.hpp"

namespace sxk::test {
namespace {

TEST(RemoveElements, ALoosePieceGoesWithItsLabels) {
    Mesh mesh = kuhn_cube(2);
    // cut off the layer z < 1 along the grid plane z = 1, labelled by the dissection
    std::vector<Simplex> plane;
    std::vector<ElementId> below;
    for (const ElementId t : elements(mesh)) {
        bool low = true;
        for (const VertexId v : mesh.simplex(t).vertices()) low = low && mesh.reference(v)[2] <= 1;
        if (low) below.push_back(t);
        for (int i = 0; i < 4; ++i) {
            const Simplex face = mesh.simplex(t).subn(i);
            bool on_plane = true;
            for (const VertexId v : face.vertices()) on_plane = on_plane && mesh.reference(v)[2] == 1;
            if (on_plane && mesh.mate(mesh.face(t, i)) != invalid_id) plane.push_back(face);
        }
    }
    ASSERT_TRUE(dissect(mesh, plane));
    const std::size_t labels = mesh.face_labels().size();
    ASSERT_EQ(labels, 16u);  // 8 faces, both sides
    ASSERT_TRUE(remove_elements(mesh, below));
    EXPECT_EQ(mesh.face_labels().size(), 8u);  // the upper side's stay
    EXPECT_EQ(mesh.element_count(), 48u - below.size());
    ASSERT_TRUE(mesh.validate({.orientation = true}));
}

TEST(RemoveElements, AFaceAnotherElementStillHasKeepsItsLabel) {
    Mesh mesh = kuhn_cube(1);
    const ElementId t{0};
    const Simplex shared = [&] {
        for (int i = 0; i < 4; ++i)
            if (mesh.mate(mesh.face(t, i)) != invalid_id) return Simplex(+1, mesh.simplex(t).subn(i).vertices());
        return Simplex{};
    }();
    const Simplex own = [&] {
        for (int i = 0; i < 4; ++i)
            if (mesh.mate(mesh.face(t, i)) == invalid_id) return Simplex(+1, mesh.simplex(t).subn(i).vertices());
        return Simplex{};
    }();
    mesh.set_face_label(shared, 3);
    mesh.set_face_label(own, 4);
    const std::array<ElementId, 1> doomed{t};
    ASSERT_TRUE(remove_elements(mesh, doomed));
    EXPECT_EQ(mesh.face_label(shared), 3);
    EXPECT_FALSE(mesh.face_label(own));
    ASSERT_TRUE(mesh.validate({.orientation = true}));
}

TEST(RemoveElements, ARefusalLeavesTheMeshAsItWas) {
    const Mesh original = kuhn_cube(2);
    Mesh mesh = original;
    const std::array<ElementId, 1> unknown{ElementId{999}};
    const auto refused = remove_elements(mesh, unknown);
    ASSERT_FALSE(refused);
    EXPECT_EQ(refused.reason(), mesh.replace_elements(unknown, {}).reason());
    expect_same_state(mesh, original);
}

TEST(RemoveElements, ARollbackPutsTheLabelsBack) {
    const Mesh original = [] {
        Mesh m = kuhn_cube(1);
        for (int i = 0; i < 4; ++i) m.set_face_label(Simplex(+1, m.simplex(ElementId{0}).subn(i).vertices()), 7);
        return m;
    }();
    Mesh mesh = original;
    {
        EditJournal journal(mesh);
        EditStep step(journal);
        const std::array<ElementId, 1> doomed{ElementId{0}};
        ASSERT_TRUE(remove_elements(mesh, doomed));
    }  // not committed: rolled back
    expect_same_state(mesh, original);
    ASSERT_TRUE(mesh.validate({.orientation = true}));
}

}  // namespace
}  // namespace sxk::test
