// The needle's options on `sxk needle`'s command line (docs/cli.md "sxk needle"), read into the
// tool's Options (sxk/plugins/needle.hpp).
#pragma once

#include <string>

#include <CLI/CLI.hpp>

#include "needle.hpp"

namespace sxk::needle {

// The session's options, and --deform (--material) into `deform`: the body as `sxk deform`'s
// words in one word.
void add_needle_options(CLI::App& app, Options& options, std::string& deform);

}  // namespace sxk::needle
