// libFuzzer target for the planar cutters (issue 16): the input is a point scalpel's path text
// (docs/formats.md, "Tool paths", 'time x y'). The reader must parse it or throw InputError; a path
// that parses is replayed on the 5 x 5 square of the thesis' Fig. 5.16 (make_triangle_grid, [0, 5]^2)
// through a PlanarCutSession of each method. Every step must complete or be refused with the mesh bit
// for bit as before; after each one the mesh validates with every triangle counter-clockwise and none
// flat. A sample whose time has an odd whole part takes the last step back (undo_step) instead of
// cutting. At the end every step is undone and the mesh must be the square again, bit for bit. A
// broken rule prints what broke and aborts.
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

#include "ops_driver.hpp"
#include "planar_cut.hpp"
#include "sxk/generators.hpp"
#include "sxk/io.hpp"
#include "sxk/tool_path.hpp"

namespace {

[[noreturn]] void finding(const std::string& what) {
    std::fprintf(stderr, "fuzz_delaunaycut: %s\n", what.c_str());
    std::abort();
}

void check(const sxk::Mesh& mesh, std::size_t step, const char* after) {
    if (auto valid = mesh.validate({.orientation = true, .flat_is_invalid = true}); !valid)
        finding("step " + std::to_string(step) + ", after " + after + ": " + valid.reason());
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    const std::array<int, 1> columns{2};
    sxk::ToolPath path;
    try {
        path = sxk::parse_tool_path(text, "fuzz.path", columns);
    } catch (const sxk::InputError&) {
        return 0;  // refused with a line and a reason: what the reader must do
    }
    for (const sxk::ToolSample& sample : path.samples)
        for (int k = 0; k < 2; ++k)
            if (!std::isfinite(sample.values[static_cast<std::size_t>(k)]))
                finding("the reader let a non-finite value through");

    const sxk::Mesh original = sxk::make_triangle_grid({5, 5}).value();
    for (const auto method : {sxk::delaunaycut::Method::delaunay, sxk::delaunaycut::Method::subdivision}) {
        sxk::Mesh mesh = original;
        sxk::delaunaycut::Options options;
        options.method = method;
        auto made = sxk::delaunaycut::PlanarCutSession::make(mesh, options);
        if (!made) finding("make: " + made.reason());
        auto& session = **made;
        std::size_t step = 0;
        for (const sxk::ToolSample& sample : path.samples) {
            ++step;
            if (static_cast<long long>(std::floor(sample.time)) % 2 != 0 && session.steps() > 0) {
                if (auto undone = session.undo_step(); !undone) finding("undo_step: " + undone.reason());
                check(mesh, step, "undo");
                continue;
            }
            const auto before = sxk::ops_driver::snapshot(mesh);
            if (auto cut = session.cut({sample.values[0], sample.values[1], 0});
                !cut && !(sxk::ops_driver::snapshot(mesh) == before))
                finding("step " + std::to_string(step) + " was refused (" + cut.reason() + ") and changed the mesh");
            check(mesh, step, "cut");
        }
        while (session.steps() > 0)
            if (auto undone = session.undo_step(); !undone) finding("undo_step: " + undone.reason());
        session.end();
        check(mesh, step, "undoing every step");
        if (!(sxk::ops_driver::snapshot(mesh) == sxk::ops_driver::snapshot(original)))
            finding("undoing every step did not give the square back");
    }
    return 0;
}
