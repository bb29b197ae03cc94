// Degeneracy removal (thesis §3.2.3, Figs. 3.8-3.10; results §3.3, Fig. 3.16): flat elements,
// as a snap cut leaves them, are found by their aspect ratio and removed by splits and edge
// collapses chosen by their shape; what cannot be collapsed is cut free.
//
// Classes (tetrahedra, by the number of dihedral angles above options.large_angle, Fig. 3.8)
// and what removes them (Fig. 3.9):
//
//   needle  (0)  a short edge                    collapse the shortest edge
//   spindle (1)  a vertex v near the edge ab      split ab at v's foot m, collapse m-v
//                opposite the large angle
//   sliver  (2)  two crossing edges ab, cd        split both at their closest points m1, m2,
//                (the quadrilateral a c b d)       collapse m1-m2
//   cap     (3)  a vertex d near the opposite     split abc at d's foot m, collapse m-d
//                face abc
//
//        spindle                  sliver                      cap
//
//           v                        c                          c
//          /|\ .                  / | \                      / | \      d just above abc:
//         / | \ .               a --m-- b                   /  d  \ .   its foot m lies
//        a--m--b                  \ | /                    /   m   \ .  inside the face
//                                   d                      a ------- b
//   v just off ab: m, its     ab and cd cross (seen from
//   foot on ab, is near v     above): m on both, close
//
// Triangles: a flat triangle with an angle above large_angle (its vertex v lies near the
// opposite edge ab) is flipped across ab when both new triangles are fine, else ab is split at
// v's foot and the short edge collapsed; one without (a short edge) collapses its shortest edge.
//
// Passes, as in the thesis: the degenerates form a list, each is handled, a new list is made
// from what remains and what the edits created; while the list shrinks, another pass. Beyond
// the thesis:
//   - a move is kept only if it pays (detail::try_moves): first only moves that make no new
//     degenerate, then moves that leave fewer degenerates or better shapes; a move that does
//     not pay is rolled back (one EditJournal step per move), so passes do not churn (the thesis keeps every collapse
//     and its cube and femur runs then went on for dozens of passes);
//   - a pass also runs while the list holds elements no pass has tried (a pass may remove
//     some and make as many new ones);
//   - slivers try a clean flip before the vertex the thesis puts where their edges cross,
//     which splits every element around both edges (+5 elements per sliver);
//   - then 2-3, 3-2 and 4-4 flips that remove an element without a crack (clean ones, else
//     ones that raise the worst shape), each followed by collapse passes again;
//   - then a follow-up stage: a move may make new degenerates if clean moves right after it
//     remove them all (move and follow-ups undone together otherwise);
//   - then elements lying flat on the boundary are peeled off (removed, their other faces
//     becoming the boundary: it moves by less than boundary_tolerance);
// and only what still remains is cut free (dissected along its faces, thesis §7.3) and
// removed: those are the cracks.
//
// Guarantees. Every edit is one of the kernel's operations (split_edge, split_face,
// collapse_edge, flip_23/32/44, dissect, replace_elements), each a transaction checked by exact
// orientation in BOTH position sets, so no element is ever flat or inverted by an edit here. A
// split whose collapse is refused is undone (collapse back and remove the new vertex), so a
// failed attempt leaves no trace. Boundary vertices only move along the boundary: a collapse
// that moves a boundary vertex needs the edge on the boundary and each boundary face around it
// to stay within options.boundary_tolerance of its plane.
#pragma once

#include <array>
#include <cstddef>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "sxk/ids.hpp"
#include "sxk/mesh.hpp"
#include "sxk/outcome.hpp"
#include "sxk/quality.hpp"
#include "sxk/plugins/degeneracy.hpp"

namespace sxk::degeneracy {

// Finds every degenerate element of the mesh and removes them. Refuses (mesh untouched) when
// an option is out of range (Options::check: "remove_degeneracies: aspect_ratio 2 is not in
// (0, 1)" and the like). Elements that are flat or inverted already (exact orientation zero or
// negative) are degenerate too, but splits refuse to cut them (their pieces would not be
// positive), so only collapses, flips or cutting free remove them.
Outcome<Report> remove_degeneracies(Mesh& mesh, const Options& options = {});

// The same, looking for degenerates only among `candidates` (ids that are not elements are
// skipped) and the elements the removal itself creates: after a local edit (a snap cut moves a
// few vertices) pass the stars of the moved vertices and the cost stays local. Elements outside
// `candidates` that are degenerate already are left alone. The quality figures of the report
// then cover the elements looked at, not the whole mesh.
Outcome<Report> remove_degeneracies(Mesh& mesh, std::span<const ElementId> candidates,
                                    const Options& options = {});

// The class of element t (none when it is not degenerate) in options.positions.
DegenerateClass classify(const Mesh& mesh, ElementId t, const Options& options = {});

}  // namespace sxk::degeneracy
