// libFuzzer target for the Delaunay cutters (issue 16): the input is a scalpel's path text
// (docs/formats.md, "Tool paths"). A point scalpel's ('time x y') is replayed on the 5 x 5 square of
// the thesis' Fig. 5.16 (make_triangle_grid, [0, 5]^2) through a PlanarCutSession of each method; a
// line scalpel's ('time hx hy hz tx ty tz') on a 6 x 6 Gaussian bell (make_gaussian_bell, [0, 6]^2,
// its top 2 high) through a SurfaceCutSession. Both under the tool oracle of tool_replay.hpp (steps
// complete or change nothing, the mesh validates, with no triangle inverted or flat in the plane,
// undo gives the mesh back).
#include <array>
#include <cstdint>

#include "planar_cut.hpp"
#include "surface_cut.hpp"
#include "sxk/generators.hpp"
#include "tool_replay.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::array<int, 2> columns{2, 6};
    const auto path = sxk::fuzz::parse_fuzzed_path({reinterpret_cast<const char*>(data), size}, columns);
    if (!path) return 0;
    if (path->columns == 6) {
        const sxk::Mesh original = sxk::make_gaussian_bell({6, 6}, {1.0, 1.0}, 2.0, 1.0).value();
        sxk::Mesh mesh = original;
        auto made = sxk::delaunaycut::SurfaceCutSession::make(mesh, {});
        if (!made) sxk::fuzz::finding("make: " + made.reason());
        auto& session = **made;
        sxk::fuzz::replay_tool_path(session, mesh, original, *path, {}, [&](const sxk::ToolSample& sample) {
            const auto& v = sample.values;
            return session.cut({v[0], v[1], v[2]}, {v[3], v[4], v[5]});
        });
        return 0;
    }
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
