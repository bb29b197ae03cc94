// The oracle the tool fuzzers share (fuzz_snapcut, fuzz_delaunaycut): a recorded path's text is
// parsed (docs/formats.md "Tool paths") or refused with InputError, and a path that parses is
// replayed through a tool session. Every step must complete or be refused with the mesh bit for bit
// as before; after each the mesh validates (ValidateOptions the tool promises). A sample whose time
// has an odd whole part takes the last step back (undo_step) instead, then takes it again
// (redo_step) and back once more: the mesh bit for bit as after the step, then as before it. At
// the end every step is undone and the mesh must be what it was before the session, bit for bit. A broken rule is a
// finding (oracle.hpp): printed, then abort.
#pragma once

#include <cmath>
#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "ops_driver.hpp"
#include "oracle.hpp"
#include "sxk/io.hpp"
#include "sxk/tool_path.hpp"
#include "sxk/tool_session.hpp"

namespace sxk::fuzz {

// The path, or none when the reader refused the text (what it must do with what it cannot read);
// a non-finite value let through is a finding.
inline std::optional<ToolPath> parse_fuzzed_path(std::string_view text, std::span<const int> columns) {
    ToolPath path;
    try {
        path = parse_tool_path(text, "fuzz.path", columns);
    } catch (const InputError&) {
        return std::nullopt;
    }
    for (const ToolSample& sample : path.samples)
        for (int k = 0; k < path.columns; ++k)
            if (!std::isfinite(sample.values[static_cast<std::size_t>(k)]))
                finding("the reader let a non-finite value through");
    return path;
}

// Replays `path` through `session` on `mesh` (as `original` was when the session began); `step`
// takes one sample as the tool's step.
template <class Step>
void replay_tool_path(ToolSession& session, const Mesh& mesh, const Mesh& original, const ToolPath& path,
                      const ValidateOptions& valid, Step&& step) {
    auto check = [&](std::size_t index, const char* after) {
        if (auto checked = mesh.validate(valid); !checked)
            finding("step " + std::to_string(index) + ", after " + after + ": " + checked.reason());
    };
    std::size_t index = 0;
    for (const ToolSample& sample : path.samples) {
        ++index;
        // fmod, not a cast to an integer: a time of 1e69 is a finite time the reader accepts
        if (std::fmod(std::floor(sample.time), 2.0) != 0 && session.steps() > 0) {
            const auto stepped = ops_driver::snapshot(mesh);
            if (auto undone = session.undo_step(); !undone) finding("undo_step: " + undone.reason());
            check(index, "undo");
            const auto undone = ops_driver::snapshot(mesh);
            if (auto redone = session.redo_step(); !redone) finding("redo_step: " + redone.reason());
            if (!(ops_driver::snapshot(mesh) == stepped))
                finding("step " + std::to_string(index) + ": the redo did not give the mesh of the step back");
            if (auto again = session.undo_step(); !again) finding("undo_step after redo_step: " + again.reason());
            if (!(ops_driver::snapshot(mesh) == undone))
                finding("step " + std::to_string(index) + ": undoing the redo did not give the mesh back");
            continue;
        }
        const auto before = ops_driver::snapshot(mesh);
        if (auto stepped = step(sample); !stepped && !(ops_driver::snapshot(mesh) == before))
            finding("step " + std::to_string(index) + " was refused (" + stepped.reason() + ") and changed the mesh");
        check(index, "the step");
    }
    while (session.steps() > 0)
        if (auto undone = session.undo_step(); !undone) finding("undo_step: " + undone.reason());
    session.end();
    check(index, "undoing every step");
    if (!(ops_driver::snapshot(mesh) == ops_driver::snapshot(original)))
        finding("undoing every step did not give the mesh back");
}

}  // namespace sxk::fuzz
