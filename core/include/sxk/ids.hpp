// Identities of vertices, elements and faces.
//
// Vertices are plain integers (thesis §7.4: "the set of vertices simply is given by the positive
// integers"), used as indices into the per-vertex arrays. Elements and faces live in pools and
// are addressed by 32-bit ids; an id names the same object for as long as it is alive, across
// change_elements, and may be reused after the object is freed.
#pragma once

#include <cstdint>
#include <limits>

namespace sxk {

using VertexId = std::uint32_t;
using ElementId = std::uint32_t;
using FaceId = std::uint32_t;

inline constexpr std::uint32_t invalid_id = std::numeric_limits<std::uint32_t>::max();

}  // namespace sxk
