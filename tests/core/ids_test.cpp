// sxk/ids.hpp: ElementId and FaceId are distinct types that behave as integers otherwise. The
// refusals are compile-time facts, so they are static_asserts: a change that lets a face id
// pass for an element id stops this file from compiling.
#include <gtest/gtest.h>

#include <type_traits>
#include <unordered_set>
#include <vector>

#include "core/fixtures.hpp"
#include "sxk/ids.hpp"
#include "sxk/mesh.hpp"

namespace sxk {
namespace {

// One kind does not become the other implicitly, in either direction.
static_assert(!std::is_convertible_v<FaceId, ElementId>);
static_assert(!std::is_convertible_v<ElementId, FaceId>);
// Integers become either kind and either kind becomes an integer.
static_assert(std::is_convertible_v<std::uint32_t, ElementId>);
static_assert(std::is_convertible_v<ElementId, std::uint32_t>);
static_assert(std::is_convertible_v<std::uint32_t, FaceId>);
// Written out, the conversion is there.
static_assert(std::is_constructible_v<ElementId, FaceId>);

// The kernel's calls take only their own kind.
template <class Id>
concept FaceElementTakes = requires(const Mesh& mesh, Id id) { mesh.face_element(id); };
static_assert(FaceElementTakes<FaceId>);
static_assert(FaceElementTakes<std::uint32_t>);
static_assert(!FaceElementTakes<ElementId>);
template <class Id>
concept SimplexTakes = requires(const Mesh& mesh, Id id) { mesh.simplex(id); };
static_assert(SimplexTakes<ElementId>);
static_assert(!SimplexTakes<FaceId>);

// Nothing but the integer: the pools and files keep their layout.
static_assert(sizeof(ElementId) == sizeof(std::uint32_t) && alignof(FaceId) == alignof(std::uint32_t));
static_assert(std::is_trivially_copyable_v<ElementId> && std::is_standard_layout_v<FaceId>);

TEST(Ids, BehaveAsIntegersOtherwise) {
    std::vector<ElementId> zeros(3);  // value-initialised: 0, as std::vector<std::uint32_t>
    for (const ElementId t : zeros) EXPECT_EQ(t, 0u);
    ElementId t = 41;
    EXPECT_EQ(++t, 42u);
    EXPECT_EQ(t++, 42u);
    EXPECT_EQ(t, 43u);
    EXPECT_EQ(--t, 42u);
    EXPECT_EQ(t * 4 + 3, 171u);
    const FaceId f = t * 4 + 3;
    EXPECT_EQ(ElementId{f / 4}, t);
    EXPECT_NE(FaceId{invalid_id}, f);
    EXPECT_EQ(std::to_string(t), "42");
    const std::unordered_set<FaceId> faces{f, FaceId{7}, f};
    EXPECT_EQ(faces.size(), 2u);
    EXPECT_TRUE(faces.contains(7));
}

TEST(Ids, TheMeshAnswersInItsOwnKinds) {
    const Mesh mesh = test::unit_square();
    for (const ElementId t : elements(mesh))
        for (const FaceId f : mesh.faces(t)) {
            const ElementId owner = mesh.face_element(f);
            EXPECT_EQ(owner, t);
            const FaceId mate = mesh.mate(f);
            if (mate != invalid_id) {
                EXPECT_NE(mesh.face_element(mate), t);
            }
        }
    EXPECT_TRUE(mesh.validate().ok());
}

}  // namespace
}  // namespace sxk
