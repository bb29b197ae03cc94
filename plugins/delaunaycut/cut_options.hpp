// The planar cutter's options as words: `sxk cut delaunay` and the ToolFactory's sessions read
// them the same way.
#pragma once

#include <CLI/CLI.hpp>

#include "planar_cut.hpp"

namespace sxk::delaunaycut {

void add_cut_options(CLI::App& app, Options& options);

}  // namespace sxk::delaunaycut
