// libFuzzer target for the needle (issue 17): the input is a needle's path text (docs/formats.md,
// "Tool paths"). A 2D path ('time bx by tx ty') is replayed into a slab of 4 x 4 cells (0.1 m,
// fixed at x = 0.1, the thesis' material) with the elasticity plug-in's body; a 3D one ('time bx by
// bz tx ty tz') into a Kuhn cube of 2 x 2 x 2 cells with its body. Both under the tool oracle of
// tool_replay.hpp (steps complete or change nothing, the mesh validates with no element inverted or
// flat in either position set, undo gives the mesh back bit for bit). The input's length picks the
// options: relocation or not, the local solve and its far-field blocks.
#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "body_words.hpp"
#include "needle.hpp"
#include "simulation.hpp"
#include "sxk/generators.hpp"
#include "tool_replay.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::array<int, 2> columns{4, 6};
    const auto path = sxk::fuzz::parse_fuzzed_path({reinterpret_cast<const char*>(data), size}, columns);
    if (!path) return 0;
    const bool planar = path->columns == 4;
    const sxk::Mesh original = planar ? sxk::make_triangle_grid({4, 4}, {0.025, 0.025}).value()
                                      : sxk::make_kuhn_cube(2, 0.05).value();
    sxk::Mesh mesh = original;
    std::vector<std::string> words{"--fix", "x>0.0999", "--E", "34e3", "--nu", "0.34", "--tol", "0.01"};
    if (planar) words.insert(words.end(), {"--thickness", "0.01"});
    auto body = sxk::elasticity::simulate(mesh, sxk::cli::body_options(words).value());
    if (!body) sxk::fuzz::finding("simulate: " + body.reason());
    sxk::needle::Options options;
    options.h_ref = planar ? 0.1 / 16 : 0.1 / 8;
    options.iterations = 200;
    options.relocate = size % 2 == 1;  // both schemes
    // and every third input solved around the needle only, half of those with far-field blocks
    if (size % 3 == 1) options.local_vertices = 8;
    if (size % 6 == 1) options.far_vertices = 8;
    auto made = sxk::needle::NeedleSession::make(mesh, options, body->get());
    if (!made) sxk::fuzz::finding("make: " + made.reason());
    auto& session = **made;
    sxk::fuzz::replay_tool_path(session, mesh, original, *path, {.orientation = true, .flat_is_invalid = true},
                                [&](const sxk::ToolSample& sample) {
                                    const auto& v = sample.values;
                                    const sxk::needle::Needle needle =
                                        planar ? sxk::needle::Needle{{v[0], v[1], 0}, {v[2], v[3], 0}}
                                               : sxk::needle::Needle{{v[0], v[1], v[2]}, {v[3], v[4], v[5]}};
                                    return session.move(needle);
                                });
    return 0;
}
