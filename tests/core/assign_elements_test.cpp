#include <gtest/gtest.h>

#include "fixtures.hpp"
#include "sxk/mesh.hpp"

namespace sxk {
namespace {

using test::expect_same_state;
using test::kuhn_cube;
using test::unit_square;

TEST(AssignElements, BuildsMatesAndBoundary) {
    const Mesh mesh = unit_square();
    ASSERT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
    EXPECT_EQ(mesh.element_count(), 2u);
    EXPECT_EQ(mesh.boundary_face_count(), 4u);
    // the diagonal: +<0,2> in <0,1,2>? <0,1,2>.subn(1) = -<0,2>; <0,2,3>.subn(2) = +<0,2>
    const FaceId in_a = mesh.face(0, 1);
    const FaceId in_b = mesh.face(1, 2);
    EXPECT_EQ(mesh.face_simplex(in_a), Simplex(-1, {0, 2}));
    EXPECT_EQ(mesh.mate(in_a), in_b);
    EXPECT_EQ(mesh.mate(in_b), in_a);
    EXPECT_EQ(mesh.neighbor(0, 1), 1u);
    EXPECT_NE(mesh.find_boundary_face(Simplex(+1, {0, 1})), invalid_id);
    EXPECT_EQ(mesh.find_boundary_face(Simplex(-1, {0, 1})), invalid_id);
}

TEST(AssignElements, ThesisCubeHasTheThesisCounts) {
    const Mesh mesh = kuhn_cube(8);
    ASSERT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
    EXPECT_EQ(mesh.vertex_count(), 729u);
    EXPECT_EQ(mesh.element_count(), 3072u);
    // 6 sides x 8 x 8 squares x 2 triangles
    EXPECT_EQ(mesh.boundary_face_count(), 768u);
}

struct BadSoup {
    const char* name;
    std::vector<Simplex> simplexes;
    std::string reason;
    std::size_t item;
    RefusalCode code;
};

class AssignElementsRefuses : public ::testing::TestWithParam<BadSoup> {};

TEST_P(AssignElementsRefuses, WithReasonAndItem) {
    Mesh mesh(3, 3);
    for (int i = 0; i < 6; ++i) mesh.add_vertex({double(i), double(i * i), double(i * i * i)});
    const Mesh before = mesh;
    const auto result = mesh.assign_elements(GetParam().simplexes);
    ASSERT_FALSE(result.ok());
    EXPECT_EQ(result.reason(), GetParam().reason);
    EXPECT_EQ(result.refusal().item, GetParam().item);
    EXPECT_EQ(result.code(), GetParam().code);
    expect_same_state(mesh, before);
    EXPECT_TRUE(mesh.validate().ok());
}

INSTANTIATE_TEST_SUITE_P(
    Soups, AssignElementsRefuses,
    ::testing::Values(BadSoup{"WrongSize",
                              {Simplex(+1, {0, 1, 2, 3}), Simplex(+1, {0, 1, 2})},
                              "element has 3 vertices, expected 4",
                              1,
                              RefusalCode::bad_argument},
                      BadSoup{"UnknownVertex",
                              {Simplex(+1, {0, 1, 2, 9})},
                              "vertex 9 does not exist (the mesh has 6 vertices)",
                              0,
                              RefusalCode::bad_argument},
                      BadSoup{"RepeatedVertex",
                              {Simplex(+1, {0, 1, 1, 2})},
                              "element +<0,1,1,2> repeats a vertex",
                              0,
                              RefusalCode::bad_argument},
                      BadSoup{"Duplicate",
                              {Simplex(+1, {0, 1, 2, 3}), Simplex(+1, {1, 0, 3, 2})},
                              "element 1 repeats element 0 (duplicate element)",
                              1,
                              RefusalCode::not_manifold},
                      BadSoup{"MirrorDuplicate",
                              {Simplex(+1, {0, 1, 2, 3}), Simplex(-1, {0, 1, 2, 3})},
                              "element 1 repeats element 0 (duplicate element)",
                              1,
                              RefusalCode::not_manifold},
                      BadSoup{"SameOrientation",
                              {Simplex(+1, {0, 1, 2, 3}), Simplex(+1, {0, 1, 2, 4})},
                              "elements 0 and 1 share face -<0,1,2> with the same orientation "
                              "(inconsistently oriented)",
                              1,
                              RefusalCode::not_manifold},
                      BadSoup{"NonManifold",
                              {Simplex(+1, {0, 1, 2, 3}), Simplex(-1, {0, 1, 2, 4}),
                               Simplex(+1, {0, 1, 2, 5})},
                              "face +<0,1,2> is shared by 3 elements (non-manifold)",
                              2,
                              RefusalCode::not_manifold}),
    [](const auto& info) { return std::string(info.param.name); });

TEST(AssignElements, RefusesAMeshThatHasElements) {
    Mesh mesh = unit_square();
    const std::array<Simplex, 1> more{Simplex(+1, {0, 1, 3})};
    const auto result = mesh.assign_elements(more);
    ASSERT_FALSE(result.ok());
    EXPECT_EQ(result.reason(), "assign_elements needs a mesh without elements");
    EXPECT_EQ(result.code(), RefusalCode::not_applicable);
    EXPECT_TRUE(mesh.validate().ok());
}

TEST(AssignElementsUnchecked, KeepsWhatValidateThenNames) {
    Mesh mesh(3, 3);
    for (int i = 0; i < 5; ++i) mesh.add_vertex({double(i), 0, 0});
    const std::array<Simplex, 2> duplicated{Simplex(+1, {0, 1, 2, 3}), Simplex(+1, {0, 1, 2, 3})};
    ASSERT_TRUE(mesh.assign_elements_unchecked(duplicated).ok());
    const auto verdict = mesh.validate();
    ASSERT_FALSE(verdict.ok());
    EXPECT_EQ(verdict.reason(),
              "invariant 7.4 (uniqueness): elements 0 and 1 have the same vertices +<0,1,2,3>");
    EXPECT_EQ(verdict.code(), RefusalCode::invalid_mesh);
}

TEST(AssignElementsUnchecked, PinchedVertexBreaksStarConnectivity) {
    // two tetrahedra that share only vertex 0 ("dangling" tet)
    Mesh mesh(3, 3);
    for (int i = 0; i < 7; ++i) mesh.add_vertex({double(i), 0, 0});
    const std::array<Simplex, 2> pinched{Simplex(+1, {0, 1, 2, 3}), Simplex(+1, {0, 4, 5, 6})};
    // the checked build refuses it; the unchecked one builds it for validate() to name
    const auto refused = mesh.assign_elements(pinched);
    ASSERT_FALSE(refused.ok());
    EXPECT_EQ(refused.reason(),
              "star connectivity: the elements around vertex 0 are not connected through faces "
              "(the mesh is pinched there)");
    EXPECT_EQ(refused.code(), RefusalCode::pinched_star);
    ASSERT_TRUE(mesh.assign_elements_unchecked(pinched).ok());
    const auto verdict = mesh.validate();
    ASSERT_FALSE(verdict.ok());
    EXPECT_EQ(verdict.reason(),
              "star connectivity: the star of vertex 0 is not face-connected (1 of its 2 elements "
              "are reachable from element 0; the mesh is pinched at this vertex)");
    EXPECT_EQ(verdict.code(), RefusalCode::invalid_mesh);
}

TEST(AssignElementsUnchecked, NonManifoldFaceBreaksTheBoundaryMap) {
    Mesh mesh(3, 3);
    for (int i = 0; i < 6; ++i) mesh.add_vertex({double(i), 0, 0});
    const std::array<Simplex, 3> fan{Simplex(+1, {0, 1, 2, 3}), Simplex(-1, {0, 1, 2, 4}),
                                     Simplex(+1, {0, 1, 2, 5})};
    ASSERT_TRUE(mesh.assign_elements_unchecked(fan).ok());
    const auto verdict = mesh.validate();
    ASSERT_FALSE(verdict.ok());
    EXPECT_EQ(verdict.reason().rfind("invariant 7.4 (uniqueness): simplex ", 0), 0u) << verdict.reason();
    EXPECT_EQ(verdict.code(), RefusalCode::invalid_mesh);
}

}  // namespace
}  // namespace sxk
