// libFuzzer target for the planar cutters (issue 16): the input is a point scalpel's path text
// (docs/formats.md, "Tool paths", 'time x y'), replayed on the 5 x 5 square of the thesis' Fig. 5.16
// (make_triangle_grid, [0, 5]^2) through a PlanarCutSession of each method, under the tool oracle
// of tool_replay.hpp (steps complete or change nothing, the mesh validates with no triangle
// inverted or flat, undo gives the square back).
#include <array>
#include <cstdint>

#include "planar_cut.hpp"
#include "sxk/generators.hpp"
#include "tool_replay.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::array<int, 1> columns{2};
    const auto path = sxk::fuzz::parse_fuzzed_path({reinterpret_cast<const char*>(data), size}, columns);
    if (!path) return 0;
    const sxk::Mesh original = sxk::make_triangle_grid({5, 5}).value();
    for (const auto method : {sxk::delaunaycut::Method::delaunay, sxk::delaunaycut::Method::subdivision}) {
        sxk::Mesh mesh = original;
        sxk::delaunaycut::Options options;
        options.method = method;
        auto made = sxk::delaunaycut::PlanarCutSession::make(mesh, options);
        if (!made) sxk::fuzz::finding("make: " + made.reason());
        auto& session = **made;
        sxk::fuzz::replay_tool_path(session, mesh, original, *path, {.orientation = true, .flat_is_invalid = true},
                                    [&](const sxk::ToolSample& sample) {
                                        return session.cut({sample.values[0], sample.values[1], 0});
                                    });
    }
    return 0;
}
