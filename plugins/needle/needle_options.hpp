// The needle's options on a command line: `sxk needle` and the ToolFactory tool "needle" read the
// same words (docs/cli.md "sxk needle").
#pragma once

#include <string>

#include <CLI/CLI.hpp>

#include "needle.hpp"

namespace sxk::needle {

// The session's options, and --deform (--material) into `deform` when given: the body as
// `sxk deform`'s words in one word.
void add_needle_options(CLI::App& app, Options& options, std::string* deform = nullptr);

}  // namespace sxk::needle
