// Roth's flatness split (flat_subdivision.hpp; thesis §6.4).
#include "flat_subdivision.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <stdexcept>
#include <string>

#include "patch_scene.hpp"
#include "vector3.hpp"

namespace sxk::bezier {
namespace {


Barycentric midpoint(const Barycentric& a, const Barycentric& b) {
    return {(a[0] + b[0]) / 2, (a[1] + b[1]) / 2, (a[2] + b[2]) / 2};
}

// Splits `original` over `corners` until flat, appending the pieces depth first. The pieces are
// always cut from the original patch (not from their parent): the corners are dyadic
// barycentric points, exact in binary, so no rounding accumulates over the levels.
void split(const TriangularPatch& original, std::uint32_t index,
           const std::array<Barycentric, 3>& corners, TriangularPatch piece, double max_height,
           int depth_left, std::vector<SubPatch>& out) {
    if (depth_left == 0 || roth_height(piece) <= max_height) {
        out.push_back(SubPatch{std::move(piece), index, corners});
        return;
    }
    const auto& [a, b, c] = corners;
    const Barycentric ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
    // counterclockwise like a, b, c (drawing in the header), so orientation is kept
    const std::array<std::array<Barycentric, 3>, 4> children{
        {{a, ab, ca}, {ab, b, bc}, {ca, bc, c}, {bc, ca, ab}}};
    for (const auto& child : children)
        split(original, index, child, original.subdivided(child[0], child[1], child[2]), max_height,
              depth_left - 1, out);
}

}  // namespace

double roth_height(const TriangularPatch& patch) {
    const int n = patch.degree();
    const std::span<const Point> points = patch.control_points();
    const Point& corner_r = patch.control_point(0, 0);  // b_n00
    const Point& corner_s = patch.control_point(n, 0);  // b_0n0
    const Point& corner_t = patch.control_point(0, n);  // b_00n
    Point normal = cross(minus(corner_s, corner_r), minus(corner_t, corner_r));
    double length = std::sqrt(dot(normal, normal));
    const double box = box_of(points).diagonal();
    // No plane through the corners (coincident or collinear corner points, up to rounding): the
    // extent along any unit direction still bounds the patch in a slab, so take the surface's
    // own normal at the centroid (defined next to a collapsed corner too); the box diagonal
    // bounds every extent when even that is missing.
    if (!(length > 1e-12 * box * box)) {
        normal = patch.normal({1.0 / 3, 1.0 / 3, 1.0 / 3});
        length = std::sqrt(dot(normal, normal));
        if (!(length > 0))
            return box;
    }
    double highest = 0, lowest = 0;
    for (const Point& p : points) {
        const double height = dot(normal, minus(p, corner_r)) / length;
        highest = std::max(highest, height);
        lowest = std::min(lowest, height);
    }
    return highest - lowest;
}

std::vector<SubPatch> flat_subdivision(const std::vector<TriangularPatch>& patches,
                                       double max_height, int max_depth) {
    if (max_depth < 0)
        throw std::invalid_argument("flat_subdivision: max_depth " + std::to_string(max_depth) +
                                    " < 0");
    if (!(max_height >= 0))
        throw std::invalid_argument("flat_subdivision: max_height " + std::to_string(max_height) +
                                    " is negative or NaN");
    // patches are independent: split them in parallel, then concatenate in patch order
    std::vector<std::vector<SubPatch>> pieces(patches.size());
    tbb::parallel_for(std::size_t{0}, patches.size(), [&](std::size_t i) {
        const std::array<Barycentric, 3> domain{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
        split(patches[i], static_cast<std::uint32_t>(i), domain, patches[i], max_height, max_depth,
              pieces[i]);
    });
    std::size_t total = 0;
    for (const auto& list : pieces)
        total += list.size();
    std::vector<SubPatch> all;
    all.reserve(total);
    for (auto& list : pieces)
        std::move(list.begin(), list.end(), std::back_inserter(all));
    return all;
}

}  // namespace sxk::bezier
