// Uniform tessellation of triangular patches (patch_scene.hpp).
//
//   k                            each patch's domain cut into segments^2 triangles over the
//   ^ (0,2)                      grid points (j, k) = segments (s, t); vertex (j, k) is the
//   |  | \                       patch at ((segments - j - k), j, k) / segments. Per cell,
//   | (0,1)-(1,1)                in rows of increasing k and j:
//   |  | \  | \                    up   (j, k), (j+1, k), (j, k+1)
//   | (0,0)-(1,0)-(2,0) -> j       down (j+1, k), (j+1, k+1), (j, k+1)  (when j + k < segments - 1)
//                                both counterclockwise like the domain (1,0,0), (0,1,0), (0,0,1),
//                                so their right-hand normals agree with TriangularPatch::normal.
#include <tbb/parallel_for.h>

#include <algorithm>
#include <limits>
#include <span>
#include <stdexcept>
#include <string>

#include "de_casteljau.hpp"
#include "patch_scene.hpp"

namespace sxk::bezier {

TriangleSoup tessellate(const std::vector<TriangularPatch>& patches, int segments) {
    if (segments < 1)
        throw std::invalid_argument("tessellate: segments " + std::to_string(segments) + " < 1");
    const auto m = static_cast<std::size_t>(segments);
    const std::size_t vertices_per_patch = (m + 1) * (m + 2) / 2, triangles_per_patch = m * m;
    if (patches.size() * vertices_per_patch > std::numeric_limits<std::uint32_t>::max())
        throw std::invalid_argument("tessellate: " + std::to_string(patches.size()) +
                                    " patches at " + std::to_string(segments) +
                                    " segments exceed 2^32 vertices");
    TriangleSoup soup;
    soup.vertices.resize(patches.size() * vertices_per_patch);
    soup.triangles.resize(patches.size() * triangles_per_patch);
    tbb::parallel_for(std::size_t{0}, patches.size(), [&](std::size_t p) {
        // de Casteljau in a buffer reused for every point (TriangularPatch::evaluate copies the net
        // each time)
        const std::span<const Point> net = patches[p].control_points();
        std::vector<Point> scratch(net.size());
        const auto evaluate = [&](const Barycentric& x) {
            std::copy(net.begin(), net.end(), scratch.begin());
            return evaluate_in_place(patches[p].degree(), scratch.data(), x);
        };
        const auto first = static_cast<std::uint32_t>(p * vertices_per_patch);
        const auto vertex = [&](std::size_t j, std::size_t k) {
            return first + static_cast<std::uint32_t>(TriangularPatch::index(
                               segments, static_cast<int>(j), static_cast<int>(k)));
        };
        for (std::size_t k = 0; k <= m; ++k)
            for (std::size_t j = 0; j + k <= m; ++j)
                soup.vertices[vertex(j, k)] = evaluate({static_cast<double>(m - j - k) / segments,
                                                        static_cast<double>(j) / segments,
                                                        static_cast<double>(k) / segments});
        std::size_t triangle = p * triangles_per_patch;
        for (std::size_t k = 0; k < m; ++k)
            for (std::size_t j = 0; j + k < m; ++j) {
                soup.triangles[triangle++] = {vertex(j, k), vertex(j + 1, k), vertex(j, k + 1)};
                if (j + k + 1 < m)
                    soup.triangles[triangle++] = {vertex(j + 1, k), vertex(j + 1, k + 1),
                                                  vertex(j, k + 1)};
            }
    });
    return soup;
}

}  // namespace sxk::bezier
