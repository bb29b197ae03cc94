// The marker's options: what an application includes to use the tool "marker" (a plug-in's
// installed header, as sxk/plugins/NAME.hpp are). The marker paints: at each step, every element
// with a corner within `radius` of the tool's position (the axis-aligned cube of half-side
// radius, deformed positions) gets the element label `label`; one undoable step.
//
//     sxk::marker::Options marker;
//     marker.label = 7;
//     auto session = host.begin_tool(mesh, marker);
//     (*session)->step(pose);          // the elements near pose.position now have label 7
#pragma once

#include <cstdint>
#include <string_view>

#include "sxk/outcome.hpp"
#include "sxk/plugins/option_checks.hpp"

namespace sxk::marker {

struct Options {
    static constexpr std::string_view tool_name = "marker";  // what PluginHost::tool finds
    static constexpr std::uint32_t options_version = 1;      // bumped when the fields change

    int label = 1;
    double radius = 0.1;

    // What begin_tool refuses before a session begins, with a code: the message every plug-in's
    // options give for a number out of range ("marker: radius 0 is not in (0, 1e+300]").
    Outcome<Done> check() const {
        using namespace option_checks;
        return first_refusal({in(tool_name, "radius", radius, {0, 1e300, true, false})});
    }
};

}  // namespace sxk::marker
