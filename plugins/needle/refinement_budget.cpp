// Estimates of the refinement's size (refinement_budget.hpp).
#include "refinement_budget.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include <Eigen/Dense>

namespace sxk::needle {

namespace {

// The mesh's area (triangles) or volume (tetrahedra), reference positions.
double measure(const Mesh& mesh) {
    double total = 0;
    for (const ElementId t : elements(mesh)) {
        const auto corners = mesh.simplex(t).vertices();
        const Point& a = mesh.reference(corners[0]);
        Eigen::Matrix3d edges = Eigen::Matrix3d::Identity();
        const int d = mesh.topological_dimension();
        for (int k = 1; k <= d; ++k)
            for (int c = 0; c < 3; ++c)
                edges(c, k - 1) = mesh.reference(corners[static_cast<std::size_t>(k)])[static_cast<std::size_t>(c)] -
                                  a[static_cast<std::size_t>(c)];
        total += d == 2 ? 0.5 * edges.col(0).cross(edges.col(1)).norm() : std::abs(edges.determinant()) / 6;
    }
    return total;
}

// The measure of one element of size h (the grid's right triangle or Kuhn tetrahedron).
double element_measure(const Mesh& mesh, double h) {
    return mesh.topological_dimension() == 2 ? h * h / 2 : h * h * h / 6;
}

// The length of segment [p, q] inside the box [low, high] (slab clipping).
double length_in_box(const Point& p, const Point& q, const Point& low, const Point& high, int dimension) {
    double enter = 0, leave = 1;
    for (int k = 0; k < dimension; ++k) {
        const auto c = static_cast<std::size_t>(k);
        const double step = q[c] - p[c];
        if (step == 0) {
            if (p[c] < low[c] || p[c] > high[c]) return 0;
            continue;
        }
        const double a = (low[c] - p[c]) / step, b = (high[c] - p[c]) / step;
        enter = std::max(enter, std::min(a, b));
        leave = std::min(leave, std::max(a, b));
    }
    if (!(leave > enter)) return 0;
    double squared = 0;
    for (int k = 0; k < dimension; ++k) {
        const auto c = static_cast<std::size_t>(k);
        squared += (q[c] - p[c]) * (q[c] - p[c]);
    }
    return (leave - enter) * std::sqrt(squared);
}

}  // namespace

double uniform_refinement_elements(const Mesh& mesh, double h) {
    return std::max(static_cast<double>(mesh.element_count()), measure(mesh) / element_measure(mesh, h));
}

double path_refinement_elements(const Mesh& mesh, std::span<const Point> tips, double h, double radius) {
    if (tips.empty()) return 0;
    const int dimension = mesh.ambient_dimension();
    Point low{0, 0, 0}, high{0, 0, 0};
    for (int k = 0; k < dimension; ++k) {
        low[static_cast<std::size_t>(k)] = std::numeric_limits<double>::infinity();
        high[static_cast<std::size_t>(k)] = -std::numeric_limits<double>::infinity();
    }
    for (const ElementId t : elements(mesh))
        for (const VertexId v : mesh.simplex(t).vertices())
            for (int k = 0; k < dimension; ++k) {
                const auto c = static_cast<std::size_t>(k);
                low[c] = std::min(low[c], mesh.reference(v)[c]);
                high[c] = std::max(high[c], mesh.reference(v)[c]);
            }
    double length = 0;
    for (std::size_t i = 1; i < tips.size(); ++i) length += length_in_box(tips[i - 1], tips[i], low, high, dimension);
    const double rho = std::max(radius, h);
    // the tube around the path and its two round ends
    const double tube = mesh.topological_dimension() == 2 ? 2 * rho * length + M_PI * rho * rho
                                                          : M_PI * rho * rho * length + 4.0 / 3 * M_PI * rho * rho * rho;
    return std::min(tube, measure(mesh)) / element_measure(mesh, h);
}

}  // namespace sxk::needle
