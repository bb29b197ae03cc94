// Ray–patch intersection by triangular Bézier clipping (Roth §6.2–6.4): exact hits on flat
// patches, rays aimed at known points of random curved patches (every one must hit, on the patch
// to 1e-9 of its size, the nearest of several crossings), misses, the t window, and the teapot's
// collapsed knob corner. Random patches print their seed (SXK_SEED repeats a run).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "bezier_teapot.hpp"
#include "bezier_clipping.hpp"
#include "bezier_random.hpp"
#include "core/fixtures.hpp"
#include "patch_scene.hpp"
#include "read_bpt.hpp"
#include "vector3.hpp"

namespace sxk::bezier {
namespace {

using test_random::random_patch;
using test_random::random_point;

using test_teapot::along;

double diagonal(const TriangularPatch& patch) { return box_of(patch.control_points()).diagonal(); }

Point random_direction(std::mt19937_64& rng) {
    std::normal_distribution<double> g;
    return unit_or_zero({g(rng), g(rng), g(rng)});
}

// A wavy patch over the unit triangle: control points on a grid with random heights, so that
// rays at a slant may cross it more than once.
TriangularPatch wavy_patch(int degree, double amplitude, std::mt19937_64& rng) {
    std::uniform_real_distribution<double> height(-amplitude, amplitude);
    std::vector<Point> points(static_cast<std::size_t>((degree + 1) * (degree + 2) / 2));
    for (int k = 0; k <= degree; ++k)
        for (int j = 0; j <= degree - k; ++j)
            points[TriangularPatch::index(degree, j, k)] = {static_cast<double>(j) / degree,
                                                            static_cast<double>(k) / degree, height(rng)};
    return TriangularPatch(degree, points);
}

// The hit must lie on the patch and on the ray, with a unit normal.
void expect_on_patch(const TriangularPatch& patch, const Ray& ray, const PatchHit& hit) {
    const double tolerance = 1e-9 * diagonal(patch);
    EXPECT_LE(distance(along(ray, hit.t), patch.evaluate(hit.at)), tolerance);
    EXPECT_NEAR(hit.at[0] + hit.at[1] + hit.at[2], 1.0, 1e-12);
    for (double c : hit.at) EXPECT_GE(c, -1e-9);
    EXPECT_NEAR(std::sqrt(hit.normal[0] * hit.normal[0] + hit.normal[1] * hit.normal[1] +
                          hit.normal[2] * hit.normal[2]),
                1.0, 1e-9);
}

TEST(BezierClipping, FlatTriangleGivesTheExactHit) {
    // degree 1: the triangle (0,0,0) (1,0,0) (0,1,0) in the plane z = 0
    const TriangularPatch flat(1, {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
    const Ray down{{0.25, 0.5, 2}, {0, 0, -1}};
    const auto hit = intersect(flat, down);
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 2, 1e-12);
    // b(r,s,t) = r b_100 + s b_010 + t b_001 = (s, t, 0): s = 0.25, t = 0.5
    EXPECT_NEAR(hit->at[0], 0.25, 1e-12);
    EXPECT_NEAR(hit->at[1], 0.25, 1e-12);
    EXPECT_NEAR(hit->at[2], 0.5, 1e-12);
    EXPECT_NEAR(std::abs(hit->normal[2]), 1, 1e-12);
    // beyond the hypotenuse, and behind the origin
    EXPECT_FALSE(intersect(flat, Ray{{0.6, 0.6, 2}, {0, 0, -1}}));
    EXPECT_FALSE(intersect(flat, Ray{{0.25, 0.5, 2}, {0, 0, 1}}));
}

TEST(BezierClipping, RayThroughTheSharedEdgeHitsAPatch) {
    // two triangles sharing the edge (1,0,0)-(0,1,0); rays exactly through points of that edge
    const TriangularPatch a(1, {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
    const TriangularPatch b(1, {{1, 1, 0}, {0, 1, 0}, {1, 0, 0}});
    for (double x : {0.0, 0.125, 0.5, 0.875, 1.0}) {
        const Ray ray{{x, 1 - x, 1}, {0, 0, -1}};
        EXPECT_TRUE(intersect(a, ray) || intersect(b, ray)) << "x = " << x;
    }
}

TEST(BezierClipping, RaysAimedAtPointsOfCurvedPatchesHitThem) {
    std::mt19937_64 rng(test::seed_for("BezierClipping.RaysAimedAtPointsOfCurvedPatchesHitThem"));
    int rays = 0, at_target = 0;
    for (int degree = 1; degree <= 7; ++degree) {
        for (int trial = 0; trial < 10; ++trial) {
            const TriangularPatch patch = random_patch(degree, rng);
            for (int sample = 0; sample < 20; ++sample) {
                const Barycentric target = random_point(rng);
                const Point p = patch.evaluate(target);
                const Point d = random_direction(rng);
                const double back = 3;
                const Ray ray{{p[0] - back * d[0], p[1] - back * d[1], p[2] - back * d[2]}, d};
                const auto hit = intersect(patch, ray);
                ++rays;
                ASSERT_TRUE(hit) << "degree " << degree << " missed the point at (" << target[0] << ", " << target[1]
                                 << ", " << target[2] << ")";
                // the nearest hit: at the target, or before it where the ray crosses the patch
                // earlier; or, for a ray grazing the patch, its second crossing within the
                // clipping's parametric tolerance of the target (two crossings in one cell may
                // give the farther: bezier_clipping.hpp; SXK_SEED=682095474, degree 6, cos 3.6e-4,
                // the crossings 5.7e-5 apart in the domain and at t = 3 and 3.00003)
                if (hit->t > back * (1 + 1e-9)) {
                    const Point n = patch.normal(target);
                    const double grazing = std::abs(n[0] * d[0] + n[1] * d[1] + n[2] * d[2]);
                    double apart = 0;
                    for (std::size_t k = 0; k < 3; ++k) apart = std::max(apart, std::abs(hit->at[k] - target[k]));
                    EXPECT_LT(grazing, 1e-2) << "degree " << degree << ": t " << hit->t << " beyond the target";
                    EXPECT_LE(apart, ClippingOptions{}.parametric_tolerance)
                        << "degree " << degree << ": t " << hit->t << " beyond the target";
                }
                expect_on_patch(patch, ray, *hit);
                if (std::abs(hit->t - back) < 1e-9) ++at_target;
            }
        }
    }
    std::cout << rays << " rays, " << at_target << " nearest hit at the target\n";
    EXPECT_GT(at_target, rays / 2);
}

TEST(BezierClipping, ReportsTheNearestOfSeveralCrossings) {
    std::mt19937_64 rng(test::seed_for("BezierClipping.ReportsTheNearestOfSeveralCrossings"));
    int multiple = 0;
    for (int trial = 0; trial < 40; ++trial) {
        const TriangularPatch patch = wavy_patch(6, 0.3, rng);
        // a slanted ray through two points of the patch: it crosses at least those
        const Barycentric a = random_point(rng), b = random_point(rng);
        const Point pa = patch.evaluate(a), pb = patch.evaluate(b);
        const Point d = unit_or_zero({pb[0] - pa[0], pb[1] - pa[1], pb[2] - pa[2]});
        const Ray ray{{pa[0] - 2 * d[0], pa[1] - 2 * d[1], pa[2] - 2 * d[2]}, d};
        const auto hit = intersect(patch, ray);
        ASSERT_TRUE(hit);
        expect_on_patch(patch, ray, *hit);
        EXPECT_LE(hit->t, 2 * (1 + 1e-9));  // pa is a crossing, so the nearest is no farther
        // starting just after the nearest crossing finds the next one, farther on
        Ray after = ray;
        after.t_near = hit->t + 1e-6;
        if (const auto next = intersect(patch, after)) {
            EXPECT_GT(next->t, hit->t);
            expect_on_patch(patch, after, *next);
            ++multiple;
        }
    }
    std::cout << multiple << " of 40 rays crossed again after the nearest hit\n";
    EXPECT_GT(multiple, 20);  // every ray passes through pa and pb
}

TEST(BezierClipping, RespectsTheRayWindow) {
    const TriangularPatch flat(1, {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
    Ray ray{{0.25, 0.25, 2}, {0, 0, -1}};
    ray.t_far = 1.5;
    EXPECT_FALSE(intersect(flat, ray));
    ray.t_far = 2.5;
    ray.t_near = 2.1;
    EXPECT_FALSE(intersect(flat, ray));
    ray.t_near = 1.9;
    EXPECT_TRUE(intersect(flat, ray));
}

TEST(BezierClipping, MissesWhatLiesBesideTheRay) {
    std::mt19937_64 rng(test::seed_for("BezierClipping.MissesWhatLiesBesideTheRay"));
    const TriangularPatch patch = wavy_patch(6, 0.3, rng);
    // rays parallel to the patch's plane above its highest point, and rays passing beside it
    for (double y = -0.5; y <= 1.5; y += 0.25) {
        EXPECT_FALSE(intersect(patch, Ray{{-1, y, 0.5}, {1, 0, 0}}));
        EXPECT_FALSE(intersect(patch, Ray{{1.5, y, -1}, {0, 0, 1}}));
    }
}

TEST(BezierClipping, HitsTheTeapotKnobWhereAnEdgeCollapses) {
    // the lid's top row collapses to one point: the sextic halves there have a corner where seven
    // control points coincide (Roth Fig. 6.13). Rays straight down near the axis must hit.
    const std::vector<TriangularPatch> patches = to_triangular(read_bpt(SXK_TEST_DATA_DIR "/teapot.bpt"));
    double top = -1e9;
    for (const TriangularPatch& p : patches)
        for (const Point& b : p.control_points()) top = std::max(top, b[2]);
    int hits = 0;
    for (double x : {0.0, 1e-6, 1e-3, 0.01, 0.05}) {
        for (double y : {0.0, 1e-6, 0.01}) {
            const Ray ray{{x, y, top + 1}, {0, 0, -1}};
            double nearest = 1e300;
            for (const TriangularPatch& p : patches)
                if (const auto hit = intersect(p, ray)) {
                    expect_on_patch(p, ray, *hit);
                    nearest = std::min(nearest, hit->t);
                }
            EXPECT_LT(nearest, 2.0) << "no hit at the knob for x = " << x << ", y = " << y;
            hits += nearest < 1e300;
        }
    }
    EXPECT_EQ(hits, 15);
}

}  // namespace
}  // namespace sxk::bezier
