// Identities of vertices, elements and faces.
//
// Vertices are plain integers (thesis §7.4: "the set of vertices simply is given by the positive
// integers"), used as indices into the per-vertex arrays. Elements and faces live in pools and
// are addressed by 32-bit ids; an id names the same object for as long as it is alive, across
// change_elements, and may be reused after the object is freed.
//
// ElementId and FaceId are distinct types, so that a face id passed where an element id is
// expected (or the other way round) does not compile. Each converts implicitly from and to
// std::uint32_t, so ids still index arrays, compare with invalid_id and take arithmetic
// (`t * k + j`) as integers do; but C++ allows one user-defined conversion in an implicit
// conversion, and FaceId -> std::uint32_t -> ElementId would take two. Turning one into the
// other is therefore always written out (`ElementId{f / k}`). The wrapper is one 32-bit integer
// with trivial members: the integer's size and layout, and no cost the tet_flips benchmark can
// tell from its run-to-run spread (docs/performance.md "Distinct id types").
#pragma once

#include <cstdint>
#include <functional>
#include <limits>

namespace sxk {

template <class Tag>
class Id {
public:
    // Like an integer: left undetermined by default-initialisation, zero by value-initialisation
    // (std::vector<ElementId>(n) holds zeros).
    Id() = default;
    constexpr Id(std::uint32_t value) noexcept : m_value(value) {}  // NOLINT(google-explicit-constructor)
    constexpr operator std::uint32_t() const noexcept { return m_value; }  // NOLINT(google-explicit-constructor)
    constexpr std::uint32_t value() const noexcept { return m_value; }

    constexpr Id& operator++() noexcept {
        ++m_value;
        return *this;
    }
    constexpr Id operator++(int) noexcept {
        const Id old = *this;
        ++m_value;
        return old;
    }
    constexpr Id& operator--() noexcept {
        --m_value;
        return *this;
    }
    constexpr Id operator--(int) noexcept {
        const Id old = *this;
        --m_value;
        return old;
    }

private:
    std::uint32_t m_value;
};

struct ElementTag;
struct FaceTag;

using VertexId = std::uint32_t;
using ElementId = Id<ElementTag>;
using FaceId = Id<FaceTag>;

inline constexpr std::uint32_t invalid_id = std::numeric_limits<std::uint32_t>::max();

// Found by argument-dependent lookup by JSON libraries that look for to_json (nlohmann's), so
// that an id is written as the number it is.
template <class Json, class Tag>
void to_json(Json& json, Id<Tag> id) {
    json = id.value();
}

}  // namespace sxk

template <class Tag>
struct std::hash<sxk::Id<Tag>> {
    std::size_t operator()(sxk::Id<Tag> id) const noexcept { return std::hash<std::uint32_t>{}(id.value()); }
};
