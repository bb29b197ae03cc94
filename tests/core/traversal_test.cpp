#include "sxk/traversal.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "fixtures.hpp"

namespace sxk {
namespace {

std::vector<ElementId> sorted(std::vector<ElementId> v) {
    std::sort(v.begin(), v.end());
    return v;
}

std::vector<ElementId> brute_force_containing(const Mesh& mesh, const Simplex& sigma) {
    std::vector<ElementId> out;
    for (ElementId t : elements(mesh)) {
        bool all = true;
        for (VertexId v : sigma.vertices()) all = all && mesh.simplex(t).contains(v);
        if (all) out.push_back(t);
    }
    return out;
}

TEST(CycleAround, InteriorAndBoundaryVerticesIn2D) {
    const Mesh mesh = test::planar_grid(4);
    for (FaceId f = 0; f < mesh.face_capacity(); ++f) {
        if (!mesh.is_face(f)) continue;
        for (int j = 0; j < 2; ++j) {
            const Simplex vertex = mesh.face_simplex(f).subn(j);
            const auto ring = cycle_around(mesh, f, j);
            EXPECT_EQ(sorted(ring), brute_force_containing(mesh, vertex)) << "face " << f << " j " << j;
            // consecutive ring elements are neighbours
            for (std::size_t i = 1; i < ring.size(); ++i) {
                bool adjacent = false;
                for (int s = 0; s < 3; ++s) adjacent = adjacent || mesh.neighbor(ring[i - 1], s) == ring[i];
                EXPECT_TRUE(adjacent);
            }
        }
    }
}

TEST(CycleAround, EdgesOfTheKuhnCube) {
    const Mesh mesh = test::kuhn_cube(3);
    std::size_t checked = 0;
    for (FaceId f = 0; f < mesh.face_capacity(); ++f) {
        if (!mesh.is_face(f)) continue;
        for (int j = 0; j < 3; ++j) {
            const Simplex edge = mesh.face_simplex(f).subn(j);
            EXPECT_EQ(sorted(cycle_around(mesh, f, j)), brute_force_containing(mesh, edge));
            ++checked;
        }
    }
    EXPECT_EQ(checked, 3u * 4u * mesh.element_count());
}

TEST(Star, EqualsTheElementsContainingTheVertex) {
    const Mesh mesh = test::kuhn_cube(3);
    for (VertexId v = 0; v < mesh.vertex_count(); ++v)
        EXPECT_EQ(sorted(star(mesh, v)), brute_force_containing(mesh, Simplex(+1, {v})));
    // corner (0,0,0) lies in the one tetrahedron... in all six of its cube: the diagonal
    EXPECT_EQ(star(mesh, 0).size(), 6u);
}

TEST(Star, OfAnIsolatedVertexIsEmpty) {
    Mesh mesh = test::unit_square();
    const VertexId lonely = mesh.add_vertex({5, 5, 0});
    EXPECT_TRUE(star(mesh, lonely).empty());
    EXPECT_TRUE(mesh.validate().ok());
}

}  // namespace
}  // namespace sxk
