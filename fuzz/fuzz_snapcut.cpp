// libFuzzer target for the snap cutter (issue 15): the input is a scalpel path's text (the
// format of docs/formats.md, "Tool paths"), replayed on a Kuhn cube (4^3 cells of 6 tetrahedra,
// edge 1: [0, 4]^3) through SnapCutSession with the degeneracy plug-in linked in, under the tool
// oracle of tool_replay.hpp (steps complete or change nothing, the mesh validates with every element
// positive in both position sets, undo gives the cube back).
#include <array>
#include <cstdint>

#include "degeneracy_plugin.hpp"
#include "sxk/plugins/degeneracy.hpp"
#include "snap_cut.hpp"
#include "sxk/generators.hpp"
#include "tool_replay.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::array<int, 1> columns{6};
    const auto path = sxk::fuzz::parse_fuzzed_path({reinterpret_cast<const char*>(data), size}, columns);
    if (!path) return 0;
    const sxk::Mesh original = sxk::make_kuhn_cube(4).value();
    sxk::Mesh mesh = original;
    auto made = sxk::snapcut::SnapCutSession::make(mesh, {}, {sxk::degeneracy::linked_in_service(), nullptr});
    if (!made) sxk::fuzz::finding("make: " + made.reason());
    auto& session = **made;
    sxk::fuzz::replay_tool_path(session, mesh, original, *path, {.orientation = true},
                                [&](const sxk::ToolSample& sample) {
                                    const auto& v = sample.values;
                                    return session.cut({{v[0], v[1], v[2]}, {v[3], v[4], v[5]}});
                                });
    return 0;
}
