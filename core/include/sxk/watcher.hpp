// Mesh connectivity watchers (thesis §7.4).
//
// A watcher keeps state of its own (solver arrays, spatial indexes, render buffers) in step with
// the mesh. When added to a Mesh it is initialised with the whole mesh (the thesis'
// init_elements + init_boundary); after that every edit reports each *net* change exactly once,
// after the edit completed (so the mesh it sees is consistent):
//
//   element_removed   an element that existed before the edit is gone (its id may already be
//                     reused by an element reported as added in the same edit)
//   element_changed   change_elements gave an element new vertices; identity kept
//   element_added     a new element exists
//   boundary_removed  a face that was on the boundary no longer is (matched, or deleted)
//   boundary_changed  a boundary face kept its identity and stays on the boundary, but its
//                     simplex changed (change_elements)
//   boundary_added    a face that was not on the boundary now is
//   vertices_moved    Mesh::move_vertices (or a position setter) gave vertices new positions
//                     in one or both position sets: one call per move, listing each vertex once
//
// Transient boundary changes inside one edit (the thesis' remove-then-add of faces that end up
// where they were) are not reported. A refused edit reports nothing. An EditJournal rollback or
// undo reports the net change back to the state of its checkpoint the same way, as one edit
// (edit_journal.hpp).
#pragma once

#include <cstdint>
#include <span>

#include "sxk/ids.hpp"
#include "sxk/simplex.hpp"

namespace sxk {

class Mesh;

// The position sets a move writes: the reference (material) positions, the deformed
// (simulated) ones, or both.
enum class PositionSet : std::uint8_t { reference = 1, deformed = 2, both = 3 };

inline bool writes_reference(PositionSet which) { return (static_cast<int>(which) & 1) != 0; }
inline bool writes_deformed(PositionSet which) { return (static_cast<int>(which) & 2) != 0; }

class Watcher {
public:
    virtual ~Watcher() = default;

    virtual void init(const Mesh& /*mesh*/) {}
    virtual void element_removed(const Mesh& /*mesh*/, ElementId /*element*/,
                                 const Simplex& /*was*/) {}
    virtual void element_changed(const Mesh& /*mesh*/, ElementId /*element*/,
                                 const Simplex& /*was*/) {}
    virtual void element_added(const Mesh& /*mesh*/, ElementId /*element*/) {}
    virtual void boundary_removed(const Mesh& /*mesh*/, FaceId /*face*/,
                                  const Simplex& /*was*/) {}
    virtual void boundary_changed(const Mesh& /*mesh*/, FaceId /*face*/,
                                  const Simplex& /*was*/) {}
    virtual void boundary_added(const Mesh& /*mesh*/, FaceId /*face*/) {}
    // `vertices` (distinct) have new positions in `which`; the mesh already holds them.
    virtual void vertices_moved(const Mesh& /*mesh*/, std::span<const VertexId> /*vertices*/,
                                PositionSet /*which*/) {}
};

}  // namespace sxk
