// The degeneracy brush (degeneracy_brush.hpp): a ToolSession removing flat elements near the tool.
#include "degeneracy_brush.hpp"

#include <algorithm>
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

}  // namespace sxk::degeneracy
