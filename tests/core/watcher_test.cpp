#include <gtest/gtest.h>

#include <algorithm>

#include "fixtures.hpp"
#include "sxk/mesh.hpp"

namespace sxk {
namespace {

using test::CountingWatcher;

TEST(Watchers, InitialisedOnceWhenAdded) {
    Mesh mesh = test::kuhn_cube(2);
    CountingWatcher watcher;
    mesh.add_watcher(watcher);
    EXPECT_EQ(watcher.inits, 1);
    EXPECT_EQ(watcher.boundary.size(), mesh.boundary_face_count());
    mesh.remove_watcher(watcher);
    const std::array<ElementId, 1> old{0};
    ASSERT_TRUE(mesh.replace_elements(old, {}).ok());
    EXPECT_EQ(watcher.removed, 0);  // no longer registered
}

TEST(Watchers, CopiesDoNotCarryWatchers) {
    Mesh mesh = test::unit_square();
    CountingWatcher watcher;
    mesh.add_watcher(watcher);
    Mesh copy = mesh;
    const std::array<ElementId, 1> old{0};
    ASSERT_TRUE(copy.replace_elements(old, {}).ok());
    EXPECT_EQ(watcher.removed, 0);
}

TEST(Watchers, EachNetChangeOnceOverManyEdits) {
    // Remove every element of a cube one by one, then put them all back: the watcher's own
    // boundary set must follow the mesh exactly, and each element is reported once each way.
    Mesh mesh = test::kuhn_cube(2);
    CountingWatcher watcher;
    mesh.add_watcher(watcher);
    // (a removal that would pinch a vertex star is refused: peel the cube in passes, the way
    // a shelling does, and put the elements back in reverse order)
    std::vector<std::pair<Simplex, int>> removed;
    for (bool progress = true; progress && mesh.element_count() > 0;) {
        progress = false;
        for (ElementId t = 0; t < mesh.element_capacity(); ++t) {
            if (!mesh.is_element(t)) continue;
            const Simplex tau = mesh.simplex(t);
            const int label = mesh.label(t);
            const std::array<ElementId, 1> old{t};
            if (!mesh.replace_elements(old, {}).ok()) continue;
            removed.emplace_back(tau, label);
            progress = true;
            watcher.expect_in_step_with(mesh);
            ASSERT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
        }
    }
    // what is left cannot lose any single element without a pinch: remove it in one edit
    std::vector<ElementId> rest;
    std::vector<Simplex> rest_simplexes;
    std::vector<int> rest_labels;
    for (ElementId t : elements(mesh)) {
        rest.push_back(t);
        rest_simplexes.push_back(mesh.simplex(t));
        rest_labels.push_back(mesh.label(t));
    }
    EXPECT_GT(removed.size(), 20u);
    ASSERT_TRUE(mesh.replace_elements(rest, {}).ok());
    watcher.expect_in_step_with(mesh);
    EXPECT_EQ(mesh.element_count(), 0u);
    std::reverse(removed.begin(), removed.end());
    EXPECT_EQ(mesh.boundary_face_count(), 0u);
    EXPECT_EQ(watcher.removed, 48);
    ASSERT_TRUE(mesh.replace_elements({}, rest_simplexes, rest_labels).ok());
    watcher.expect_in_step_with(mesh);
    for (const auto& [tau, label] : removed) {
        const std::array<Simplex, 1> back{tau};
        const std::array<int, 1> labels{label};
        ASSERT_TRUE(mesh.replace_elements({}, back, labels).ok());
        watcher.expect_in_step_with(mesh);
    }
    EXPECT_EQ(watcher.added, 48);
    ASSERT_TRUE(mesh.validate().ok()) << mesh.validate().reason();
    EXPECT_EQ(mesh.boundary_face_count(), 48u);  // 6 sides x 2 x 2 squares x 2
}

TEST(Watchers, RefusedEditsAreSilent) {
    Mesh mesh = test::unit_square();
    CountingWatcher watcher;
    mesh.add_watcher(watcher);
    const std::array<Simplex, 1> clash{Simplex(+1, {0, 1, 2})};
    ASSERT_FALSE(mesh.replace_elements({}, clash).ok());
    EXPECT_EQ(watcher.added + watcher.removed + watcher.boundary_added_count +
                  watcher.boundary_removed_count,
              0);
}

}  // namespace
}  // namespace sxk
