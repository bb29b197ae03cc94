// A mesh file of two bodies: two copies of the thesis cube (`sxk generate --cells 8`: 8 x 8 x 8
// Kuhn cells of side 1, 3072 tetrahedra each), the second moved by `offset`. For the commands'
// tests of what they do with several components (cut snap's loose pieces, deform's free parts).
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <vector>

#include "sxk/generators.hpp"
#include "sxk/io.hpp"
#include "sxk/mesh.hpp"

namespace sxk::test {

inline void write_two_cubes(const std::filesystem::path& file, const Point& offset) {
    const auto cube = make_kuhn_box({8, 8, 8}, {1, 1, 1});
    ASSERT_TRUE(cube.ok());
    Mesh two(3, 3);
    const auto n = static_cast<VertexId>(cube->vertex_count());
    for (int copy = 0; copy < 2; ++copy)
        for (VertexId v = 0; v < n; ++v) {
            Point p = cube->reference(v);
            if (copy == 1)
                for (std::size_t k = 0; k < 3; ++k) p[k] += offset[k];
            two.add_vertex(p);
        }
    std::vector<Simplex> simplexes;
    for (int copy = 0; copy < 2; ++copy)
        for (const ElementId t : elements(*cube)) {
            const Simplex& s = cube->simplex(t);
            std::vector<VertexId> corners(s.vertices().begin(), s.vertices().end());
            for (VertexId& v : corners) v += copy == 1 ? n : 0;
            simplexes.emplace_back(s.sign(), corners);
        }
    ASSERT_TRUE(two.assign_elements(simplexes).ok());
    ASSERT_TRUE(two.validate().ok());
    write_mesh(two, file);
}

}  // namespace sxk::test
