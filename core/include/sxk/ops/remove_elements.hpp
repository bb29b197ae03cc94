// Removal of elements from a mesh (a piece a cut separated, an element cut free, a flat element
// peeled off the boundary): one Mesh::replace_elements call with no new elements, and the face
// labels of the faces that went with them dropped, so that every label still names a face.
//
//        before                        after remove_elements({t})
//     +-------+-------+             +-------+       +
//     |  s   /|\  u   |             |  s   /|\      |   t's faces shared with s and u stay (as
//     |    /  |  \    |             |    /  |       |   their boundary faces) with their labels;
//     |  /  t |    \  |             |  /    |       |   t's own boundary faces are gone, and so
//     +-------+-------+             +-------+       +   are their labels
//
// Contract.
//   Before: `elements` are element ids (repeats allowed).
//   After (on success): those elements are gone (Mesh::replace_elements' identities: other
//   elements and faces keep their ids; faces the removed elements shared become boundary faces
//   of their neighbours); the label of every face of a removed element that no element has any
//   more is erased (a face some element still has keeps its label). The vertices stay, in no
//   element when all their elements went. Inside an EditJournal step every change is recorded.
// Refusals (mesh untouched): Mesh::replace_elements' ("element 7 is not an element"; a removal
// that would pinch a vertex star: remove the whole piece around the vertex, or cut it first).
#pragma once

#include <span>

#include "sxk/config.hpp"
#include "sxk/mesh.hpp"
#include "sxk/outcome.hpp"

namespace sxk {

SXK_API Outcome<Done> remove_elements(Mesh& mesh, std::span<const ElementId> elements);

}  // namespace sxk
