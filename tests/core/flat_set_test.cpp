// detail::FlatSet and FlatMap: the open-addressing set of the snap cut's hot loops and the map of
// an edit's touched faces, against std::set and std::map.
#include "sxk/detail/flat_set.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <map>
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

// Values stay with their keys through the doublings; a second insert keeps the first value.
TEST(FlatMap, AgreesWithStdMapThroughGrowth) {
    const std::uint64_t seed = seed_for("FlatMap.AgreesWithStdMapThroughGrowth");
    std::mt19937_64 random(seed);
    detail::FlatMap<std::uint32_t, std::uint32_t> map;
    std::map<std::uint32_t, std::uint32_t> peer;
    std::uniform_int_distribution<std::uint32_t> key_of(0, 50000), value_of;
    EXPECT_EQ(map.find(3), nullptr);
    for (int i = 0; i < 20000; ++i) {
        const std::uint32_t key = key_of(random), value = value_of(random);
        ASSERT_EQ(map.insert(key, value), peer.emplace(key, value).second) << "key " << key << " (seed " << seed << ")";
        ASSERT_NE(map.find(key), nullptr);
        ASSERT_EQ(*map.find(key), peer.at(key)) << "key " << key << " (seed " << seed << ")";
    }
    EXPECT_EQ(map.size(), peer.size());
    for (std::uint32_t key = 0; key <= 50000; ++key) {
        const auto it = peer.find(key);
        const std::uint32_t* value = map.find(key);
        ASSERT_EQ(value != nullptr, it != peer.end()) << "key " << key << " (seed " << seed << ")";
        if (value != nullptr) {
            ASSERT_EQ(*value, it->second) << "key " << key << " (seed " << seed << ")";
        }
    }
    *map.find(peer.begin()->first) = 7;  // found values are the map's own
    EXPECT_EQ(*map.find(peer.begin()->first), 7u);
}

}  // namespace
}  // namespace sxk::test
