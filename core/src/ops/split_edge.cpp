// split_edge (thesis §3.2 subdivision; connectivity edit by §7.3 replace-elements).
#include "sxk/ops/split_edge.hpp"

#include <array>

#include "ops/split_collapse_checks.hpp"

namespace sxk {

Outcome<SplitResult> split_edge(Mesh& mesh, VertexId a, VertexId b, double t) {
    if (a >= mesh.vertex_count() || b >= mesh.vertex_count())
        return Refusal{"split_edge: " + std::to_string(a >= mesh.vertex_count() ? a : b) +
                       " is not a vertex"};
    if (a == b) return Refusal{"split_edge: the two ends are the same vertex"};
    // negated comparison so that NaN is refused too
    if (!(t > 0 && t < 1)) return Refusal{"split_edge: t = " + std::to_string(t) + " is not in (0,1)"};
    const std::vector<ElementId> parents = detail::elements_with_edge(mesh, a, b);
    if (parents.empty())
        return Refusal{"split_edge: " + to_text(Simplex(+1, {a, b})) +
                       " is not an edge"};

    const std::array<VertexId, 2> ends{a, b};
    const std::array<double, 2> weights{1 - t, t};
    const auto [reference, deformed] = detail::interpolate(mesh, ends, weights);
    // The new vertex will get id vertex_count(); checks run with it at its future position so
    // that a refusal leaves the mesh without the vertex.
    const auto m = static_cast<VertexId>(mesh.vertex_count());
    const detail::MovedVertex moved{m, reference, deformed};

    std::vector<Simplex> children;
    std::vector<ElementId> parent_of_child;
    std::vector<int> labels;
    for (const ElementId parent : parents) {
        const Simplex& tau = mesh.simplex(parent);
        for (const VertexId replaced : ends) {
            children.push_back(tau.substituted(replaced, m));
            parent_of_child.push_back(parent);
            labels.push_back(mesh.label(parent));
        }
    }
    if (Refusal r = detail::refuse_bad_children(mesh, children, parent_of_child, moved, "split_edge");
        !r.reason.empty())
        return r;

    // From here nothing can refuse on a valid mesh: the children only use faces of the parents
    // and faces through the fresh vertex m, which no other element has (invariant 7.4 holds).
    mesh.add_vertex(reference, deformed);
    auto result = mesh.replace_elements(parents, children, labels);
    if (!result.ok()) return Refusal{"split_edge: " + result.reason()};
    return SplitResult{m, std::move(*result)};
}

}  // namespace sxk
