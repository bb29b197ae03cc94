// Issue 5's correctness checks on the teapot (64 sextic patches): at 512 x 512 primary rays on
// the whole teapot, and on close-ups of the points where patch edges collapse (the lid's knob at
// 256 x 256, its apex and the bottom's centre at 128 x 128):
//
//   no missed hits   the hit/miss mask of Scene::from_patches (Bézier clipping under Embree) equals
//                    the mask of the reference intersector (bezier_reference.hpp: dense
//                    subdivision to flatness 1e-7 x the diagonal, exact ray/triangle tests) except
//                    near a silhouette, checkably: a mismatching pixel is excused only when the
//                    reference itself answers differently for one of the four rays moved by
//                    +-4 x its tolerance along the two screen directions
//   nearest hit      where both hit, Scene::intersect's t is the reference's (no farther layer)
//   hits on patches  every hit Scene::intersect reports lies on its patch:
//                    |ray(t) - b(r,s)| <= 1e-9 x the bounding box diagonal
//
// and the checks' own checks: the reference intersector finds a paraboloid analytically, and the
// mask comparison rejects a coarse tessellation.
#include <gtest/gtest.h>

#include <tbb/blocked_range.h>
#include <tbb/combinable.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <limits>
#include <map>
#include <optional>
#include <mutex>
#include <sstream>
#include <string>
#include <vector>

#include "bezier_teapot.hpp"
#include "bezier_reference.hpp"
#include "patch_scene.hpp"
#include "read_bpt.hpp"
#include "render.hpp"
#include "triangular_patch.hpp"

namespace sxk::bezier {
namespace {

Point plus(const Point& a, const Point& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
Point scaled(double s, const Point& a) { return {s * a[0], s * a[1], s * a[2]}; }
Point cross(const Point& a, const Point& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double length(const Point& a) { return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]); }
Point unit(const Point& a) { return scaled(1 / length(a), a); }

using test_teapot::teapot;

// The teapot: its patches, the reference over them, and the scene under test.
struct Teapot {
    std::vector<TriangularPatch> patches = teapot();
    oracle::ReferencePatches reference{patches};
    Scene scene = Scene::from_patches(patches);
};

const Teapot& the_teapot() {
    static const Teapot teapot;
    return teapot;
}

// A picture the masks are compared on.
struct View {
    const char* name;
    Camera camera;
    int size;
};

// The picture: the whole teapot at 512 x 512, from (1, -2, 1.2), z up.
View whole_teapot() { return {"teapot", frame(the_teapot().scene.bounds(), {1, -2, 1.2}, {0, 0, 1}), 512}; }

// A close-up of the lid's knob (Roth Fig. 6.13), where four patches have an edge collapsed to the
// apex: the box of the control points above z = 2.7, from the same direction, at 256 x 256.
View knob_close_up() {
    Box knob{{1e300, 1e300, 1e300}, {-1e300, -1e300, -1e300}};
    for (const TriangularPatch& patch : the_teapot().patches)
        for (const Point& p : patch.control_points())
            if (p[2] > 2.7)
                for (std::size_t q = 0; q < 3; ++q) {
                    knob.lower[q] = std::min(knob.lower[q], p[q]);
                    knob.upper[q] = std::max(knob.upper[q], p[q]);
                }
    return {"knob", frame(knob, {1, -2, 1.2}, {0, 0, 1}), 256};
}

// Closer still, the points where four patches each have an edge collapsed: the lid's apex
// (0, 0, 3.15) from above and the bottom's centre (0, 0, 0) from below, boxes 0.1 wide, 128 x 128.
View lid_apex() { return {"lid apex", frame(Box{{-0.05, -0.05, 3.1}, {0.05, 0.05, 3.2}}, {1, -2, 1.2}, {0, 0, 1}), 128}; }
View bottom_centre() {
    return {"bottom centre", frame(Box{{-0.05, -0.05, -0.05}, {0.05, 0.05, 0.05}}, {1, -2, -1.2}, {0, 0, 1}), 128};
}

// The reference's tolerance: 1e-7 x the diagonal of the control points' box (issue 5), and the
// bisection depth that takes every leaf the test rays reach below it (checked: coarse_leaves).
oracle::ReferenceOptions reference_options() {
    oracle::ReferenceOptions options;
    options.tolerance = 1e-7 * the_teapot().reference.diagonal();
    options.depth = 24;
    return options;
}

// The reference's mask of a view, computed once per view (rows in parallel), and its statistics.
struct ReferenceMask {
    std::vector<std::uint8_t> hits;
    std::vector<double> t;  // of the nearest hit; NaN for a miss
    oracle::ReferenceStats stats;
};

const ReferenceMask& reference_mask(const View& view) {
    static std::map<std::string, ReferenceMask> cache;
    static std::mutex guard;
    std::lock_guard<std::mutex> lock(guard);
    const auto known = cache.find(view.name);
    if (known != cache.end()) return known->second;
    ReferenceMask made;
    made.hits.resize(std::size_t(view.size) * view.size);
    made.t.resize(made.hits.size(), std::numeric_limits<double>::quiet_NaN());
    tbb::combinable<oracle::ReferenceStats> stats;
    const oracle::ReferenceOptions options = reference_options();
    tbb::parallel_for(tbb::blocked_range<int>(0, view.size), [&](const tbb::blocked_range<int>& rows) {
        for (int y = rows.begin(); y != rows.end(); ++y)
            for (int x = 0; x < view.size; ++x) {
                const std::size_t pixel = std::size_t(y) * view.size + x;
                const auto hit = oracle::reference_intersect(
                    the_teapot().reference, primary_ray(view.camera, view.size, view.size, x, y), options, &stats.local());
                made.hits[pixel] = hit.has_value();
                if (hit) made.t[pixel] = hit->t;
            }
    });
    stats.combine_each([&](const oracle::ReferenceStats& s) { made.stats.add(s); });
    return cache.emplace(view.name, std::move(made)).first->second;
}

// A mask against the reference: mismatching pixels, and among them those near a silhouette,
// where the reference's answer changes for one of the four rays moved by +-shift along the
// camera's right and up directions (shift = 4 x the reference's tolerance: more than the
// reference's and the clipping's errors together, also for a silhouette running diagonally).
struct Comparison {
    int hits = 0, silhouette_pixels = 0, mismatches = 0, near_silhouette = 0;
    std::vector<std::string> unexcused;  // the mismatches away from any silhouette
};

Comparison compare(const View& view, const std::vector<std::uint8_t>& mask) {
    const ReferenceMask& reference = reference_mask(view);
    const oracle::ReferenceOptions options = reference_options();
    const double shift = 4 * options.tolerance;
    const Point forward = unit(plus(view.camera.target, scaled(-1, view.camera.eye)));
    const Point right = unit(cross(forward, view.camera.up));
    const Point up = cross(right, forward);
    Comparison result;
    std::vector<std::size_t> mismatching;
    for (int y = 0; y < view.size; ++y)
        for (int x = 0; x < view.size; ++x) {
            const std::size_t pixel = std::size_t(y) * view.size + x;
            const std::uint8_t value = reference.hits[pixel];
            result.hits += value;
            if (bool(mask[pixel]) != bool(value)) mismatching.push_back(pixel);
            // silhouette pixels of the reference mask (a 4-neighbour differs), for scale
            bool edge = false;
            for (const auto& [dx, dy] : {std::array<int, 2>{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
                const int u = x + dx, v = y + dy;
                if (u >= 0 && v >= 0 && u < view.size && v < view.size)
                    edge |= reference.hits[std::size_t(v) * view.size + u] != value;
            }
            result.silhouette_pixels += edge;
        }
    result.mismatches = int(mismatching.size());
    std::vector<std::uint8_t> unstable(mismatching.size());
    tbb::parallel_for(std::size_t{0}, mismatching.size(), [&](std::size_t i) {
        const int x = int(mismatching[i] % view.size), y = int(mismatching[i] / view.size);
        const Ray ray = primary_ray(view.camera, view.size, view.size, x, y);
        const bool hit = reference.hits[mismatching[i]];
        for (const Point& direction : {right, scaled(-1, right), up, scaled(-1, up)}) {
            Ray moved = ray;
            moved.origin = plus(ray.origin, scaled(shift, direction));
            unstable[i] |= oracle::reference_intersect(the_teapot().reference, moved, options).has_value() != hit;
        }
    });
    for (std::size_t i = 0; i < mismatching.size(); ++i) {
        if (unstable[i]) {
            ++result.near_silhouette;
            continue;
        }
        const bool hit = reference.hits[mismatching[i]];
        std::ostringstream text;
        text << "pixel (" << mismatching[i] % view.size << ", " << mismatching[i] / view.size << "): the mask "
             << (hit ? "misses" : "hits") << ", the reference " << (hit ? "hits" : "misses")
             << " and keeps its answer for the ray moved by " << shift;
        result.unexcused.push_back(text.str());
    }
    return result;
}

// The scene's mask of a view against the reference's, printed and asserted.
void expect_no_missed_hits(const View& view) {
    const std::vector<std::uint8_t> mask = hit_mask(the_teapot().scene, view.camera, view.size, view.size);
    ASSERT_EQ(mask.size(), std::size_t(view.size) * view.size);
    const Comparison result = compare(view, mask);
    const ReferenceMask& reference = reference_mask(view);
    const oracle::ReferenceStats& stats = reference.stats;
    const oracle::ReferenceOptions options = reference_options();
    // where both hit, the scene's nearest hit is the reference's: the same t up to the tolerance
    // over the cosine of the angle of incidence; 1e-4 x the diagonal is far above that but below
    // the distance between two layers of the teapot, so a farther layer reported is caught
    const double layer_gap = 1e-4 * the_teapot().reference.diagonal();
    tbb::combinable<double> worst_t([] { return 0.0; });
    tbb::combinable<int> other_layer([] { return 0; });
    tbb::parallel_for(tbb::blocked_range<int>(0, view.size), [&](const tbb::blocked_range<int>& rows) {
        for (int y = rows.begin(); y != rows.end(); ++y)
            for (int x = 0; x < view.size; ++x) {
                const std::size_t pixel = std::size_t(y) * view.size + x;
                if (!mask[pixel] || !reference.hits[pixel]) continue;
                const auto hit = the_teapot().scene.intersect(primary_ray(view.camera, view.size, view.size, x, y));
                const double difference = hit ? std::abs(hit->t - reference.t[pixel]) : 0.0;
                worst_t.local() = std::max(worst_t.local(), difference);
                other_layer.local() += difference > layer_gap;
            }
    });
    const double worst_difference = worst_t.combine([](double a, double b) { return std::max(a, b); });
    const int farther = other_layer.combine(std::plus<int>());
    std::cout << "[ mask     ] " << view.name << " " << view.size << "x" << view.size << ": reference hits "
              << result.hits << ", silhouette pixels " << result.silhouette_pixels << ", mismatches "
              << result.mismatches << " (near a silhouette: " << result.near_silhouette << ")\n"
              << "[ mask     ] reference: tolerance " << options.tolerance << " (1e-7 x diagonal "
              << the_teapot().reference.diagonal() << "), depth " << options.depth << ", " << stats.rays
              << " rays, " << stats.bisections << " bisections, " << stats.leaves
              << " leaves, worst leaf deviation " << stats.worst_deviation << ", coarse leaves "
              << stats.coarse_leaves << "\n"
              << "[ mask     ] nearest hit: largest |t - reference t| " << worst_difference << ", above "
              << layer_gap << ": " << farther << std::endl;
    EXPECT_EQ(farther, 0) << "hits farther than the reference's nearest";
    EXPECT_EQ(stats.coarse_leaves, 0u) << "depth " << options.depth << " leaves leaves above the tolerance";
    EXPECT_TRUE(result.unexcused.empty()) << result.unexcused.size() << " mismatches away from a silhouette, first: "
                                          << (result.unexcused.empty() ? "" : result.unexcused.front());
    EXPECT_GT(result.hits, view.size * view.size / 10) << "the view should show a good part of the teapot";
}

// The point an edge of the patch collapsed to (two equal corners), if one did.
std::optional<Point> collapsed_corner(const TriangularPatch& patch) {
    const int n = patch.degree();
    const Point &a = patch.control_point(0, 0), &b = patch.control_point(n, 0), &c = patch.control_point(0, n);
    if (a == b || a == c) return a;
    if (b == c) return b;
    return std::nullopt;
}

// Every hit Scene::intersect reports in a view lies on its patch. Returns the number of hits
// within 1e-3 x the diagonal of a point a patch edge collapsed to (the knob's apex).
int expect_hits_on_patches(const View& view) {
    const Teapot& teapot = the_teapot();
    const double diagonal = teapot.scene.bounds().diagonal();
    const double allowed = 1e-9 * diagonal;
    tbb::combinable<int> hits([] { return 0; }), off_patch([] { return 0; }), at_apex([] { return 0; });
    tbb::combinable<double> worst([] { return 0.0; });
    std::mutex report;
    tbb::parallel_for(tbb::blocked_range<int>(0, view.size), [&](const tbb::blocked_range<int>& rows) {
        for (int y = rows.begin(); y != rows.end(); ++y)
            for (int x = 0; x < view.size; ++x) {
                const Ray ray = primary_ray(view.camera, view.size, view.size, x, y);
                const auto hit = teapot.scene.intersect(ray);
                if (!hit) continue;
                ++hits.local();
                double distance = std::numeric_limits<double>::infinity();
                if (hit->primitive < teapot.patches.size()) {
                    const TriangularPatch& patch = teapot.patches[hit->primitive];
                    const Point on_ray = plus(ray.origin, scaled(hit->t, ray.direction));
                    distance = length(plus(on_ray, scaled(-1, patch.evaluate(hit->at))));
                    if (const auto apex = collapsed_corner(patch))
                        at_apex.local() += length(plus(on_ray, scaled(-1, *apex))) < 1e-3 * diagonal;
                }
                worst.local() = std::max(worst.local(), distance);
                if (distance > allowed && ++off_patch.local() <= 5) {
                    std::lock_guard<std::mutex> lock(report);
                    ADD_FAILURE() << view.name << " pixel (" << x << ", " << y << "): hit " << distance
                                  << " from patch " << hit->primitive << " at (" << hit->at[0] << ", " << hit->at[1]
                                  << ", " << hit->at[2] << ")";
                }
            }
    });
    const int total_hits = hits.combine(std::plus<int>());
    const int apex_hits = at_apex.combine(std::plus<int>());
    std::cout << "[ on patch ] " << view.name << ": " << total_hits << " hits, off the patch by more than " << allowed
              << ": " << off_patch.combine(std::plus<int>()) << ", worst distance "
              << worst.combine([](double a, double b) { return std::max(a, b); }) << "; hits within "
              << 1e-3 * diagonal << " of a collapsed edge: " << apex_hits << std::endl;
    EXPECT_GT(total_hits, view.size * view.size / 10);
    return apex_hits;
}

// The paraboloid z = x^2 + y^2 over the triangle (0,0) (1,0) (0,1) is the
// quadratic patch x = s, y = t, z = s^2 + t^2; its control points (blossoms of s^2 + t^2):
//
//   b_002 (0, 1, 1)                        a ray straight down through (x, y)
//     |      \ .                           meets it at z = x^2 + y^2
//   b_101 (0, .5, 0) -- b_011 (.5, .5, 0)
//     |                   \ .
//   b_200 (0, 0, 0) -- b_110 (.5, 0, 0) -- b_020 (1, 0, 1)
TEST(ReferenceIntersector, FindsAParaboloidWithinItsTolerance) {
    const TriangularPatch paraboloid(2, {{0, 0, 0}, {0.5, 0, 0}, {1, 0, 1}, {0, 0.5, 0}, {0.5, 0.5, 0}, {0, 1, 1}});
    const oracle::ReferencePatches patches({paraboloid});
    oracle::ReferenceOptions options;
    options.tolerance = 1e-7;
    options.depth = 24;
    oracle::ReferenceStats stats;
    for (const auto& [x, y] : std::vector<std::array<double, 2>>{{0.1, 0.2}, {0.5, 0.25}, {0.3, 0.69}, {0.01, 0.01}}) {
        const auto hit = oracle::reference_intersect(patches, Ray{{x, y, 10}, {0, 0, -1}}, options, &stats);
        ASSERT_TRUE(hit) << x << " " << y;
        EXPECT_NEAR(hit->t, 10 - (x * x + y * y), options.tolerance) << x << " " << y;
    }
    // beside the triangle, and pointing away
    EXPECT_FALSE(oracle::reference_intersect(patches, Ray{{0.6, 0.6, 10}, {0, 0, -1}}, options, &stats));
    EXPECT_FALSE(oracle::reference_intersect(patches, Ray{{0.2, 0.2, 10}, {0, 0, 1}}, options, &stats));
    EXPECT_EQ(stats.coarse_leaves, 0u);
    EXPECT_LE(stats.worst_deviation, options.tolerance);
}

TEST(TeapotMask, MatchesTheReferenceExceptNearSilhouettes) { expect_no_missed_hits(whole_teapot()); }

TEST(TeapotMask, MatchesTheReferenceAtTheKnob) { expect_no_missed_hits(knob_close_up()); }

TEST(TeapotMask, MatchesTheReferenceAtCollapsedEdges) {
    expect_no_missed_hits(lid_apex());
    expect_no_missed_hits(bottom_centre());
}

// The check is not vacuous: Embree's triangles on a coarse tessellation (8 segments per patch
// edge, errors of some 1e-3 x the diagonal) miss and add hits well away from any silhouette.
TEST(TeapotMask, CatchesACoarseTessellation) {
    const View view = whole_teapot();
    const Scene coarse = Scene::from_triangles(tessellate(the_teapot().patches, 8));
    const Comparison result = compare(view, hit_mask(coarse, view.camera, view.size, view.size));
    std::cout << "[ mask     ] 8 segments: mismatches " << result.mismatches << " (near a silhouette: "
              << result.near_silhouette << ", away: " << result.unexcused.size() << ")" << std::endl;
    EXPECT_GT(result.unexcused.size(), 10u);
}

TEST(TeapotMask, EveryHitLiesOnItsPatch) {
    expect_hits_on_patches(whole_teapot());
    expect_hits_on_patches(knob_close_up());
    EXPECT_GT(expect_hits_on_patches(lid_apex()), 20) << "the close-up should show the lid's apex";
    EXPECT_GT(expect_hits_on_patches(bottom_centre()), 20) << "the close-up should show the bottom's centre";
}

}  // namespace
}  // namespace sxk::bezier
