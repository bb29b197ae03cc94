// Reading .bpt files: Bézier patches as the teapot is distributed (tests/data/teapot.bpt).
//
//   32                 the number of patches
//   3 3                per patch: degrees m n (tensor product), then (m+1)(n+1) lines
//   1.4 0.0 2.4        "x y z", row by row: point (a, b) is line a (n+1) + b
//   ...
#pragma once

#include <filesystem>
#include <istream>
#include <string>
#include <vector>

#include "triangular_patch.hpp"

namespace sxk::bezier {

// Throws sxk::InputError ("FILE:LINE: reason") for a file that cannot be read as text (missing,
// a directory or a device, binary data: sxk::read_text_file, as mesh files are read; a UTF-8
// byte order mark is dropped), a bad count or degree (0 to 20), a malformed or non-finite
// coordinate, a short file or trailing data.
std::vector<TensorPatch> read_bpt(const std::filesystem::path& path);
// The same from a stream; `name` stands for FILE in the messages.
std::vector<TensorPatch> read_bpt(std::istream& in, const std::string& name);

}  // namespace sxk::bezier
