// The built-in commands' progress line: the spinner the plug-ins' commands use too
// (plugins/progress_line.hpp, on sxk's include path as command_line.hpp is).
#pragma once

#include "progress_line.hpp"

namespace sxk::cli {

using Progress = ProgressLine;

}  // namespace sxk::cli
