#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <map>
#include <numeric>
#include <random>
#include <vector>

#include "core/fixtures.hpp"
#include "sxk/ops/reorder_vertices.hpp"

namespace sxk {
namespace {

//   a 10 x 10 grid numbered row by row has bandwidth 12 (the diagonal (i,j)-(i+1,j+1)); shuffled
//   at random it is near 120; Cuthill-McKee brings it back to at most the natural 12.
TEST(ReorderVertices, CuthillMcKeeUndoesAShuffle) {
    const Mesh grid = test::planar_grid(10);
    const std::size_t natural = vertex_bandwidth(grid);
    EXPECT_EQ(natural, 12u);

    std::vector<VertexId> shuffle(grid.vertex_count());
    std::iota(shuffle.begin(), shuffle.end(), VertexId{0});
    std::mt19937 random(7);
    std::shuffle(shuffle.begin(), shuffle.end(), random);
    const Mesh shuffled = renumbered(grid, shuffle);
    ASSERT_TRUE(shuffled.validate().ok()) << shuffled.validate().reason();
    EXPECT_GT(vertex_bandwidth(shuffled), natural);

    const std::vector<VertexId> order = cuthill_mckee_order(shuffled);
    std::vector<VertexId> sorted = order;
    std::sort(sorted.begin(), sorted.end());
    for (std::size_t i = 0; i < sorted.size(); ++i) ASSERT_EQ(sorted[i], i);  // a permutation

    const Mesh reordered = renumbered(shuffled, order);
    ASSERT_TRUE(reordered.validate().ok()) << reordered.validate().reason();
    EXPECT_EQ(reordered.element_count(), grid.element_count());
    EXPECT_EQ(reordered.boundary_face_count(), grid.boundary_face_count());
    EXPECT_LE(vertex_bandwidth(reordered), natural);
    // positions travel with their vertices
    for (VertexId v = 0; v < shuffled.vertex_count(); ++v)
        EXPECT_EQ(reordered.reference(order[v]), shuffled.reference(v));
}

TEST(ReorderVertices, RenumberedKeepsOrientationAndLabels) {
    Mesh cube = test::kuhn_cube(2);
    cube.face_labels()[Simplex(+1, {0, 1, 4})] = 5;
    std::vector<VertexId> reverse(cube.vertex_count());
    for (VertexId v = 0; v < reverse.size(); ++v) reverse[v] = static_cast<VertexId>(reverse.size() - 1 - v);
    for (ElementId t : elements(cube)) cube.set_label(t, static_cast<int>(t.value()) + 1);
    const Mesh result = renumbered(cube, reverse);
    ASSERT_TRUE(result.validate().ok()) << result.validate().reason();
    // each element keeps its orientation and label, wherever it now is in the element order
    std::map<Simplex, int> before, after;
    for (ElementId t : elements(cube)) {
        Simplex mapped = cube.simplex(t);
        std::array<VertexId, 4> vertices{};
        for (int j = 0; j < 4; ++j) vertices[static_cast<std::size_t>(j)] = reverse[mapped.vertex(j)];
        before[Simplex(mapped.sign(), vertices)] = cube.label(t);
    }
    for (ElementId t : elements(result)) after[result.simplex(t)] = result.label(t);
    EXPECT_EQ(after, before);
    // and the elements come in the order of their lowest vertex
    VertexId last = 0;
    for (ElementId t : elements(result)) {
        const Simplex s = result.simplex(t);
        const VertexId lowest = *std::min_element(s.vertices().begin(), s.vertices().end());
        EXPECT_GE(lowest, last) << "element " << t;
        last = lowest;
    }
    const VertexId n = static_cast<VertexId>(reverse.size() - 1);
    EXPECT_EQ(result.face_labels().at(Simplex(+1, {n - 4, n - 1, n})), 5);
}

}  // namespace
}  // namespace sxk
