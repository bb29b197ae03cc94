// The snap cutter's session (plugins/snapcut/snap_cut.hpp): cuts on the thesis' cube, undo,
// refusals. Every cut ends with validate().
#include <gtest/gtest.h>

#include "snapcut_fixture.hpp"
#include "sxk/traversal.hpp"

namespace sxk::test {
namespace {

std::size_t faces_with_label(const Mesh& mesh, int label) {
    std::size_t count = 0;
    mesh.for_each_boundary_face([&](FaceId f) {
        const Simplex s = mesh.face_simplex(f);
        count += mesh.face_label(s) == label;
    });
    return count;
}

TEST(SnapCut, APlaneAlongTheGridOpensTheGridFacesItCrosses) {
    Mesh mesh = make_kuhn_cube(8).value();
    auto session = snapcut::SnapCutSession::make(mesh, {}, {degeneracy_service()}).value();
    // the blade stands in x = 3.3 from z = 4 to above the cube, and crosses it along y
    for (const snapcut::Scalpel& scalpel : straight_path({3.3, -1, 0}, {0, 1, 0}, 10, 4, 10, 10)) {
        ASSERT_TRUE(session->cut(scalpel));
        const auto& r = session->last_step();
        std::printf("edges %zu selected %zu dissected %zu snapped %zu incomplete %zu labelled %zu\n", r.edges_hit,
                    r.faces_selected, r.faces_dissected, r.nodes_snapped, r.incomplete, faces_with_label(mesh, 9999));
    }
    ASSERT_TRUE(mesh.validate({.orientation = true}));
    // the faces in x = 3 above z = 4: 8 x 4 squares of 2 triangles, both sides labelled
    EXPECT_EQ(faces_with_label(mesh, snapcut::Options{}.cut_label), 2u * 64u);
}

}  // namespace
}  // namespace sxk::test
