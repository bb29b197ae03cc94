// The degeneracy plug-in's tool "degeneracies" (options: BrushOptions, sxk/plugins/degeneracy.hpp):
// a brush that, at each step, removes the degenerate elements having a vertex
// within `radius` of the tool's position (the axis-aligned cube of half-side radius, found with a
// SpatialIndex of the session), by remove_degeneracies on those candidates. Thesis §3.3: flat
// elements are removed right after each cut step, where the tool was; as a ToolSession each
// step is one transaction the application can undo.
//
//     auto brush = host.begin_tool(mesh, sxk::degeneracy::BrushOptions{.radius = 0.05});
//     auto report = (*brush)->step(pose);   // report->actions: "3 degenerate, 3 removed (...)"
#pragma once

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

}  // namespace sxk::degeneracy
