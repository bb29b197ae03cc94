#include "sxk/simplex.hpp"

#include <gtest/gtest.h>

#include <sstream>
#include <unordered_set>

namespace sxk {
namespace {

TEST(Simplex, CanonicalFormCountsSwaps) {
    // <c,a,b> is an even permutation of <a,b,c>, <b,a,c> an odd one
    EXPECT_EQ(Simplex(+1, {7, 3, 5}), Simplex(+1, {3, 5, 7}));
    EXPECT_EQ(Simplex(+1, {5, 3, 7}), Simplex(-1, {3, 5, 7}));
    const Simplex s(+1, {9, 2, 4, 1});
    EXPECT_EQ(s.vertex(0), 1u);
    EXPECT_EQ(s.vertex(3), 9u);
    // (9,2,4,1) has 3+1+1 = 5 inversions: an odd permutation of (1,2,4,9)
    EXPECT_EQ(s.sign(), -1);
    EXPECT_EQ(s.count(), 4);
    EXPECT_EQ(s.dimension(), 3);
}

TEST(Simplex, SubnAlternatesSign) {
    const Simplex t(+1, {0, 1, 2, 3});
    EXPECT_EQ(t.subn(0), Simplex(+1, {1, 2, 3}));
    EXPECT_EQ(t.subn(1), Simplex(-1, {0, 2, 3}));
    EXPECT_EQ(t.subn(2), Simplex(+1, {0, 1, 3}));
    EXPECT_EQ(t.subn(3), Simplex(-1, {0, 1, 2}));
    EXPECT_EQ(t.mate().subn(0), Simplex(-1, {1, 2, 3}));
    EXPECT_EQ(t.subv(2), t.subn(2));
}

TEST(Simplex, BoundaryOfBoundaryCancels) {
    // every (k-2)-face appears twice with opposite signs: the boundary of a boundary is empty
    const Simplex t(-1, {4, 8, 15, 16});
    std::vector<Simplex> edges;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 3; ++j) edges.push_back(t.subn(i).subn(j));
    for (const Simplex& e : edges) {
        const auto same = std::count(edges.begin(), edges.end(), e);
        const auto opposite = std::count(edges.begin(), edges.end(), e.mate());
        EXPECT_EQ(same, 1) << e;
        EXPECT_EQ(opposite, 1) << e;
    }
}

TEST(Simplex, MateFlipsOnlyTheSign) {
    const Simplex s(+1, {1, 2, 3});
    EXPECT_EQ(s.mate().sign(), -1);
    EXPECT_TRUE(s.mate().same_vertices(s));
    EXPECT_EQ(s.mate().mate(), s);
    EXPECT_NE(s.mate(), s);
}

TEST(Simplex, SupIsInverseOfSubv) {
    const Simplex face(-1, {2, 5, 9});
    for (VertexId v : {0u, 3u, 7u, 11u}) {
        const Simplex up = face.sup(v);
        EXPECT_EQ(up.count(), 4);
        EXPECT_TRUE(up.contains(v));
        EXPECT_EQ(up.subv(v), face) << "v=" << v;
    }
    // sup(v) equals p<v, a0, ..., ak> literally
    EXPECT_EQ(face.sup(7), Simplex(-1, {7, 2, 5, 9}));
}

TEST(Simplex, SubstitutedResorts) {
    const Simplex t(+1, {1, 2, 3});
    // replacing 1 by 4 gives the order <4,2,3>: two inversions, an even permutation of <2,3,4>
    EXPECT_EQ(t.substituted(1, 4), Simplex(+1, {4, 2, 3}));
    EXPECT_EQ(t.substituted(1, 4), Simplex(+1, {2, 3, 4}));
    EXPECT_EQ(t.substituted(2, 0), Simplex(+1, {1, 0, 3}));
    EXPECT_EQ(t.substituted(2, 0), Simplex(-1, {0, 1, 3}));
    EXPECT_EQ(t.substituted(8, 9), t);  // not a vertex: unchanged
}

TEST(Simplex, IndexAndVertices) {
    const Simplex s(+1, {10, 30, 20});
    EXPECT_EQ(s.index(20), 1);
    EXPECT_EQ(s.index(31), -1);
    EXPECT_FALSE(Simplex(+1, {1, 1, 2}).has_distinct_vertices());
    EXPECT_TRUE(s.has_distinct_vertices());
}

TEST(Simplex, CompareIsLexicographicAndSigned) {
    EXPECT_EQ(compare(Simplex(+1, {1, 2}), Simplex(+1, {1, 2})), 0);
    EXPECT_EQ(compare(Simplex(+1, {1, 2}), Simplex(+1, {1, 3})), -1);
    EXPECT_EQ(compare(Simplex(+1, {1, 3}), Simplex(+1, {1, 2})), 1);
    EXPECT_NE(compare(Simplex(+1, {1, 2}), Simplex(-1, {1, 2})), 0);
    EXPECT_LT(Simplex(+1, {5}), Simplex(+1, {0, 1}));  // fewer vertices first
}

TEST(Simplex, HashSeparatesOrientations) {
    std::unordered_set<Simplex, SimplexHash> set;
    set.insert(Simplex(+1, {1, 2, 3}));
    set.insert(Simplex(+1, {2, 3, 1}));  // same oriented simplex
    set.insert(Simplex(-1, {1, 2, 3}));
    EXPECT_EQ(set.size(), 2u);
    EXPECT_EQ(Simplex(+1, {1, 2, 3}).unoriented_hash(), Simplex(-1, {1, 2, 3}).unoriented_hash());
}

TEST(Simplex, ZeroSimplexHasTwoOrientations) {
    const Simplex v(+1, {4});
    EXPECT_EQ(v.dimension(), 0);
    EXPECT_NE(v, v.mate());
    EXPECT_EQ(Simplex(+1, {3, 4}).subn(0), Simplex(+1, {4}));
    EXPECT_EQ(Simplex(+1, {3, 4}).subn(1), Simplex(-1, {3}));
}

TEST(Simplex, Prints) {
    std::ostringstream out;
    out << Simplex(+1, {2, 1, 0});
    EXPECT_EQ(out.str(), "-<0,1,2>");
}

}  // namespace
}  // namespace sxk
