#include "sxk/traversal.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "fixtures.hpp"
#include "star_walk.hpp"

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

// A disk of n triangles around vertex 0: a star far beyond StarList's table in place.
TEST(Star, OfAVertexWithHundredsOfElements) {
    constexpr VertexId n = 400;
    Mesh mesh(2, 2);
    mesh.add_vertex({0, 0, 0});
    for (VertexId i = 0; i < n; ++i) {
        const double angle = 2 * 3.141592653589793 * i / n;
        mesh.add_vertex({std::cos(angle), std::sin(angle), 0});
    }
    std::vector<Simplex> triangles;
    for (VertexId i = 0; i < n; ++i) triangles.push_back(Simplex(+1, {0, 1 + i, 1 + (i + 1) % n}));
    ASSERT_TRUE(mesh.assign_elements(triangles).ok());
    ASSERT_TRUE(mesh.validate().ok());
    const std::vector<ElementId> around = star(mesh, 0);
    EXPECT_EQ(sorted(around), brute_force_containing(mesh, Simplex(+1, {0})));
    // breadth first from the anchor: every element after the first is a neighbour of an
    // element listed before it
    for (std::size_t i = 1; i < around.size(); ++i) {
        bool reached = false;
        for (std::size_t j = 0; j < i && !reached; ++j)
            for (int s = 0; s < 3; ++s) reached = reached || mesh.neighbor(around[j], s) == around[i];
        EXPECT_TRUE(reached) << i;
    }
}

// The walk's list (core/src/star_walk.hpp) answers positions like a scanned list, through its
// scanned start, its table in place and the heap tables it grows into.
TEST(StarList, GivesThePositionsOfAScannedList) {
    detail::StarList list;
    std::vector<ElementId> expected;
    std::uint32_t x = 12345;
    for (int step = 0; step < 5000; ++step) {
        x = x * 1664525u + 1013904223u;
        const ElementId t = (x >> 8) % 1500;
        const auto found = std::find(expected.begin(), expected.end(), t);
        const std::size_t position = static_cast<std::size_t>(found - expected.begin());
        if (found == expected.end()) expected.push_back(t);
        ASSERT_EQ(list.insert(t), position) << "step " << step;
        ASSERT_EQ(list.size(), expected.size());
    }
    EXPECT_TRUE(std::equal(list.begin(), list.end(), expected.begin(), expected.end()));
}

}  // namespace
}  // namespace sxk

namespace sxk {
namespace {

// fan_around on the planar 2 x 2 grid (vertex (i,j) is 3j + i): the centre's six triangles close
// around it counter-clockwise; a side vertex's three run from one boundary edge to the other; every
// triangle i of a fan is <v, ring[i], ring[i+1]> in its positive order.
TEST(Traversal, FanAroundListsTheTrianglesInOrder) {
    const Mesh mesh = test::planar_grid(2);
    const VertexFan centre = fan_around(mesh, 4);
    EXPECT_TRUE(centre.closed);
    ASSERT_EQ(centre.triangles.size(), 6u);
    ASSERT_EQ(centre.ring.size(), 6u);
    const VertexFan side = fan_around(mesh, 1);  // (1, 0)
    EXPECT_FALSE(side.closed);
    ASSERT_EQ(side.triangles.size(), 3u);
    ASSERT_EQ(side.ring.size(), 4u);
    EXPECT_EQ(side.ring.front(), 2u);  // the boundary edge 1-2 has the mesh on its left
    EXPECT_EQ(side.ring.back(), 0u);   // and so has 0-1
    for (const VertexFan* fan : {&centre, &side})
        for (std::size_t i = 0; i < fan->triangles.size(); ++i) {
            const VertexId v = fan == &centre ? 4 : 1;
            EXPECT_EQ(mesh.simplex(fan->triangles[i]), Simplex(+1, {v, fan->ring[i], fan->next(i)}));
        }
    EXPECT_TRUE(fan_around(test::kuhn_cube(1), 0).triangles.empty());  // tetrahedra: no fan
}

}  // namespace
}  // namespace sxk
