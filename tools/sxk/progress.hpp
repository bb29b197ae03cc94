// The built-in commands' progress line: the spinner the plug-ins' commands use too
// (cli/progress_line.hpp, the command-line library).
#pragma once

#include "progress_line.hpp"

namespace sxk::cli {

using Progress = ProgressLine;

}  // namespace sxk::cli
