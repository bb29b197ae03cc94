// What the refinement options of `sxk needle` imply before any of it is done: a --h-start of 1e-6
// on a 10 cm slab asks for about 1e15 elements, and a --radius of 5 cm with --h-ref 1e-4 for a tube
// of 1e10; the refinement would grow until memory runs out (the hostile trial: ~35 MB/s until
// killed). The command refuses, up front, options whose estimate passes a limit.
#pragma once

#include <cstddef>
#include <optional>
#include <span>

#include "sxk/mesh.hpp"

namespace sxk::needle {

// The most elements the options may add: a needle run holds about 4 KB per element (measured:
// `--radius 0.05 --h-ref 5e-4` on the 0.1 m slab, 93,088 elements at 407 MB, the steps' undo
// records and the needle's nodes included), so a million is about 4 GB of this 23 GB machine's
// memory, and far above the thesis' runs (Table 6.5: tens of thousands of elements).
inline constexpr double refinement_element_limit = 1e6;

// Estimates of the elements the refinements create, from the measure (area, volume) they cover
// over the measure of an element of size h (shaft_refinement.hpp: the h_k grid's right triangles,
// h^2 / 2, or Kuhn tetrahedra, h^3 / 6):
// - uniform: the whole mesh refined to size h (--h-start), at least the elements it has;
// - along the path: a tube of radius max(radius, h) around the tip's path inside the mesh's box
//   (`tips`: the tip of every sample, reference positions), never more than the whole mesh at
//   size h. Overlapping movements are counted again: an upper estimate.
double uniform_refinement_elements(const Mesh& mesh, double h);
double path_refinement_elements(const Mesh& mesh, std::span<const Point> tips, double h, double radius);

}  // namespace sxk::needle
