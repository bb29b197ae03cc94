// The needle's options on a command line: `sxk needle` and the ToolFactory tool "needle" read the
// same words (docs/cli.md "sxk needle").
#pragma once

#include <CLI/CLI.hpp>

#include "needle.hpp"

namespace sxk::needle {

void add_needle_options(CLI::App& app, Options& options);

}  // namespace sxk::needle
