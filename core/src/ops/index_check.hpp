// The check of the operations that locate points with a caller's SpatialIndex (refine_around,
// refine_around_tetrahedra): it must watch the mesh being edited, over the reference positions,
// where these operations measure and locate.
#pragma once

#include <optional>
#include <string>

#include "sxk/locate.hpp"
#include "sxk/mesh.hpp"
#include "sxk/outcome.hpp"

namespace sxk::detail {

// Nothing when `index` fits; `operation` starts the reason ("refine_around: ...").
inline std::optional<Refusal> refuse_index(const Mesh& mesh, const SpatialIndex& index, const std::string& operation) {
    if (&index.mesh() != &mesh) return Refusal{RefusalCode::bad_argument, operation + ": the spatial index watches another mesh"};
    if (index.positions() != Positions::reference)
        return Refusal{RefusalCode::bad_argument,
                       operation + ": the spatial index is over the deformed positions; refinement locates in the reference "
                       "positions"};
    return std::nullopt;
}

}  // namespace sxk::detail
