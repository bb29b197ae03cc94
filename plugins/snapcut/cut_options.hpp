// The snap cutter's options as `sxk cut snap`'s words, read into the tool's Options
// (sxk/plugins/snapcut.hpp, whose check() the session applies again):
//
//   --no-snap                  faces are dissected where they are (jagged incisions, Fig. 3.5)
//   --no-degeneracy-removal    flat elements stay (thesis Fig. 3.14)
//   --aspect A                 degeneracy threshold, 0 < A < 1 (0.01)
//   --angle RADIANS            large dihedral angle, pi/2 < x < pi (0.99 pi)
//   --snap-min-aspect A        refuse a snap leaving an element below A, 0 <= A < 1 (0: off)
//   --split-beyond X           split crossed edges whose nearer end is farther than X mean edge
//                              lengths from the sweep's plane, where crossed (0.5; 0: never)
//   --remove-loose             remove the pieces a step cuts loose
//   --largest-crumb N          keep pieces of at most N elements attached, cut free crumbs (4)
//   --cut-label L              the face label of the cut surface (9999)
//   --relax-iterations N       with a simulation: CG iterations after each step (100)
//   --local N                  with a simulation: relax only around what the step changed, at
//                              most N vertices (0: the whole body)
//   --far N                    with --local: one far-field block of at most N vertices per step
#pragma once

#include <CLI/CLI.hpp>

#include "snap_cut.hpp"

namespace sxk::snapcut {

// Adds the options above to `app`, writing into `options` when parsed.
void add_cut_options(CLI::App& app, Options& options);

}  // namespace sxk::snapcut
