#include "sxk/generators.hpp"

#include <array>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>


namespace sxk {

Outcome<Mesh> make_kuhn_cube(int n, double spacing) {
    if (n < 1 || n > 1000)
        return Refusal{RefusalCode::bad_argument, "make_kuhn_cube: " + std::to_string(n) +
                                                      " cubes per side is not in 1..1000"};
    if (!(spacing > 0) || !std::isfinite(spacing))
        return Refusal{RefusalCode::bad_argument,
                       "make_kuhn_cube: spacing " + std::to_string(spacing) +
                       " is not positive and finite"};
    const std::size_t side = static_cast<std::size_t>(n) + 1;
    const std::size_t cubes = static_cast<std::size_t>(n) * static_cast<std::size_t>(n) *
                              static_cast<std::size_t>(n);
    Mesh mesh(3, 3);
    mesh.reserve(side * side * side, 6 * cubes);
    for (int k = 0; k <= n; ++k)
        for (int j = 0; j <= n; ++j)
            for (int i = 0; i <= n; ++i) mesh.add_vertex({i * spacing, j * spacing, k * spacing});
    auto id = [side](int i, int j, int k) {
        return static_cast<VertexId>((static_cast<std::size_t>(k) * side + static_cast<std::size_t>(j)) * side +
                                     static_cast<std::size_t>(i));
    };
    static constexpr std::array<std::array<int, 3>, 6> orders{
        {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}}};
    std::vector<Simplex> tets;
    tets.reserve(6 * cubes);
    for (int k = 0; k < n; ++k)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i)
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
                       "make_kuhn_cube: " + built.reason()};  // cannot happen: the cuts match
    return mesh;
}

}  // namespace sxk
