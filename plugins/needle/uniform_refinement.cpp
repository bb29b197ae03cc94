// Uniform refinement to h_start (uniform_refinement.hpp).
#include "uniform_refinement.hpp"

#include <cmath>
#include <string>

#include "sxk/locate.hpp"
#include "sxk/ops/refine_around.hpp"
#include "sxk/ops/refine_around_tetrahedra.hpp"
#include "shaft_refinement.hpp"

namespace sxk::needle {

namespace {

double longest_edge(const Mesh& mesh, ElementId t) {
    const Simplex element = mesh.simplex(t);
    const auto v = element.vertices();
    double longest = 0;
    for (std::size_t i = 0; i < v.size(); ++i)
        for (std::size_t j = i + 1; j < v.size(); ++j) {
            const Point& a = mesh.reference(v[i]);
            const Point& b = mesh.reference(v[j]);
            longest = std::max(longest, std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]));
        }
    return longest;
}

}  // namespace

Outcome<std::size_t> refine_uniformly(Mesh& mesh, double h) {
    if (!(std::isfinite(h) && h > 0))
        return Refusal{RefusalCode::bad_argument, "refine_uniformly: h = " + std::to_string(h) + " is not positive"};
    const SpatialIndex index(mesh, Positions::reference);
    const double limit = bisection_edge_limit(mesh, h);
    std::size_t added = 0;
    // ids of new elements come after (or reuse) old ones: sweep until a pass refines nothing
    for (bool refined = true; refined;) {
        refined = false;
        for (ElementId t = 0; t < mesh.element_capacity(); ++t) {
            if (!mesh.is_element(t) || longest_edge(mesh, t) <= limit) continue;
            Point centre{0, 0, 0};
            const Simplex element = mesh.simplex(t);
            for (const VertexId v : element.vertices())
                for (int k = 0; k < 3; ++k) centre[k] += mesh.reference(v)[k] / double(element.vertices().size());
            const std::size_t before = mesh.vertex_count();
            if (mesh.topological_dimension() == 2) {
                if (auto done = refine_around(mesh, centre, limit, index, t); !done) return done.refusal();
            } else if (auto done = refine_around_tetrahedra(mesh, centre, limit, index); !done) {
                return done.refusal();
            }
            added += mesh.vertex_count() - before;
            refined = refined || mesh.vertex_count() > before;
        }
    }
    return added;
}

}  // namespace sxk::needle
