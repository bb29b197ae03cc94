// The incision's distance from the scalpel's path (incision_distance.hpp).
#include "incision_distance.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "sxk/locate.hpp"

namespace sxk::delaunaycut {

double distance_to_path(const Point& p, std::span<const Point> path) {
    double nearest = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < path.size(); ++i) {
        const Point& a = path[i];
        const Point& b = i + 1 < path.size() ? path[i + 1] : path[i];
        const double dx = b[0] - a[0], dy = b[1] - a[1];
        const double length2 = dx * dx + dy * dy;
        const double s = length2 > 0 ? std::clamp(((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / length2, 0.0, 1.0) : 0;
        nearest = std::min(nearest, std::hypot(p[0] - a[0] - s * dx, p[1] - a[1] - s * dy));
    }
    return nearest;
}

namespace {

template <class Distance>
IncisionDistance measure(const Mesh& mesh, int cut_label, const Distance& distance) {
    std::vector<VertexId> nodes;
    mesh.for_each_boundary_face([&](FaceId f) {
        const Simplex edge = mesh.face_simplex(f);
        if (const auto label = mesh.face_label(edge); label && *label == cut_label)
            nodes.insert(nodes.end(), edge.vertices().begin(), edge.vertices().end());
    });
    std::sort(nodes.begin(), nodes.end());
    nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
    IncisionDistance result;
    result.nodes = nodes.size();
    for (const VertexId v : nodes) {
        const double d = distance(mesh.deformed(v));
        result.farthest = std::max(result.farthest, d);
        result.mean += d / static_cast<double>(nodes.size());
    }
    return result;
}

}  // namespace

IncisionDistance incision_distance(const Mesh& mesh, std::span<const Point> path, int cut_label) {
    return measure(mesh, cut_label, [&](const Point& p) { return distance_to_path(p, path); });
}

double distance_to_sweep(const Point& p, std::span<const Blade> blades) {
    double nearest = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < blades.size(); ++i) {
        const Blade& a = blades[i];
        const Blade& b = i + 1 < blades.size() ? blades[i + 1] : blades[i];
        for (const std::array<Point, 3>& t : {std::array<Point, 3>{a.handle, a.tip, b.tip},
                                              std::array<Point, 3>{a.handle, b.tip, b.handle}}) {
            const std::array<double, 3> w = nearest_on_triangle(t[0], t[1], t[2], p);
            Point on{};
            for (std::size_t j = 0; j < 3; ++j)
                for (std::size_t k = 0; k < 3; ++k) on[k] += w[j] * t[j][k];
            nearest = std::min(nearest, std::hypot(p[0] - on[0], p[1] - on[1], p[2] - on[2]));
        }
    }
    return nearest;
}

IncisionDistance incision_distance(const Mesh& mesh, std::span<const Blade> blades, int cut_label) {
    return measure(mesh, cut_label, [&](const Point& p) { return distance_to_sweep(p, blades); });
}

}  // namespace sxk::delaunaycut
