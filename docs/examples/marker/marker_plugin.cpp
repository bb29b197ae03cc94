// An example tool plug-in (docs/architecture.md "Where things go"): the tool "marker" of
// marker.hpp, offered through the plug-in's ToolFactory. A step is one transaction of the mesh's
// journal (ToolSession::step): it completes or the mesh is as before, and undo and redo take it
// back and again, with no stack of the tool's own.
#include <memory>
#include <string>

#include "marker.hpp"
#include "sxk/locate.hpp"
#include "sxk/plugin.hpp"
#include "sxk/tool_session.hpp"

namespace sxk::marker {
namespace {

class MarkerSession final : public ToolSession {
public:
    // The index follows the mesh's edits (it is a watcher): other tools may cut between steps.
    MarkerSession(Mesh& mesh, const Options& options)
        : ToolSession(mesh), m_options(options), m_index(mesh, Positions::deformed) {}

protected:
    Outcome<Done> apply(const ToolPose& pose, StepReport& report) override {
        const Point& x = pose.position;
        const double r = m_options.radius;
        // the index finds the elements near the tool: nothing in a step scans the whole mesh
        std::size_t marked = 0;
        for (const ElementId t : m_index.elements_with_vertex_in_box({x[0] - r, x[1] - r, x[2] - r},
                                                                     {x[0] + r, x[1] + r, x[2] + r}))
            if (mesh().label(t) != m_options.label) {
                mesh().set_label(t, m_options.label);  // journaled: the step can be taken back
                ++marked;
            }
        report.actions.push_back("marked " + std::to_string(marked) + " elements");
        return Done{};
    }

private:
    Options m_options;
    SpatialIndex m_index;
};

class MarkerPlugin final : public Plugin {
public:
    std::span<PluginCommand* const> commands() override { return {}; }
    ServiceOffer offer(std::string_view service_id) override {
        if (service_id == ToolFactory::service_id) return offer_of<ToolFactory>(&m_tools);
        return {};
    }

private:
    // begin_tool checks the name, the layout and Options::check, then makes the session
    ToolFactoryOf<Options> m_tools{
        [](Mesh& mesh, const Options& options, const ToolContext&) -> Outcome<std::unique_ptr<ToolSession>> {
            return std::unique_ptr<ToolSession>(std::make_unique<MarkerSession>(mesh, options));
        }};
};

}  // namespace
}  // namespace sxk::marker

SXK_PLUGIN(marker, sxk::marker::MarkerPlugin, "0.1.0", "marks the elements near a tool with a label (an example)");
