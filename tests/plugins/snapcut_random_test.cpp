// Property test of the snap cutter: seeded random scalpel paths (curved: the blade turns and
// tilts as it goes) on the thesis' cube, a Delaunay mesh of random points and the Delaunay
// cylinder; after every step the mesh is valid, with no element inverted or flat in either
// position set, and undoing every step gives back the input exactly. SXK_SEED replays a run.
// 10,980 steps in all (80 + 50 + 50 paths of 61 samples). The femur: tests/real/snapcut_femur.cpp
// (SnapCutFemur.RandomPathsKeepTheFemurValid).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "core/fixtures.hpp"
#include "snapcut_fixture.hpp"

namespace sxk::test {
namespace {

TEST(SnapCutRandom, ThesisCube) {
    std::size_t dissected = 0;
    check_random_cuts("SnapCutRandom.ThesisCube", make_kuhn_cube(8).value(), 80, 60, dissected);
    EXPECT_GT(dissected, 0u);
}

TEST(SnapCutRandom, DelaunayOfRandomPoints) {
    const char* name = "SnapCutRandom.DelaunayOfRandomPoints";
    const std::uint64_t seed = seed_for(name);
    std::size_t dissected = 0;
    check_random_cuts(name, seed, make_delaunay(random_points(seed, 600)).value(), 50, 60, dissected);
    EXPECT_GT(dissected, 0u);
}

TEST(SnapCutRandom, DelaunayCylinder) {
    std::size_t dissected = 0;
    check_random_cuts("SnapCutRandom.DelaunayCylinder", make_delaunay(cylinder_cloud(4, 13)).value(), 50, 60, dissected);
    EXPECT_GT(dissected, 0u);
}

}  // namespace
}  // namespace sxk::test
