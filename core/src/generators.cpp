#include "sxk/generators.hpp"

#include <array>
#include <cmath>
#include <cstddef>
#include <initializer_list>
#include <string>
#include <vector>

namespace sxk {

namespace {

// Both generators: the counts and spacings are checked by the caller, whose name the refusals carry.
Outcome<Mesh> kuhn_box(std::array<int, 3> n, std::array<double, 3> spacing, const char* name) {
    const auto size = [&](std::size_t k) { return static_cast<std::size_t>(n[k]); };
    const std::array<std::size_t, 3> side{size(0) + 1, size(1) + 1, size(2) + 1};
    const std::size_t cubes = size(0) * size(1) * size(2);
    Mesh mesh(3, 3);
    mesh.reserve(side[0] * side[1] * side[2], 6 * cubes);
    for (int k = 0; k <= n[2]; ++k)
        for (int j = 0; j <= n[1]; ++j)
            for (int i = 0; i <= n[0]; ++i) mesh.add_vertex({i * spacing[0], j * spacing[1], k * spacing[2]});
    auto id = [&side](int i, int j, int k) {
        return static_cast<VertexId>((static_cast<std::size_t>(k) * side[1] + static_cast<std::size_t>(j)) * side[0] +
                                     static_cast<std::size_t>(i));
    };
    static constexpr std::array<std::array<int, 3>, 6> orders{
        {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}}};
    std::vector<Simplex> tets;
    tets.reserve(6 * cubes);
    for (int k = 0; k < n[2]; ++k)
        for (int j = 0; j < n[1]; ++j)
            for (int i = 0; i < n[0]; ++i)
                for (std::size_t o = 0; o < orders.size(); ++o) {
                    std::array<int, 3> c{i, j, k};
                    std::array<VertexId, 4> v{};
                    v[0] = id(c[0], c[1], c[2]);
                    for (std::size_t step = 0; step < 3; ++step) {
                        ++c[static_cast<std::size_t>(orders[o][step])];
                        v[step + 1] = id(c[0], c[1], c[2]);
                    }
                    // the path's vertices in path order are positive for an even permutation
                    // of the axes and negative for an odd one
                    const int sign = (o == 0 || o == 3 || o == 4) ? +1 : -1;
                    tets.emplace_back(sign, v);
                }
    if (auto built = mesh.assign_elements(tets); !built)
        return Refusal{RefusalCode::internal_error,
                       std::string(name) + ": " + built.reason()};  // cannot happen: the cuts match
    return mesh;
}

bool positive_finite(double x) { return x > 0 && std::isfinite(x); }

}  // namespace

Outcome<Mesh> make_kuhn_cube(int n, double spacing) {
    if (n < 1 || n > 1000)
        return Refusal{RefusalCode::bad_argument, "make_kuhn_cube: " + std::to_string(n) +
                                                      " cubes per side is not in 1..1000"};
    if (!positive_finite(spacing))
        return Refusal{RefusalCode::bad_argument,
                       "make_kuhn_cube: spacing " + std::to_string(spacing) +
                       " is not positive and finite"};
    return kuhn_box({n, n, n}, {spacing, spacing, spacing}, "make_kuhn_cube");
}

Outcome<Mesh> make_kuhn_box(std::array<int, 3> cells, std::array<double, 3> spacing) {
    static constexpr std::array<char, 3> axis{'x', 'y', 'z'};
    for (std::size_t k = 0; k < 3; ++k) {
        if (cells[k] < 1 || cells[k] > 1000)
            return Refusal{RefusalCode::bad_argument, "make_kuhn_box: " + std::to_string(cells[k]) + " cells along " +
                                                          axis[k] + " is not in 1..1000"};
        if (!positive_finite(spacing[k]))
            return Refusal{RefusalCode::bad_argument, "make_kuhn_box: spacing " + std::to_string(spacing[k]) +
                                                          " along " + axis[k] + " is not positive and finite"};
    }
    return kuhn_box(cells, spacing, "make_kuhn_box");
}

Outcome<Mesh> make_triangle_grid(std::array<int, 2> cells, std::array<double, 2> spacing) {
    static constexpr std::array<char, 2> axis{'x', 'y'};
    for (std::size_t k = 0; k < 2; ++k) {
        if (cells[k] < 1 || cells[k] > 5000)
            return Refusal{RefusalCode::bad_argument, "make_triangle_grid: " + std::to_string(cells[k]) +
                                                          " cells along " + axis[k] + " is not in 1..5000"};
        if (!positive_finite(spacing[k]))
            return Refusal{RefusalCode::bad_argument, "make_triangle_grid: spacing " + std::to_string(spacing[k]) +
                                                          " along " + axis[k] + " is not positive and finite"};
    }
    const auto columns = static_cast<std::size_t>(cells[0]) + 1;
    const auto rows = static_cast<std::size_t>(cells[1]) + 1;
    Mesh mesh(2, 2);
    mesh.reserve(columns * rows, 2 * (columns - 1) * (rows - 1));
    for (int j = 0; j <= cells[1]; ++j)
        for (int i = 0; i <= cells[0]; ++i) mesh.add_vertex({i * spacing[0], j * spacing[1], 0});
    auto id = [columns](int i, int j) {
        return static_cast<VertexId>(static_cast<std::size_t>(j) * columns + static_cast<std::size_t>(i));
    };
    std::vector<Simplex> triangles;
    triangles.reserve(2 * (columns - 1) * (rows - 1));
    for (int j = 0; j < cells[1]; ++j)
        for (int i = 0; i < cells[0]; ++i) {
            triangles.emplace_back(+1, std::initializer_list<VertexId>{id(i, j), id(i + 1, j), id(i + 1, j + 1)});
            triangles.emplace_back(+1, std::initializer_list<VertexId>{id(i, j), id(i + 1, j + 1), id(i, j + 1)});
        }
    if (auto built = mesh.assign_elements(triangles); !built)
        return Refusal{RefusalCode::internal_error, "make_triangle_grid: " + built.reason()};  // cannot happen
    return mesh;
}

Outcome<Mesh> make_gaussian_bell(std::array<int, 2> cells, std::array<double, 2> spacing, double height,
                                 double width) {
    if (!std::isfinite(height))
        return Refusal{RefusalCode::bad_argument, "make_gaussian_bell: height " + std::to_string(height) +
                                                      " is not finite"};
    if (!positive_finite(width))
        return Refusal{RefusalCode::bad_argument, "make_gaussian_bell: width " + std::to_string(width) +
                                                      " is not positive and finite"};
    Outcome<Mesh> grid = make_triangle_grid(cells, spacing);
    if (!grid) return Refusal{grid.refusal().code, "make_gaussian_bell: " + grid.reason().substr(20)};
    const double cx = cells[0] * spacing[0] / 2, cy = cells[1] * spacing[1] / 2;
    Mesh bell(2, 3);
    bell.reserve(grid->vertex_count(), grid->element_count());
    for (VertexId v = 0; v < grid->vertex_count(); ++v) {
        const Point& p = grid->reference(v);
        const double r2 = (p[0] - cx) * (p[0] - cx) + (p[1] - cy) * (p[1] - cy);
        bell.add_vertex({p[0], p[1], height * std::exp(-r2 / (2 * width * width))});
    }
    std::vector<Simplex> triangles;
    triangles.reserve(grid->element_count());
    for (const ElementId t : elements(*grid)) triangles.push_back(grid->simplex(t));
    if (auto built = bell.assign_elements(triangles); !built)
        return Refusal{RefusalCode::internal_error, "make_gaussian_bell: " + built.reason()};  // cannot happen
    return bell;
}

}  // namespace sxk
