// The unit-cell meshes the latency benchmarks compare at two sizes (refine_latency, locate): a
// Kuhn cube of n^3 unit cubes (6 tetrahedra each) and a planar grid of n^2 unit squares (2
// triangles each). Unit cells on both sizes, so the same query does the same local work and only
// the mesh around it is larger. A mesh that cannot be made ends the program.
#pragma once

#include <cstdio>
#include <cstdlib>
#include <initializer_list>
#include <vector>

#include "sxk/generators.hpp"
#include "sxk/mesh.hpp"

namespace sxk_bench {

inline sxk::Mesh kuhn_cube(int n) {
    auto made = sxk::make_kuhn_cube(n);
    if (!made) {
        std::fprintf(stderr, "bench: %s\n", made.reason().c_str());
        std::exit(1);
    }
    return std::move(made).value();
}

inline sxk::Mesh grid(int n) {
    sxk::Mesh mesh(2, 2);
    mesh.reserve(static_cast<std::size_t>((n + 1) * (n + 1)), static_cast<std::size_t>(2 * n * n));
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) mesh.add_vertex({double(i), double(j), 0});
    auto id = [n](int i, int j) { return sxk::VertexId(j * (n + 1) + i); };
    std::vector<sxk::Simplex> triangles;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            triangles.emplace_back(+1, std::initializer_list<sxk::VertexId>{id(i, j), id(i + 1, j), id(i + 1, j + 1)});
            triangles.emplace_back(+1, std::initializer_list<sxk::VertexId>{id(i, j), id(i + 1, j + 1), id(i, j + 1)});
        }
    if (const auto built = mesh.assign_elements(triangles); !built) {
        std::fprintf(stderr, "bench: %s\n", built.reason().c_str());
        std::exit(1);
    }
    return mesh;
}

}  // namespace sxk_bench
