// Boxes (patch_scene.hpp): of points, of patches' control points, where a ray enters one, and
// the smallest flatness a box's rounding resolves.
#include "patch_scene.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "vector3.hpp"

namespace sxk::bezier {

double Box::diagonal() const { return norm(minus(upper, lower)); }

Box box_of(std::span<const Point> points) {
    if (points.empty()) return {};
    constexpr double huge = std::numeric_limits<double>::infinity();
    Box box{{huge, huge, huge}, {-huge, -huge, -huge}};
    for (const Point& p : points)
        for (std::size_t q = 0; q < 3; ++q)
            box.lower[q] = std::min(box.lower[q], p[q]), box.upper[q] = std::max(box.upper[q], p[q]);
    return box;
}

Box box_of(const std::vector<TriangularPatch>& patches) {
    if (patches.empty()) return {};
    Box box = box_of(patches.front().control_points());
    for (const TriangularPatch& patch : patches) {
        const Box own = box_of(patch.control_points());
        for (std::size_t q = 0; q < 3; ++q)
            box.lower[q] = std::min(box.lower[q], own.lower[q]), box.upper[q] = std::max(box.upper[q], own.upper[q]);
    }
    return box;
}

double smallest_flatness(const Box& box) {
    const double diagonal = box.diagonal();
    if (!(diagonal > 0))
        return 0;
    double largest_coordinate = 0;
    for (std::size_t q = 0; q < 3; ++q)
        largest_coordinate =
            std::max({largest_coordinate, std::abs(box.lower[q]), std::abs(box.upper[q])});
    return 1e-12 * (diagonal + largest_coordinate) / diagonal;
}

std::optional<double> entry(const Ray& ray, const Box& box) {
    double enter = ray.t_near, leave = ray.t_far;
    for (std::size_t q = 0; q < 3; ++q) {
        if (ray.direction[q] == 0) {
            if (ray.origin[q] < box.lower[q] || ray.origin[q] > box.upper[q])
                return std::nullopt;
            continue;
        }
        const double a = (box.lower[q] - ray.origin[q]) / ray.direction[q];
        const double b = (box.upper[q] - ray.origin[q]) / ray.direction[q];
        enter = std::max(enter, std::min(a, b));
        leave = std::min(leave, std::max(a, b));
    }
    if (!(enter <= leave))
        return std::nullopt;
    return enter;
}
}  // namespace sxk::bezier
