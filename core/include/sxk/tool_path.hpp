// Recorded tool paths (docs/formats.md "Tool paths"): the scalpel, needle or point samples that
// `sxk cut snap`, `sxk cut delaunay` and `sxk needle` replay through their tool sessions.
//
//     # time  hx hy hz  tx ty tz        one sample per line: a time, then the tool's coordinates
//     0.0     0 0 1     0 0 0.2
//     0.1     0.1 0 1   0.1 0 0.2
//
// Every sample line holds the same number of values after the time; the tools say which counts
// they take (a 2D point scalpel: 2, a 2D needle's base and tip: 4, a 3D scalpel's or needle's two
// ends: 6). Blank lines and everything from '#' to the end of a line are ignored.
#pragma once

#include <array>
#include <cstddef>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "sxk/config.hpp"
#include "sxk/mesh.hpp"

namespace sxk {

struct ToolSample {
    double time = 0;
    std::array<double, 6> values{};  // the first ToolPath::columns are the sample's
    std::size_t line = 0;            // where it is in the file (1-based), for the tools' messages
};

struct ToolPath {
    int columns = 0;  // values per sample after the time
    std::vector<ToolSample> samples;
};

// Parses a tool path. `columns`: the value counts the caller accepts (at most 6 each); the first
// sample decides which, and every other sample must have as many. Throws InputError ("NAME:LINE:
// reason"; docs/formats.md lists them) for a value that is not a finite number, a sample with
// another count of values, a time before the previous sample's (equal times are allowed), and a
// path of fewer than two samples (line 0: not tied to a line). The text must be text
// (read_text_file checks it).
SXK_API ToolPath parse_tool_path(std::string_view text, const std::string& name,
                                 std::span<const int> columns);
// read_text_file, then parse_tool_path with the file's name.
SXK_API ToolPath read_tool_path(const std::filesystem::path& path, std::span<const int> columns);

// A tool's path given by the triangles it sweeps, in order: an OBJ file's faces as listed (the
// OBJ reader's syntax, docs/formats.md), with none of a mesh's checks, since sweeps overlap,
// repeat and fan around shared edges. Throws InputError as the OBJ reader does, and for a file
// with no face (line 0).
struct SweptTriangle {
    std::array<Point, 3> corners;
    std::size_t line = 0;  // of its "f" statement (1-based)
};
SXK_API std::vector<SweptTriangle> parse_swept_triangles(std::string_view text, const std::string& name);
// read_text_file, then parse_swept_triangles with the file's name.
SXK_API std::vector<SweptTriangle> read_swept_triangles(const std::filesystem::path& path);

}  // namespace sxk
