// Shape measures in the measured positions (thesis §3.2.3): aspect ratio and class.
#include <algorithm>
#include <array>

#include "removal_steps.hpp"
#include "sxk/quality.hpp"

namespace sxk::degeneracy {

namespace detail {

double aspect_ratio_of(const Mesh& mesh, std::span<const VertexId> vertices, Positions positions) {
    std::array<Point, 4> points{};
    for (std::size_t i = 0; i < vertices.size(); ++i) points[i] = position(mesh, vertices[i], positions);
    return sxk::aspect_ratio(std::span<const Point>(points.data(), vertices.size()));
}

double element_aspect_ratio(const Mesh& mesh, ElementId t, Positions positions) {
    const Simplex& tau = mesh.simplex(t);
    return aspect_ratio_of(mesh, tau.vertices(), positions);
}

DegenerateClass classify_element(const Mesh& mesh, ElementId t, const Options& options) {
    const Simplex& tau = mesh.simplex(t);
    std::array<Point, 4> points{};
    for (int i = 0; i < tau.count(); ++i)
        points[static_cast<std::size_t>(i)] = position(mesh, tau.vertex(i), options.positions);
    const std::span<const Point> p(points.data(), static_cast<std::size_t>(tau.count()));
    if (tau.count() == 4)
        return classify_tetrahedron(p, DegeneracyThresholds{options.aspect_ratio, options.large_angle});
    if (sxk::aspect_ratio(p) >= options.aspect_ratio) return DegenerateClass::none;
    const auto angles = triangle_angles(p);
    return std::any_of(angles.begin(), angles.end(), [&](double a) { return a > options.large_angle; })
               ? DegenerateClass::cap
               : DegenerateClass::needle;
}

Foot foot_on_line(const Point& a, const Point& b, const Point& p) {
    const Point u = minus(b, a);
    const double length2 = dot(u, u);
    Foot foot;
    foot.s = length2 > 0 ? dot(minus(p, a), u) / length2 : 0;
    const Point f{a[0] + foot.s * u[0], a[1] + foot.s * u[1], a[2] + foot.s * u[2]};
    foot.distance = distance(p, f);
    return foot;
}

}  // namespace detail


DegenerateClass classify(const Mesh& mesh, ElementId t, const Options& options) {
    return detail::classify_element(mesh, t, options);
}

}  // namespace sxk::degeneracy
