// Uniform refinement to h_start (uniform_refinement.hpp).
#include "uniform_refinement.hpp"

#include <array>
#include <cmath>
#include <span>
#include <string>

#include "sxk/locate.hpp"
#include "sxk/ops/refine_around.hpp"
#include "sxk/ops/refine_around_tetrahedra.hpp"
#include "shaft_refinement.hpp"

namespace sxk::needle {

Outcome<std::size_t> refine_uniformly(Mesh& mesh, double h) {
    if (!(std::isfinite(h) && h > 0))
        return Refusal{RefusalCode::bad_argument, "refine_uniformly: h = " + std::to_string(h) + " is not positive"};
    const SpatialIndex index(mesh, Positions::reference);
    const double limit = bisection_edge_limit(mesh, h);
    std::size_t added = 0;
    // ids of new elements come after (or reuse) old ones: sweep until a pass refines nothing; the
    // refinement around an element's centre does nothing when that element is of size h already
    const std::size_t corners = static_cast<std::size_t>(mesh.element_vertex_count());
    std::array<double, 4> weights{};
    weights.fill(1.0 / static_cast<double>(corners));
    const std::span<const double> centre_weights(weights.data(), corners);
    for (bool refined = true; refined;) {
        refined = false;
        for (ElementId t = 0; t < mesh.element_capacity(); ++t) {
            if (!mesh.is_element(t)) continue;
            const Simplex element = mesh.simplex(t);
            const Point centre = mesh.interpolated_positions(element.vertices(), centre_weights).first;
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
