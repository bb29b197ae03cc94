// The degeneracy plug-in's tool, offered through its ToolFactory (sxk/tool_session.hpp) as
// "degeneracies": a brush that, at each step, removes the degenerate elements having a vertex
// within `radius` of the tool's position (the axis-aligned cube of half-side radius, found with a
// SpatialIndex of the session), by remove_degeneracies on those candidates. Thesis §3.3: flat
// elements are removed right after each cut step, where the tool was; as a ToolSession each
// step is one transaction the application can undo.
//
//     auto factory = host.service<sxk::ToolFactory>("degeneracy");
//     auto brush = (*factory)->begin("degeneracies", mesh, {"--radius", "0.05"});
//     auto report = (*brush)->step(pose);   // report->actions: "3 degenerate, 3 removed (...)"
#pragma once

#include <memory>
#include <span>
#include <string>
#include <string_view>

#include "remove_degeneracies.hpp"
#include "sxk/locate.hpp"
#include "sxk/tool_session.hpp"

namespace sxk::degeneracy {

class DegeneracyBrush final : public ToolSession {
public:
    // radius > 0; the index is over options.positions, where the shapes are measured.
    DegeneracyBrush(Mesh& mesh, double radius, const Options& options);

protected:
    Outcome<Done> apply(const ToolPose& pose, StepReport& report) override;

private:
    double m_radius;
    Options m_options;
    SpatialIndex m_index;
};

// The tools of the plug-in's ToolFactory: {"degeneracies"}.
std::span<const std::string_view> brush_tools();

// A brush session from command-line style options: --radius R (required, > 0), --aspect A,
// --angle RADIANS, --no-cut-free, --positions reference|deformed. Refuses an unknown tool
// ("no tool called T in degeneracy (it has: degeneracies)") and bad options with CLI11's message.
Outcome<std::unique_ptr<ToolSession>> begin_brush(std::string_view tool, Mesh& mesh,
                                                  std::span<const std::string> options);

}  // namespace sxk::degeneracy
