// The moving line scalpel against an edge (plugins/delaunaycut/scalpel_sweep.hpp, thesis eq. 5.1):
// hand-made movements with known answers, the degenerate ones the thesis' solution fails on
// (coplanar movements, a blade parallel to the edge), and random movements against a brute-force
// search over time.
#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "core/fixtures.hpp"
#include "scalpel_sweep.hpp"

namespace sxk::delaunaycut {
namespace {

void expect_hit(const std::optional<SweepHit>& hit, double time, double blade, double edge, const Point& at) {
    ASSERT_TRUE(hit.has_value());
    EXPECT_NEAR(hit->time, time, 1e-12);
    EXPECT_NEAR(hit->along_blade, blade, 1e-12);
    EXPECT_NEAR(hit->along_edge, edge, 1e-12);
    for (std::size_t k = 0; k < 3; ++k) EXPECT_NEAR(hit->point[k], at[k], 1e-12);
}

TEST(ScalpelSweep, ABladeMovingAcrossAnEdgeMeetsItWhereTheLinesCross) {
    // a vertical blade moving along x through an edge along y
    expect_hit(first_sweep_hit({-1, 0, 1}, {-1, 0, -1}, {1, 0, 1}, {1, 0, -1}, {0, -1, 0}, {0, 1, 0}), 0.5, 0.5,
               0.5, {0, 0, 0});
    // a blade turning about its handle: the tip sweeps from x = -1 to x = 1 below it, and the blade
    // reaches the edge x = 0.5 (at half its length) as the movement ends
    expect_hit(first_sweep_hit({0, 0, 1}, {-1, 0, -1}, {0, 0, 1}, {1, 0, -1}, {0.5, -1, 0}, {0.5, 1, 0}), 1, 0.5,
               0.5, {0.5, 0, 0});
    // the edge beyond the blade's reach, and a movement that stops short of it
    EXPECT_FALSE(first_sweep_hit({-1, 0, 1}, {-1, 0, 0.5}, {1, 0, 1}, {1, 0, 0.5}, {0, -1, 0}, {0, 1, 0}));
    EXPECT_FALSE(first_sweep_hit({-1, 0, 1}, {-1, 0, -1}, {-0.1, 0, 1}, {-0.1, 0, -1}, {0, -1, 0}, {0, 1, 0}));
}

// The cases eq. 5.1's linear system cannot solve: the coplanarity determinant vanishes for every s.
TEST(ScalpelSweep, MovementsInThePlaneOfTheEdgeAndBladesParallelToIt) {
    // everything in z = 0: the blade slides right along y = 0.5 and its tip reaches the edge x = 0
    expect_hit(first_sweep_hit({-2, 0.5, 0}, {-1, 0.5, 0}, {2, 0.5, 0}, {3, 0.5, 0}, {0, 0, 0}, {0, 1, 0}), 0.25, 1,
               0.5, {0, 0.5, 0});
    // the blade slides towards the edge's end: the end a touches the blade's middle
    expect_hit(first_sweep_hit({-1, 1, 0}, {1, 1, 0}, {-1, -1, 0}, {1, -1, 0}, {0, 0, 0}, {0, -1, 0}), 0.5, 0.5, 0,
               {0, 0, 0});
    // parallel to the edge, one unit above its plane: never
    EXPECT_FALSE(first_sweep_hit({-1, -1, 1}, {-1, 1, 1}, {1, -1, 1}, {1, 1, 1}, {0, -2, 0}, {0, 2, 0}));
    // parallel to the edge in its plane: they overlap from s = 0.5, first at the blade's handle
    expect_hit(first_sweep_hit({-1, -1, 0}, {-1, 1, 0}, {1, -1, 0}, {1, 1, 0}, {0, -2, 0}, {0, 2, 0}), 0.5, 0, 0.25,
               {0, -1, 0});
    // already crossing the edge when the movement starts
    expect_hit(first_sweep_hit({0, -1, 0}, {0, 1, 0}, {0, -1, 0}, {0, 1, 0}, {-1, 0, 0}, {1, 0, 0}), 0, 0.5, 0.5,
               {0, 0, 0});
}

// The distance between the segments p-q and a-b (closest points, clamped to both segments).
double segment_distance(const Point& p, const Point& q, const Point& a, const Point& b) {
    auto sub = [](const Point& x, const Point& y) { return Point{x[0] - y[0], x[1] - y[1], x[2] - y[2]}; };
    auto dot = [](const Point& x, const Point& y) { return x[0] * y[0] + x[1] * y[1] + x[2] * y[2]; };
    const Point d1 = sub(q, p), d2 = sub(b, a), r = sub(p, a);
    const double aa = dot(d1, d1), e = dot(d2, d2), f = dot(d2, r), c = dot(d1, r), bb = dot(d1, d2);
    const double denom = aa * e - bb * bb;
    double s = denom > 0 ? std::clamp((bb * f - c * e) / denom, 0.0, 1.0) : 0.0;
    double t = (bb * s + f) / e;
    if (t < 0) t = 0, s = std::clamp(-c / aa, 0.0, 1.0);
    else if (t > 1) t = 1, s = std::clamp((bb - c) / aa, 0.0, 1.0);
    const Point x{p[0] + s * d1[0], p[1] + s * d1[1], p[2] + s * d1[2]};
    const Point y{a[0] + t * d2[0], a[1] + t * d2[1], a[2] + t * d2[2]};
    const Point gap = sub(x, y);
    return std::sqrt(dot(gap, gap));
}

// Random movements: the first time found agrees with a search over time of the distance between
// the blade and the edge (its local minima refined by ternary search; configurations whose closest
// approach is neither a touch nor clearly apart are skipped), and the point found is on both.
TEST(ScalpelSweep, AgreesWithABruteForceSearchOverTime) {
    std::mt19937_64 random(test::seed_for("ScalpelSweep.BruteForce"));
    std::uniform_real_distribution<double> coordinate(-1, 1);
    auto point = [&] { return Point{coordinate(random), coordinate(random), coordinate(random)}; };
    int hits = 0, misses = 0;
    for (int trial = 0; trial < 300; ++trial) {
        const Point h0 = point(), t0 = point(), h1 = point(), t1 = point(), a = point(), b = point();
        auto at = [](const Point& p, const Point& q, double s) {
            return Point{p[0] + s * (q[0] - p[0]), p[1] + s * (q[1] - p[1]), p[2] + s * (q[2] - p[2])};
        };
        auto distance_at = [&](double s) { return segment_distance(at(h0, h1, s), at(t0, t1, s), a, b); };
        // the first local minimum of the distance that touches, refined
        constexpr int samples = 2000;
        double first = -1, closest = 1e300;
        for (int i = 0; i <= samples && first < 0; ++i) {
            double low = std::max(0, i - 1) / double(samples), high = std::min(samples, i + 1) / double(samples);
            if (distance_at(i / double(samples)) > 0.01) continue;
            for (int k = 0; k < 100; ++k) {
                const double m1 = low + (high - low) / 3, m2 = high - (high - low) / 3;
                if (distance_at(m1) < distance_at(m2)) high = m2;
                else low = m1;
            }
            const double d = distance_at(low);
            closest = std::min(closest, d);
            if (d < 1e-9) first = low;
        }
        for (int i = 0; i <= samples; ++i) closest = std::min(closest, distance_at(i / double(samples)));
        if (first < 0 && closest < 1e-3) continue;  // a near miss: too close to call
        SCOPED_TRACE("trial " + std::to_string(trial));
        const auto found = first_sweep_hit(h0, t0, h1, t1, a, b);
        EXPECT_EQ(found.has_value(), first >= 0);
        if (!found || first < 0) {
            ++misses;
            continue;
        }
        ++hits;
        EXPECT_NEAR(found->time, first, 1e-6);
        const double s = found->time, l = found->along_blade;
        for (std::size_t k = 0; k < 3; ++k) {
            const double blade = (1 - l) * (h0[k] + s * (h1[k] - h0[k])) + l * (t0[k] + s * (t1[k] - t0[k]));
            EXPECT_NEAR(blade, found->point[k], 1e-9);
            EXPECT_NEAR(a[k] + found->along_edge * (b[k] - a[k]), found->point[k], 1e-9);
        }
    }
    EXPECT_GT(hits, 20);
    EXPECT_GT(misses, 20);
}

// Fig. 5.11: moves of both ends shorter than d_max never meet the edges; a move a little longer, along
// the common normal towards the nearest edge's line, meets that line.
TEST(ScalpelSweep, MovesShorterThanTheSafeDistanceNeverMeetTheEdges) {
    std::mt19937_64 random(test::seed_for("ScalpelSweep.SafeMove"));
    std::uniform_real_distribution<double> coordinate(-1, 1);
    auto point = [&] { return Point{coordinate(random), coordinate(random), coordinate(random)}; };
    for (int trial = 0; trial < 200; ++trial) {
        const Point h = point(), t = point();
        std::vector<std::array<Point, 2>> edges;
        for (int k = 0; k < 4; ++k) edges.push_back({point(), point()});
        const double safe = largest_safe_move(h, t, edges);
        ASSERT_GT(safe, 0);
        for (int move = 0; move < 20; ++move) {
            // both ends moved by less than `safe`, in random directions
            auto short_move = [&] {
                Point p = point();
                const double length = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
                const double scale = 0.999 * safe * std::uniform_real_distribution<double>(0, 1)(random) / length;
                return Point{p[0] * scale, p[1] * scale, p[2] * scale};
            };
            const Point p = short_move(), q = short_move();
            const Point h1{h[0] + p[0], h[1] + p[1], h[2] + p[2]}, t1{t[0] + q[0], t[1] + q[1], t[2] + q[2]};
            for (const auto& [x, y] : edges)
                EXPECT_FALSE(first_sweep_hit(h, t, h1, t1, x, y)) << "trial " << trial << ", move " << move;
        }
    }
    // the bound is the distance: a blade along x at height 1 over an edge along y at height 0
    const std::array<std::array<Point, 2>, 1> edge{{{Point{0, -1, 0}, Point{0, 1, 0}}}};
    EXPECT_DOUBLE_EQ(largest_safe_move({-1, 0, 1}, {1, 0, 1}, edge), 1.0);
    EXPECT_FALSE(first_sweep_hit({-1, 0, 1}, {1, 0, 1}, {-1, 0, 0.001}, {1, 0, 0.001}, edge[0][0], edge[0][1]));
    EXPECT_TRUE(first_sweep_hit({-1, 0, 1}, {1, 0, 1}, {-1, 0, -0.001}, {1, 0, -0.001}, edge[0][0], edge[0][1]));
}

}  // namespace
}  // namespace sxk::delaunaycut
