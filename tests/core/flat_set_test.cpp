// detail::FlatSet: the open-addressing set of the snap cut's hot loops, against std::set.
#include "sxk/detail/flat_set.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <set>

#include "fixtures.hpp"

namespace sxk::test {
namespace {

TEST(FlatSet, HoldsWhatWasInsertedAndNothingElse) {
    detail::FlatSet<std::uint32_t> set;
    EXPECT_TRUE(set.empty());
    EXPECT_FALSE(set.contains(0));
    EXPECT_TRUE(set.insert(0));
    EXPECT_FALSE(set.insert(0));
    EXPECT_TRUE(set.insert(7));
    EXPECT_TRUE(set.contains(0));
    EXPECT_TRUE(set.contains(7));
    EXPECT_FALSE(set.contains(1));
    EXPECT_EQ(set.size(), 2u);
}

// Keys in runs and at random, through several doublings of the table, each inserted twice.
TEST(FlatSet, AgreesWithStdSetThroughGrowth) {
    const std::uint64_t seed = seed_for("FlatSet.AgreesWithStdSetThroughGrowth");
    std::mt19937_64 random(seed);
    detail::FlatSet<std::uint64_t> set;
    std::set<std::uint64_t> peer;
    std::uniform_int_distribution<std::uint64_t> any(0, ~std::uint64_t{0} - 1), few(0, 5000);
    for (int i = 0; i < 20000; ++i) {
        const std::uint64_t key = i % 3 == 0 ? any(random) : (few(random) << 32) | few(random);  // edges' shape
        ASSERT_EQ(set.insert(key), peer.insert(key).second) << "key " << key << " (seed " << seed << ")";
        ASSERT_FALSE(set.insert(key));
    }
    EXPECT_EQ(set.size(), peer.size());
    for (int i = 0; i < 20000; ++i) {
        const std::uint64_t key = (few(random) << 32) | few(random);
        ASSERT_EQ(set.contains(key), peer.count(key) == 1) << "key " << key << " (seed " << seed << ")";
    }
    for (const std::uint64_t key : peer) ASSERT_TRUE(set.contains(key)) << "key " << key << " (seed " << seed << ")";
}

}  // namespace
}  // namespace sxk::test
