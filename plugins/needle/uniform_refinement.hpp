// The start mesh of the thesis' needle runs (§6.7: "the starting mesh is uniformly refined until
// edge lengths have a specified length h_start"): every element bisected until it is of size h
// (shaft_refinement.hpp: its bisection edge at most sqrt(d) h), by the
// same refine-around the needle uses. For setting a mesh up, not for a frame: it visits every
// element.
#pragma once

#include <cstddef>

#include "sxk/mesh.hpp"
#include "sxk/outcome.hpp"

namespace sxk::needle {

// New vertices; refuses h not positive and what the refinement refuses.
Outcome<std::size_t> refine_uniformly(Mesh& mesh, double h);

}  // namespace sxk::needle
