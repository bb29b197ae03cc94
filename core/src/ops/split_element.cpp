// split_element (thesis §3.2 subdivision; connectivity edit by §7.3 replace-elements).
#include "sxk/ops/split_element.hpp"

#include <array>

#include "ops/split_parents.hpp"

namespace sxk {

Outcome<SplitResult> split_element(Mesh& mesh, ElementId t, std::span<const double> weights) {
    if (!mesh.is_element(t))
        return Refusal{RefusalCode::not_found,
                       "split_element: " + std::to_string(t) + " is not an element"};
    const auto count = static_cast<std::size_t>(mesh.element_vertex_count());
    std::vector<double> normalized(weights.begin(), weights.end());
    if (normalized.empty()) normalized.assign(count, 1.0);
    if (normalized.size() != count)
        return Refusal{RefusalCode::bad_argument,
                       "split_element: needs " + std::to_string(count) + " weights, got " +
                       std::to_string(weights.size())};
    if (!detail::weights_inside(normalized))
        return Refusal{
            RefusalCode::bad_argument,
            "split_element: the weights must all be > 0 (the new vertex inside the element)"};
    double sum = 0;
    for (const double w : normalized) sum += w;
    for (double& w : normalized) w /= sum;

    const Simplex tau = mesh.simplex(t);
    const std::array<ElementId, 1> parent{t};
    return detail::split_parents(mesh, parent, tau.vertices(), normalized, "split_element");
}

}  // namespace sxk
