// The Delaunay cutters' options as `sxk cut delaunay`'s words, read into the tool's Options
// (sxk/plugins/delaunaycut.hpp).
#pragma once

#include <CLI/CLI.hpp>

#include "planar_cut.hpp"

namespace sxk::delaunaycut {

void add_cut_options(CLI::App& app, Options& options);

}  // namespace sxk::delaunaycut
