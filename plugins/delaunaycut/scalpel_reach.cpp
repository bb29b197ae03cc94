// ScalpelReach (scalpel_reach.hpp): the box a scalpel must stay near.
#include "scalpel_reach.hpp"

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <limits>

#include "sxk/traversal.hpp"

namespace sxk::delaunaycut {

ScalpelReach::ScalpelReach(const Mesh& mesh, double mean_edge, std::size_t dimensions)
    : m_mean_edge(mean_edge), m_dimensions(dimensions) {
    m_low.fill(std::numeric_limits<double>::infinity());
    m_high.fill(-std::numeric_limits<double>::infinity());
    for (const ElementId t : elements(mesh))
        for (const VertexId v : mesh.simplex(t).vertices())
            for (std::size_t k = 0; k < m_dimensions; ++k) {
                m_low[k] = std::min(m_low[k], mesh.deformed(v)[k] - mean_edge);
                m_high[k] = std::max(m_high[k], mesh.deformed(v)[k] + mean_edge);
            }
}

std::optional<std::string> ScalpelReach::too_far(const Point& p, std::string_view what) const {
    double off = 0;
    for (std::size_t k = 0; k < m_dimensions; ++k) off = std::max({off, m_low[k] - p[k], p[k] - m_high[k]});
    if (!(off > farthest * m_mean_edge)) return std::nullopt;
    // the coordinates as given (shortest round-trip text), the distances to three digits
    std::string at;
    for (std::size_t k = 0; k < m_dimensions; ++k) {
        char text[32];
        at += (k ? ", " : "") + std::string(text, std::to_chars(text, text + sizeof text, p[k]).ptr);
    }
    char distances[96];
    std::snprintf(distances, sizeof distances, "%.3g from the mesh, more than 1e12 mean edges (%.3g)", off,
                  farthest * m_mean_edge);
    return "delaunaycut: " + std::string(what) + " at (" + at + ") is " + distances +
           ": so far away a movement cannot be placed on the mesh in doubles";
}

}  // namespace sxk::delaunaycut
