// The mesh's mean edge length (sxk/quality.hpp).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "sxk/quality.hpp"
#include "sxk/traversal.hpp"

namespace sxk {

double mean_edge_length(const Mesh& mesh, Positions positions) {
    // each edge once: its sorted vertex pair packed into 64 bits, sorted and made unique (about
    // 7 pairs per tetrahedron: 1.5M for the 213k-tet femur, sorted in well under a second)
    std::vector<std::uint64_t> edges;
    const int k = mesh.element_vertex_count();
    edges.reserve(mesh.element_count() * static_cast<std::size_t>(k * (k - 1) / 2));
    for (const ElementId t : elements(mesh)) {
        const Simplex& s = mesh.simplex(t);
        for (int i = 0; i < k; ++i)
            for (int j = i + 1; j < k; ++j) {
                const std::uint64_t a = std::min(s.vertex(i), s.vertex(j));
                const std::uint64_t b = std::max(s.vertex(i), s.vertex(j));
                edges.push_back(a << 32 | b);
            }
    }
    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
    if (edges.empty()) return 0;
    const auto& at = positions == Positions::reference ? mesh.reference_positions() : mesh.deformed_positions();
    double sum = 0;
    for (const std::uint64_t e : edges) {
        const Point &p = at[static_cast<VertexId>(e >> 32)], &q = at[static_cast<VertexId>(e & 0xffffffffu)];
        sum += std::hypot(p[0] - q[0], p[1] - q[1], p[2] - q[2]);
    }
    return sum / static_cast<double>(edges.size());
}

}  // namespace sxk
