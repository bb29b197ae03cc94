// Property test of SpatialIndex (issue 13, item 3) under edits: seeded random steps of 1-4 random
// local operations of the operation driver (flips, splits, collapses, dissections, bisections,
// refinement, Lawson flipping, node removal) and checked vertex moves, each step committed,
// rolled back, undone or redone at random, on the four start meshes of the driver (planar grid,
// planar random points, octahedron surface, Kuhn cube), with one index over the reference and
// one over the deformed positions attached throughout.
//
// After every step: validate() is clean and both indexes validate (every live element and
// boundary face in its tree once, with the box its positions give now); every 4th step both
// indexes answer random locate, segment, triangle, nearest-boundary and ray queries as a scan of
// every element does (tests/core/locate_scan.hpp). The seed is printed; SXK_SEED=<n> replays.
#include <gtest/gtest.h>

#include <random>
#include <string>

#include "../../fuzz/ops_driver.hpp"
#include "core/fixtures.hpp"
#include "core/locate_scan.hpp"
#include "ops/random_steps.hpp"
#include "sxk/edit_journal.hpp"
#include "sxk/locate.hpp"

namespace sxk {
namespace {

struct Counts {
    int steps = 0, operations = 0, done = 0, moves = 0, rollbacks = 0, undos = 0, redos = 0, comparisons = 0;
};

void run(std::uint32_t kind, int steps, const char* name, Counts& counts) {
    const std::uint64_t seed = test::seed_for(name);
    SCOPED_TRACE("SXK_SEED=" + std::to_string(seed));
    std::mt19937_64 rng(seed);
    test::StartChoices start(rng, kind);
    ops_driver::Choices& choices = start.choices();
    constexpr int restart = 250;  // steps per start mesh (dissections shred a mesh over time)
    for (int first = 0; first < steps; first += restart) {
        start.restart();
        Mesh mesh = ops_driver::start_mesh(choices, 6, 3);
        const SpatialIndex reference(mesh, Positions::reference);
        const SpatialIndex deformed(mesh, Positions::deformed);
        EditJournal journal(mesh);
        for (int i = first; i < std::min(steps, first + restart); ++i) {
            ++counts.steps;
            journal.checkpoint();
            const int operations = 1 + static_cast<int>(rng() % 4);
            for (int o = 0; o < operations; ++o) {
                if (rng() % 4 == 0) {
                    test::random_move(mesh, rng);
                    ++counts.moves;
                } else {
                    const ops_driver::Step op = ops_driver::run_step(mesh, choices, 500);
                    ++counts.operations;
                    counts.done += op.done;
                    ASSERT_TRUE(op.finding.empty()) << "step " << i << ": " << op.finding;
                }
                if (::testing::Test::HasFatalFailure()) return;
            }
            const std::uint64_t choice = rng() % 10;
            if (choice < 4) {
                ASSERT_TRUE(journal.rollback().ok());
                ++counts.rollbacks;
            } else {
                ASSERT_TRUE(journal.commit().ok());
                if (choice == 8 && journal.undo_count() > 0) {
                    ASSERT_TRUE(journal.undo().ok());
                    ++counts.undos;
                    if (rng() % 2 == 0) {  // a redo needs an undo since the last commit
                        ASSERT_TRUE(journal.redo().ok());
                        ++counts.redos;
                    }
                } else if (choice == 9 && journal.redo_count() > 0) {
                    ASSERT_TRUE(journal.redo().ok());
                    ++counts.redos;
                }
            }
            const auto valid = mesh.validate();
            ASSERT_TRUE(valid.ok()) << "step " << i << ": " << valid.reason();
            for (const SpatialIndex* index : {&reference, &deformed}) {
                const auto indexed = index->validate();
                ASSERT_TRUE(indexed.ok()) << "step " << i << ": " << indexed.reason();
            }
            if (i % 4 == 0) {
                ++counts.comparisons;
                test::expect_index_agrees(reference, rng, 3, "step " + std::to_string(i) + ", reference");
                test::expect_index_agrees(deformed, rng, 3, "step " + std::to_string(i) + ", deformed");
            }
            if (::testing::Test::HasFailure()) FAIL() << "step " << i;
        }
    }
}

void expect_all_kinds(const Counts& c) {
    std::cout << "[ done     ] steps " << c.steps << ", operations " << c.operations << " (" << c.done
              << " done), moves " << c.moves << ", rollbacks " << c.rollbacks << ", undos " << c.undos << ", redos "
              << c.redos << ", comparisons " << c.comparisons << "\n";
    EXPECT_GT(c.done, c.operations / 10);
    EXPECT_GT(c.rollbacks, c.steps / 4);
    EXPECT_GT(c.undos, 0);
    EXPECT_GT(c.redos, 0);
}

TEST(SpatialIndexRandom, JitteredPlanarGrid) {
    Counts counts;
    run(0, 1000, "SpatialIndexRandom.JitteredPlanarGrid", counts);
    expect_all_kinds(counts);
}

TEST(SpatialIndexRandom, PlanarRandomPoints) {
    Counts counts;
    run(1, 750, "SpatialIndexRandom.PlanarRandomPoints", counts);
    expect_all_kinds(counts);
}

TEST(SpatialIndexRandom, OctahedronSurface) {
    Counts counts;
    run(2, 750, "SpatialIndexRandom.OctahedronSurface", counts);
    expect_all_kinds(counts);
}

TEST(SpatialIndexRandom, JitteredKuhnCube) {
    Counts counts;
    run(3, 1000, "SpatialIndexRandom.JitteredKuhnCube", counts);
    expect_all_kinds(counts);
}

}  // namespace
}  // namespace sxk
