// The coarsest uniform tessellation within a geometric error (patch_scene.hpp).
//
// The error of `segments` is measured, not bounded: per small triangle of the tessellation
// (tessellate.cpp's grid), the distance between the patch and the flat triangle at its three
// edge midpoints and its centroid, where the interpolation error of a nearly quadratic piece
// peaks. Every grid edge is an edge of exactly one upward cell, so each midpoint is evaluated
// once: about 2.5 segments^2 evaluations per patch.
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>

#include "de_casteljau.hpp"
#include "patch_scene.hpp"
#include "vector3.hpp"

namespace sxk::bezier {
namespace {


Point average(const Point& a, const Point& b) {
    return {(a[0] + b[0]) / 2, (a[1] + b[1]) / 2, (a[2] + b[2]) / 2};
}
Point average(const Point& a, const Point& b, const Point& c) {
    return {(a[0] + b[0] + c[0]) / 3, (a[1] + b[1] + c[1]) / 3, (a[2] + b[2] + c[2]) / 3};
}

// The largest deviation of one patch from its tessellation with `segments` segments.
double patch_error(const TriangularPatch& patch, int segments) {
    // de Casteljau in a buffer reused for every point (TriangularPatch::evaluate copies the net
    // each time)
    const std::span<const Point> net = patch.control_points();
    std::vector<Point> scratch(net.size());
    const auto evaluate = [&](const Barycentric& x) {
        std::copy(net.begin(), net.end(), scratch.begin());
        return evaluate_in_place(patch.degree(), scratch.data(), x);
    };
    const double m = segments;
    // the domain point at grid coordinates (j, k), which may be fractional
    const auto at = [&](double j, double k) { return Barycentric{(m - j - k) / m, j / m, k / m}; };
    std::vector<Point> grid(TriangularPatch::index(segments, 0, segments) + 1);
    for (int k = 0; k <= segments; ++k)
        for (int j = 0; j + k <= segments; ++j)
            grid[TriangularPatch::index(segments, j, k)] = evaluate(at(j, k));
    const auto vertex = [&](int j, int k) -> const Point& {
        return grid[TriangularPatch::index(segments, j, k)];
    };
    double error = 0;
    for (int k = 0; k < segments; ++k)
        for (int j = 0; j + k < segments; ++j) {
            const Point &a = vertex(j, k), &b = vertex(j + 1, k), &c = vertex(j, k + 1);
            error = std::max({error, distance(evaluate(at(j + 0.5, k)), average(a, b)),
                              distance(evaluate(at(j, k + 0.5)), average(a, c)),
                              distance(evaluate(at(j + 0.5, k + 0.5)), average(b, c)),
                              distance(evaluate(at(j + 1.0 / 3, k + 1.0 / 3)), average(a, b, c))});
            if (j + k + 1 < segments) {
                const Point& d = vertex(j + 1, k + 1);
                error = std::max(
                    error, distance(evaluate(at(j + 2.0 / 3, k + 2.0 / 3)), average(b, d, c)));
            }
        }
    return error;
}

double tessellation_error(const std::vector<TriangularPatch>& patches, int segments) {
    std::vector<double> errors(patches.size());
    tbb::parallel_for(std::size_t{0}, patches.size(),
                      [&](std::size_t p) { errors[p] = patch_error(patches[p], segments); });
    return errors.empty() ? 0 : *std::max_element(errors.begin(), errors.end());
}

}  // namespace

int segments_for_error(const std::vector<TriangularPatch>& patches, double max_error, int max_segments) {
    if (!(max_error > 0) || !std::isfinite(max_error))
        throw std::invalid_argument("segments_for_error: max_error " + std::to_string(max_error) +
                                    " is not a positive finite number");
    if (patches.empty())
        return 1;
    // the largest count tessellate can index (2^32 vertices)
    const double vertices_per_count =
        static_cast<double>(std::numeric_limits<std::uint32_t>::max()) /
        static_cast<double>(patches.size());
    const int indexable = static_cast<int>(std::min(std::sqrt(2 * vertices_per_count) - 2, 1e9));
    const int largest = std::min(indexable, std::max(1, max_segments));

    // Find lo (too coarse, or 0) and hi (fine enough) with hi = lo + 1. The error of a smooth
    // patch falls like segments^-2 once the cells are small, so from a coarse count that fails
    // the next guess is lo sqrt(error(lo) / max_error); doubling while the counts are small and
    // bisection after two guesses keep the search safe where that model is wrong.
    int lo = 0;
    double lo_error = std::numeric_limits<double>::infinity();
    std::optional<int> hi;
    int guesses = 0;
    while (!hi || *hi - lo > 1) {
        int next;
        if (lo < 8 || !std::isfinite(lo_error)) {
            next = std::max(1, 2 * lo);
            if (hi)
                next = std::min(next, (lo + *hi) / 2 > lo ? (lo + *hi) / 2 : lo + 1);
        } else if (guesses < 2 || !hi) {
            const double predicted = std::ceil(lo * std::sqrt(lo_error / max_error));
            next = static_cast<int>(std::min(predicted, static_cast<double>(largest) + 1));
            // without a fine-enough count yet, step at least an eighth up
            next = std::max(next, hi ? lo + 1 : lo + std::max(1, lo / 8));
            if (hi)
                next = std::min(next, *hi - 1);
            ++guesses;
        } else {
            next = lo + (*hi - lo) / 2;
        }
        if (next > largest && largest < indexable) return largest;  // the caller's bound
        if (next > largest)
            throw std::invalid_argument("segments_for_error: error " + std::to_string(max_error) +
                                        " needs more than " + std::to_string(largest) +
                                        " segments per patch (beyond 2^32 vertices)");
        const double error = tessellation_error(patches, next);
        if (error <= max_error)
            hi = next;
        else
            lo = next, lo_error = error;
    }
    return *hi;
}

}  // namespace sxk::bezier
