// load_shares: equal parts, or parts by boundary area (load_shares.hpp).
#include "load_shares.hpp"

#include <algorithm>
#include <cmath>

namespace sxk::elasticity {
namespace {

// The area of boundary face s (a triangle in space) or its length (an edge in the plane).
double measure(const Mesh& mesh, const Simplex& s) {
    const Point& a = mesh.reference(s.vertex(0));
    const Point& b = mesh.reference(s.vertex(1));
    const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    if (s.count() == 2)
        return std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
    const Point& c = mesh.reference(s.vertex(2));
    const double v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    const double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
                         u[0] * v[1] - u[1] * v[0]};
    return 0.5 * std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
}

}  // namespace

Outcome<std::vector<double>> load_shares(const Mesh& mesh, std::span<const VertexId> vertices,
                                         Share share) {
    std::vector<double> parts(vertices.size(),
                              vertices.empty() ? 0.0 : 1.0 / static_cast<double>(vertices.size()));
    if (share == Share::equal)
        return parts;
    std::fill(parts.begin(), parts.end(), 0.0);
    auto index = [&](VertexId v) -> std::ptrdiff_t {
        const auto it = std::lower_bound(vertices.begin(), vertices.end(), v);
        return it != vertices.end() && *it == v ? it - vertices.begin() : -1;
    };
    double total = 0;
    mesh.for_each_boundary_face([&](FaceId f) {
        const Simplex s = mesh.face_simplex(f);
        for (int j = 0; j < s.count(); ++j)
            if (index(s.vertex(j)) < 0)
                return;
        const double part = measure(mesh, s) / s.count();
        for (int j = 0; j < s.count(); ++j)
            parts[static_cast<std::size_t>(index(s.vertex(j)))] += part;
        total += part * s.count();
    });
    if (!(total > 0))
        return Refusal{RefusalCode::not_found,
                       "no boundary face has all its corners among the selected vertices, so there "
                       "is no area to share "
                       "the force by"};
    for (double& p : parts)
        p /= total;
    return parts;
}

}  // namespace sxk::elasticity
