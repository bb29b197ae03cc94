// The degeneracy brush (degeneracy_brush.hpp): a ToolSession removing flat elements near the tool.
#include "degeneracy_brush.hpp"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <array>
#include <vector>

namespace sxk::degeneracy {

DegeneracyBrush::DegeneracyBrush(Mesh& mesh, double radius, const Options& options)
    : ToolSession(mesh), m_radius(radius), m_options(options), m_index(mesh, options.positions) {}

Outcome<Done> DegeneracyBrush::apply(const ToolPose& pose, StepReport& report) {
    const Point& x = pose.position;
    const Point low{x[0] - m_radius, x[1] - m_radius, x[2] - m_radius};
    const Point high{x[0] + m_radius, x[1] + m_radius, x[2] + m_radius};
    const std::vector<ElementId> candidates = m_index.elements_with_vertex_in_box(low, high);
    if (candidates.empty()) {
        report.actions.push_back("no element within the brush");
        return Done{};
    }
    const auto removed = remove_degeneracies(mesh(), candidates, m_options);
    if (!removed) return removed.refusal().prefixed("degeneracy brush: ");
    const Report& r = *removed;
    report.actions.push_back(std::to_string(candidates.size()) + " elements under the brush, " +
                             std::to_string(r.found) + " degenerate, " + std::to_string(r.found - r.remaining) +
                             " removed (" + std::to_string(r.collapses) + " collapses, " +
                             std::to_string(r.splits) + " splits, " + std::to_string(r.flips) + " flips, " +
                             std::to_string(r.peeled) + " peeled, " + std::to_string(r.cut_free) + " cut free)");
    return Done{};
}

std::span<const std::string_view> brush_tools() {
    static constexpr std::array<std::string_view, 1> tools{"degeneracies"};
    return tools;
}

Outcome<std::unique_ptr<ToolSession>> begin_brush(std::string_view tool, Mesh& mesh,
                                                  std::span<const std::string> options) {
    if (tool != "degeneracies")
        return Refusal{RefusalCode::not_found,
                       "no tool called " + std::string(tool) + " in degeneracy (it has: degeneracies)"};
    CLI::App app("degeneracies brush", "degeneracies");
    double radius = 0;
    Options removal;
    bool no_cut_free = false;
    std::string positions = "reference";
    app.add_option("--radius", radius, "Half-side of the brush's cube")->required();
    app.add_option("--aspect", removal.aspect_ratio, "Aspect ratio threshold, 0 < a < 1");
    app.add_option("--angle", removal.large_angle, "Large angle threshold in radians");
    app.add_flag("--no-cut-free", no_cut_free, "Leave what no collapse, flip or peel removes");
    app.add_option("--positions", positions, "reference or deformed")
        ->check(CLI::IsMember({"reference", "deformed"}));
    std::vector<std::string> arguments(options.rbegin(), options.rend());  // CLI11 parses from the back
    try {
        app.parse(arguments);
    } catch (const CLI::ParseError& error) {
        return Refusal{RefusalCode::bad_argument, std::string("degeneracies brush: ") + error.what()};
    }
    if (!(radius > 0))
        return Refusal{RefusalCode::bad_argument,
                       "degeneracies brush: --radius must be positive, not " + std::to_string(radius)};
    removal.cut_free = !no_cut_free;
    removal.positions = positions == "deformed" ? Positions::deformed : Positions::reference;
    return std::unique_ptr<ToolSession>(std::make_unique<DegeneracyBrush>(mesh, radius, removal));
}

}  // namespace sxk::degeneracy
