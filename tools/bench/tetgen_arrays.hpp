// A minimal fast TetGen .node/.ele reader for the benchmarks: plain arrays, nothing else.
//
// The benchmarks time what is built *from* these arrays, so the reader only has to be quick
// enough not to dominate a run (1.2M tets load in well under a second) and independent of the
// library reader under test. It reads first-order tets (4 or 10 nodes per tet, the first 4 are
// the corners), ignores attributes and boundary markers, and maps TetGen's 0- or 1-based
// numbering (taken from the first node index in the .node file) to 0-based vertex ids.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace sxk_bench {

struct TetArrays {
    std::vector<std::array<double, 3>> points;
    std::vector<std::array<std::uint32_t, 4>> tets;  // 0-based, in TetGen's (positive) order
};

// Reads ELE_PATH and the .node file beside it (same stem). Throws std::runtime_error with the
// file name and a reason when a file is missing or malformed.
TetArrays load_tetgen(const std::string& ele_path);

}  // namespace sxk_bench
