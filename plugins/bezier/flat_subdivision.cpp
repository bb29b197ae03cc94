// Roth's flatness split (flat_subdivision.hpp; thesis §6.4).
#include "flat_subdivision.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <iterator>
#include <stdexcept>
#include <string>

#include "de_casteljau.hpp"
#include "patch_scene.hpp"
#include "vector3.hpp"

namespace sxk::bezier {
namespace {


Barycentric midpoint(const Barycentric& a, const Barycentric& b) {
    return {(a[0] + b[0]) / 2, (a[1] + b[1]) / 2, (a[2] + b[2]) / 2};
}

// The memory budget shared by all patches' splits (they run in parallel).
struct Budget {
    std::size_t max_bytes;
    std::atomic<std::size_t> used{0};
    std::atomic<bool> exceeded{false};
};

// Splits `piece` (the patch over `corners`) until flat, appending the pieces depth first. The
// children are cut from the piece itself, in its own coordinates: the corner quarters by three
// convex corner moves, the middle one by middle_quarter (de_casteljau.hpp), O(n^3) and O(n^4)
// where cutting the middle quarters of the original patch at depth d needed the general blossom,
// O(n^5), 94% of sxk render's time on degree-40 patches. Every step is a convex combination
// (mostly an average), so rounding grows by about 3n steps per level, eight levels at most
// (smallest_flatness allows for it). The corners stay in the original patch's coordinates, exact
// in binary (dyadic). Returns early, keeping nothing more, once the budget is exceeded (by this
// split or another).
void split(std::uint32_t index, const std::array<Barycentric, 3>& corners, TriangularPatch piece,
           double max_height, int depth_left, Budget& budget, std::vector<SubPatch>& out) {
    if (budget.exceeded.load(std::memory_order_relaxed))
        return;
    if (depth_left == 0 || roth_height(piece) <= max_height) {
        const std::size_t bytes = leaf_bytes(piece.degree());
        if (budget.used.fetch_add(bytes, std::memory_order_relaxed) + bytes > budget.max_bytes) {
            budget.exceeded.store(true, std::memory_order_relaxed);
            return;
        }
        out.push_back(SubPatch{std::move(piece), index, corners});
        return;
    }
    const auto& [a, b, c] = corners;
    const Barycentric ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
    // counterclockwise like a, b, c (drawing in the header), so orientation is kept
    const std::array<std::array<Barycentric, 3>, 4> children{
        {{a, ab, ca}, {ab, b, bc}, {ca, bc, c}, {bc, ca, ab}}};
    // the same four in the piece's own coordinates
    constexpr Barycentric r{1, 0, 0}, s{0, 1, 0}, t{0, 0, 1}, rs{0.5, 0.5, 0}, st{0, 0.5, 0.5},
        tr{0.5, 0, 0.5};
    constexpr std::array<std::array<Barycentric, 3>, 3> local{
        {{r, rs, tr}, {rs, s, st}, {tr, st, t}}};
    for (std::size_t child = 0; child < 3; ++child)
        split(index, children[child],
              piece.subdivided(local[child][0], local[child][1], local[child][2]), max_height,
              depth_left - 1, budget, out);
    std::vector<Point> middle;
    NetScratch scratch;
    middle_quarter(piece.degree(), piece.control_points(), middle, scratch);
    split(index, children[3], TriangularPatch(piece.degree(), std::move(middle)), max_height,
          depth_left - 1, budget, out);
}

}  // namespace

std::size_t leaf_bytes(int degree) {
    return net_size(degree) * sizeof(Point) + 256;
}

SubdivisionTooLarge::SubdivisionTooLarge(std::size_t max_bytes, std::size_t pieces)
    : std::length_error("flat_subdivision: the pieces would take more than " +
                        std::to_string(max_bytes) + " bytes (" + std::to_string(pieces) +
                        " made when it stopped)"),
      m_max_bytes(max_bytes),
      m_pieces(pieces) {}

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
                                       double max_height, int max_depth, std::size_t max_bytes) {
    if (max_depth < 0)
        throw std::invalid_argument("flat_subdivision: max_depth " + std::to_string(max_depth) +
                                    " < 0");
    if (!(max_height >= 0))
        throw std::invalid_argument("flat_subdivision: max_height " + std::to_string(max_height) +
                                    " is negative or NaN");
    // patches are independent: split them in parallel, then concatenate in patch order
    std::vector<std::vector<SubPatch>> pieces(patches.size());
    Budget budget{max_bytes};
    tbb::parallel_for(std::size_t{0}, patches.size(), [&](std::size_t i) {
        const std::array<Barycentric, 3> domain{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
        split(static_cast<std::uint32_t>(i), domain, patches[i], max_height, max_depth, budget,
              pieces[i]);
    });
    std::size_t total = 0;
    for (const auto& list : pieces)
        total += list.size();
    if (budget.exceeded)
        throw SubdivisionTooLarge(max_bytes, total);
    std::vector<SubPatch> all;
    all.reserve(total);
    for (auto& list : pieces)
        std::move(list.begin(), list.end(), std::back_inserter(all));
    return all;
}

}  // namespace sxk::bezier
