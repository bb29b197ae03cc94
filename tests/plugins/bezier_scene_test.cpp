// The Embree scene (patch_scene.hpp, flat_subdivision.hpp): Roth's flatness split (§6.4), patch
// scenes (Embree user geometry + Bézier clipping) and triangle scenes hit where they should,
// hits lie on the original patch, and the uniform tessellation and its error bound.
//
//   the flat fixture: one degree-1 patch (and the same as a triangle) in the plane z = 0
//
//     y                        control points b_100 = a, b_010 = b, b_001 = c;
//     ^ c (0,1,0)              normal D_u x D_v = (b - a) x (c - a) = +z;
//     | \                      a ray straight down through (x, y) hits it at
//     |   \                    (r, s, t) = (1 - x - y, x, y) when x, y >= 0 and x + y <= 1
//     a ---- b -> x
//   (0,0,0) (1,0,0)
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "bezier_teapot.hpp"
#include "bezier_random.hpp"
#include "core/fixtures.hpp"
#include "flat_subdivision.hpp"
#include "patch_scene.hpp"
#include "read_bpt.hpp"
#include "vector3.hpp"

namespace sxk::bezier {
namespace {

using test_random::random_point;

using test_teapot::along;

TriangularPatch flat_patch() {
    return TriangularPatch(1, {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
}

Ray downward(double x, double y) {
    return Ray{{x, y, 5}, {0, 0, -1}};
}

using test_teapot::teapot;

// A curved patch of the given degree over the unit triangle: a flat net lifted and jittered,
// so that it bends but does not fold over itself.
TriangularPatch curved_patch(int degree, std::mt19937_64& rng) {
    std::uniform_real_distribution<double> lift(-0.4, 0.4), jitter(-0.05, 0.05);
    std::vector<Point> points(static_cast<std::size_t>((degree + 1) * (degree + 2) / 2));
    for (int k = 0; k <= degree; ++k)
        for (int j = 0; j + k <= degree; ++j)
            points[TriangularPatch::index(degree, j, k)] = {
                double(j) / degree + jitter(rng), double(k) / degree + jitter(rng), lift(rng)};
    return TriangularPatch(degree, points);
}

TEST(FlatSubdivision, RothHeightOfAFlatAndOfABentPatch) {
    EXPECT_EQ(roth_height(flat_patch()), 0.0);
    // degree 2, the middle of edge b_100 - b_010 lifted to z = 1: h = 1 (corners in z = 0)
    const TriangularPatch bent(
        2, {{0, 0, 0}, {0.5, 0, 1}, {1, 0, 0}, {0, 0.5, 0}, {0.5, 0.5, 0}, {0, 1, 0}});
    EXPECT_DOUBLE_EQ(roth_height(bent), 1.0);
    // corners b_200 = b_020 (no corner plane), the patch in z = 0: measured along the patch's
    // own normal, flat
    const TriangularPatch collapsed(
        2, {{0, 0, 0}, {1, 0, 0}, {0, 0, 0}, {0.5, 0.5, 0}, {-0.5, 0.5, 0}, {0, 1, 0}});
    EXPECT_NEAR(roth_height(collapsed), 0.0, 1e-15);
    // and bent out of the plane at b_110 by 0.5: the extent along the centroid normal
    const TriangularPatch bent_collapsed(
        2, {{0, 0, 0}, {1, 0, 0.5}, {0, 0, 0}, {0.5, 0.5, 0}, {-0.5, 0.5, 0}, {0, 1, 0}});
    const Point normal = bent_collapsed.normal({1.0 / 3, 1.0 / 3, 1.0 / 3});
    double highest = 0, lowest = 0;
    for (const Point& p : bent_collapsed.control_points())
        highest = std::max(highest, dot(normal, p)), lowest = std::min(lowest, dot(normal, p));
    EXPECT_GT(highest - lowest, 0.1);
    EXPECT_NEAR(roth_height(bent_collapsed), highest - lowest, 1e-15);
    // a patch flat to a line (no normal anywhere): the box diagonal
    const TriangularPatch line(2,
                               {{0, 0, 0}, {1, 0, 0}, {0, 0, 0}, {2, 0, 0}, {3, 0, 0}, {0, 0, 0}});
    EXPECT_DOUBLE_EQ(roth_height(line), 3.0);
}

// Every piece is the original surface over its corners, keeps the orientation, and is flat.
TEST(FlatSubdivision, PiecesReproduceThePatchAndKeepItsOrientation) {
    std::mt19937_64 rng(
        test::seed_for("FlatSubdivision.PiecesReproduceThePatchAndKeepItsOrientation"));
    const std::vector<TriangularPatch> patches{curved_patch(4, rng), curved_patch(2, rng)};
    const std::vector<SubPatch> pieces = flat_subdivision(patches, 0.01, 6);
    ASSERT_GT(pieces.size(), 8u);
    double area[2] = {0, 0};
    for (const SubPatch& piece : pieces) {
        ASSERT_LT(piece.patch, 2u);
        const TriangularPatch& original = patches[piece.patch];
        EXPECT_LE(roth_height(piece.surface), 0.01);
        // the domain area of the piece (its corners' barycentric triangle, signed)
        const auto& [a, b, c] = piece.corners;
        area[piece.patch] += (b[1] - a[1]) * (c[2] - a[2]) - (b[2] - a[2]) * (c[1] - a[1]);
        for (int sample = 0; sample < 4; ++sample) {
            const Barycentric local = random_point(rng);
            Barycentric global{};
            for (std::size_t q = 0; q < 3; ++q)
                global[q] = local[0] * a[q] + local[1] * b[q] + local[2] * c[q];
            EXPECT_LT(distance(piece.surface.evaluate(local), original.evaluate(global)), 1e-13);
            EXPECT_GT(dot(piece.surface.normal(local), original.normal(global)), 0.999);
        }
    }
    // the pieces tile the domain, all positively
    EXPECT_NEAR(area[0], 1.0, 1e-12);
    EXPECT_NEAR(area[1], 1.0, 1e-12);
}

TEST(FlatSubdivision, StopsAtTheDepthBound) {
    std::mt19937_64 rng(test::seed_for("FlatSubdivision.StopsAtTheDepthBound"));
    EXPECT_EQ(flat_subdivision({curved_patch(3, rng)}, 0, 3).size(), 64u);
    EXPECT_EQ(flat_subdivision({curved_patch(3, rng)}, 0, 0).size(), 1u);
    EXPECT_THROW(flat_subdivision({flat_patch()}, 0.1, -1), std::invalid_argument);
}

// Issue 12: the split stops as soon as its pieces would take more than max_bytes (leaf_bytes
// each), in every patch, and says how many it made; pieces of one degree make that count exact.
TEST(FlatSubdivision, StopsAtItsMemoryBound) {
    std::mt19937_64 rng(test::seed_for("FlatSubdivision.StopsAtItsMemoryBound"));
    const std::vector<TriangularPatch> patches{curved_patch(3, rng), curved_patch(3, rng)};
    EXPECT_EQ(leaf_bytes(3), 10 * sizeof(Point) + 256);
    // depth 3 at height 0: 64 pieces per patch
    EXPECT_EQ(flat_subdivision(patches, 0, 3, 128 * leaf_bytes(3)).size(), 128u);
    try {
        (void)flat_subdivision(patches, 0, 3, 40 * leaf_bytes(3) + 100);
        ADD_FAILURE() << "no SubdivisionTooLarge";
    } catch (const SubdivisionTooLarge& error) {
        EXPECT_EQ(error.max_bytes(), 40 * leaf_bytes(3) + 100);
        EXPECT_EQ(error.pieces(), 40u);
        EXPECT_EQ(std::string(error.what()),
                  "flat_subdivision: the pieces would take more than 19940 bytes (40 made when it "
                  "stopped)");
    }
}

// Issue 12: a flatness below what the scene's rounding resolves is refused (smallest_flatness:
// 1e-12 x (diagonal + largest coordinate) / diagonal), before anything is split.
TEST(PatchScene, RefusesAFlatnessBelowRounding) {
    const Box box = box_of(flat_patch().control_points());  // (0,0,0) to (1,1,0)
    EXPECT_DOUBLE_EQ(smallest_flatness(box), 1e-12 * (std::sqrt(2.0) + 1) / std::sqrt(2.0));
    EXPECT_EQ(smallest_flatness(Box{{2, 2, 2}, {2, 2, 2}}), 0);
    PatchSceneOptions options;
    options.flatness = 1e-13;
    try {
        (void)Scene::from_patches({flat_patch()}, options);
        ADD_FAILURE() << "no refusal";
    } catch (const std::invalid_argument& error) {
        EXPECT_EQ(std::string(error.what()),
                  "Scene::from_patches: flatness 1e-13 is below the smallest the scene's rounding "
                  "resolves, 1.71e-12");
    }
    options.flatness = smallest_flatness(box);
    EXPECT_EQ(Scene::from_patches({flat_patch()}, options).leaf_count(), 1u);
}

TEST(PatchScene, FlatPatchHitsAndMisses) {
    const Scene scene = Scene::from_patches({flat_patch()});
    EXPECT_EQ(scene.primitive_count(), 1u);
    EXPECT_EQ(scene.leaf_count(), 1u);
    const auto hit = scene.intersect(downward(0.25, 0.5));
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 5.0, 1e-12);
    EXPECT_EQ(hit->primitive, 0u);
    EXPECT_NEAR(hit->at[0], 0.25, 1e-12);
    EXPECT_NEAR(hit->at[1], 0.25, 1e-12);
    EXPECT_NEAR(hit->at[2], 0.5, 1e-12);
    EXPECT_NEAR(distance(hit->normal, {0, 0, 1}), 0, 1e-12);
    // from below: same normal (not turned toward the ray)
    const auto below = scene.intersect(Ray{{0.1, 0.1, -2}, {0, 0, 1}});
    ASSERT_TRUE(below);
    EXPECT_NEAR(below->t, 2.0, 1e-12);
    EXPECT_NEAR(distance(below->normal, {0, 0, 1}), 0, 1e-12);
    // beside the triangle, beyond t_far, before t_near, parallel to the plane
    EXPECT_FALSE(scene.intersect(downward(0.6, 0.6)));
    EXPECT_FALSE(scene.intersect(downward(-0.1, 0.5)));
    EXPECT_FALSE(scene.intersect(Ray{{0.2, 0.2, 5}, {0, 0, -1}, 0, 4.5}));
    EXPECT_FALSE(scene.intersect(Ray{{0.2, 0.2, 5}, {0, 0, -1}, 5.5}));
    EXPECT_FALSE(scene.intersect(Ray{{-1, 0.2, 0.5}, {1, 0, 0}}));
    EXPECT_TRUE(scene.occluded(downward(0.25, 0.5)));
    EXPECT_FALSE(scene.occluded(downward(0.6, 0.6)));
    EXPECT_FALSE(scene.occluded(Ray{{0.2, 0.2, 5}, {0, 0, -1}, 0, 4.5}));
    const Box box = scene.bounds();
    EXPECT_EQ(box.lower, (Point{0, 0, 0}));
    EXPECT_EQ(box.upper, (Point{1, 1, 0}));
    EXPECT_DOUBLE_EQ(box.diagonal(), std::sqrt(2.0));
}

// Double precision end to end: a patch far from the origin in a scene far larger than float
// resolves, hit at a t that float could not represent.
TEST(PatchScene, HitsAreExactInDoubleNotFloat) {
    const Point o{1000, 1000, 0};
    std::vector<TriangularPatch> patches{
        TriangularPatch(1, {{o[0], o[1], 0}, {o[0] + 1, o[1], 0}, {o[0], o[1] + 1, 0}})};
    const Scene scene = Scene::from_patches(patches);
    const double x = o[0] + 0.123456789012, y = o[1] + 0.3;
    const auto hit = scene.intersect(Ray{{x, y, 3.000000001}, {0, 0, -1}});
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 3.000000001, 1e-12);
    EXPECT_NEAR(hit->at[1], 0.123456789012, 1e-9);
}

// Embree traces a float copy of the ray; from a million units away its rounding moves it by
// about 0.1, far more than the leaves' box margin. Rays aimed from there at points just inside
// the corners of the flat triangle must still hit (the scene starts Embree's float ray where
// the double ray enters the scene's box).
TEST(PatchScene, FarRaysHitNearCorners) {
    const Scene patches = Scene::from_patches({flat_patch()});
    const Scene triangles =
        Scene::from_triangles(TriangleSoup{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}}});
    const std::vector<Point> targets{
        {1e-7, 1e-7, 0}, {1 - 2e-7, 1e-7, 0}, {1e-7, 1 - 2e-7, 0}, {0.5 - 1e-7, 0.5 - 1e-7, 0}};
    const std::vector<Point> origins{
        {3e5, 2e5, 1e6}, {-7e5, 1e5, 1e6}, {1e5, -9e5, -1e6}, {-1.3e6, -0.7e6, 0.3e6}};
    for (const Point& target : targets)
        for (const Point& origin : origins) {
            Point direction{target[0] - origin[0], target[1] - origin[1], target[2] - origin[2]};
            const double length = std::sqrt(dot(direction, direction));
            for (double& x : direction)
                x /= length;
            const Ray ray{origin, direction};
            for (const Scene* scene : {&patches, &triangles}) {
                const auto hit = scene->intersect(ray);
                ASSERT_TRUE(hit) << "target " << target[0] << " " << target[1] << " from "
                                 << origin[0];
                EXPECT_LE(distance(along(ray, hit->t), target), 1e-9);
                EXPECT_TRUE(scene->occluded(ray));
            }
        }
}

TEST(TriangleScene, HitsAndMissesWithTheRightHandNormal) {
    // the flat triangle and, above it, the same triangle reversed (normal -z) shifted by (1, 1)
    TriangleSoup soup{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 1}, {1, 2, 1}, {2, 1, 1}},
                      {{0, 1, 2}, {3, 4, 5}}};
    const Scene scene = Scene::from_triangles(soup);
    EXPECT_EQ(scene.primitive_count(), 2u);
    EXPECT_EQ(scene.leaf_count(), 2u);
    const auto first = scene.intersect(downward(0.25, 0.5));
    ASSERT_TRUE(first);
    EXPECT_EQ(first->primitive, 0u);
    EXPECT_NEAR(first->t, 5.0, 1e-12);
    EXPECT_NEAR(first->at[0], 0.25, 1e-12);
    EXPECT_NEAR(first->at[1], 0.25, 1e-12);
    EXPECT_NEAR(first->at[2], 0.5, 1e-12);
    EXPECT_NEAR(distance(first->normal, {0, 0, 1}), 0, 1e-15);
    const auto second = scene.intersect(downward(1.2, 1.1));
    ASSERT_TRUE(second);
    EXPECT_EQ(second->primitive, 1u);
    EXPECT_NEAR(second->t, 4.0, 1e-12);
    // at = (1 - u - v, u, v) for the corners 3, 4, 5: (1.2, 1.1) = 3 + 0.1 (4 - 3) + 0.2 (5 - 3)
    EXPECT_NEAR(second->at[1], 0.1, 1e-12);
    EXPECT_NEAR(second->at[2], 0.2, 1e-12);
    EXPECT_NEAR(distance(second->normal, {0, 0, -1}), 0, 1e-15);
    EXPECT_FALSE(scene.intersect(downward(0.9, 0.9)));
    EXPECT_TRUE(scene.occluded(downward(1.2, 1.1)));
    EXPECT_FALSE(scene.occluded(Ray{{1.2, 1.1, 5}, {0, 0, -1}, 0, 3.9}));
    EXPECT_THROW(Scene::from_triangles(TriangleSoup{{{0, 0, 0}}, {{0, 0, 1}}}),
                 std::invalid_argument);
}

TEST(TriangleScene, EmptyScenesMissEverything) {
    EXPECT_FALSE(Scene::from_triangles({}).intersect(downward(0, 0)));
    EXPECT_FALSE(Scene::from_patches({}).intersect(downward(0, 0)));
    EXPECT_EQ(Scene::from_patches({}).leaf_count(), 0u);
}

// Rays aimed at random points of random curved patches: every hit lies on the ORIGINAL patch at
// SceneHit::at (issue 5: |ray(t) - b(at)| <= 1e-9 x box diagonal), no nearer than the aimed
// point's parameter allows, and with the original patch's normal.
TEST(PatchScene, EveryHitLiesOnTheOriginalPatch) {
    std::mt19937_64 rng(test::seed_for("PatchScene.EveryHitLiesOnTheOriginalPatch"));
    std::uniform_real_distribution<double> coordinate(-1, 1);
    int hits = 0, rays = 0;
    for (int trial = 0; trial < 6; ++trial) {
        const std::vector<TriangularPatch> patches{curved_patch(2 + trial % 5, rng)};
        PatchSceneOptions options;
        options.flatness = trial % 2 == 0 ? 1e-2 : 1e-1;
        const Scene scene = Scene::from_patches(patches, options);
        const double diagonal = scene.bounds().diagonal();
        for (int i = 0; i < 60; ++i, ++rays) {
            // strictly inside the domain, so the aimed point itself is a hit
            Barycentric aim = random_point(rng);
            for (double& x : aim)
                x = 0.02 + 0.94 * x;
            const Point target = patches[0].evaluate(aim);
            const Point origin{target[0] + 3 * coordinate(rng), target[1] + 3 * coordinate(rng),
                               target[2] + 3 * coordinate(rng)};
            Point direction{target[0] - origin[0], target[1] - origin[1], target[2] - origin[2]};
            const double length = std::sqrt(dot(direction, direction));
            for (double& x : direction)
                x /= length;
            const Ray ray{origin, direction};
            const auto hit = scene.intersect(ray);
            ASSERT_TRUE(hit) << "trial " << trial << " ray " << i;
            ++hits;
            EXPECT_EQ(hit->primitive, 0u);
            EXPECT_LE(distance(along(ray, hit->t), patches[0].evaluate(hit->at)), 1e-9 * diagonal);
            EXPECT_LE(hit->t, length + 1e-9 * diagonal);
            EXPECT_NEAR(distance(hit->normal, patches[0].normal(hit->at)), 0, 1e-9);
            EXPECT_TRUE(scene.occluded(ray));
        }
    }
    EXPECT_EQ(hits, rays);
}

// The teapot (Roth §6.4): 64 sextic patches, split finer for a smaller flatness; its knob and
// bottom have collapsed corners and must split without trouble; rays from outside toward the
// centre hit, and their hits lie on the patches.
TEST(PatchScene, Teapot) {
    const std::vector<TriangularPatch> patches = teapot();
    PatchSceneOptions coarse_options;
    coarse_options.flatness = 1e-2;
    const Scene coarse = Scene::from_patches(patches, coarse_options);
    EXPECT_EQ(coarse.primitive_count(), 64u);
    EXPECT_GT(coarse.leaf_count(), 64u);
    const Scene fine = Scene::from_patches(patches);  // the default, 1e-3
    EXPECT_GT(fine.leaf_count(), coarse.leaf_count());
    std::cout << "[ leaves   ] teapot: " << coarse.leaf_count() << " at flatness 1e-2, "
              << fine.leaf_count() << " at 1e-3" << std::endl;

    std::mt19937_64 rng(test::seed_for("PatchScene.Teapot"));
    std::normal_distribution<double> gaussian;
    const Box box = coarse.bounds();
    const double diagonal = box.diagonal();
    const Point centre{(box.lower[0] + box.upper[0]) / 2, (box.lower[1] + box.upper[1]) / 2,
                       (box.lower[2] + box.upper[2]) / 2};
    for (int i = 0; i < 200; ++i) {
        Point from{gaussian(rng), gaussian(rng), gaussian(rng)};
        const double length = std::sqrt(dot(from, from));
        const Point origin{centre[0] + 2 * diagonal * from[0] / length,
                           centre[1] + 2 * diagonal * from[1] / length,
                           centre[2] + 2 * diagonal * from[2] / length};
        Point direction{centre[0] - origin[0], centre[1] - origin[1], centre[2] - origin[2]};
        const double d = std::sqrt(dot(direction, direction));
        for (double& x : direction)
            x /= d;
        const Ray ray{origin, direction};
        for (const Scene* scene : {&coarse, &fine}) {
            const auto hit = scene->intersect(ray);
            // the centre lies inside the closed body: every ray toward it meets the surface first
            ASSERT_TRUE(hit) << "ray " << i;
            ASSERT_LT(hit->primitive, 64u);
            EXPECT_LE(distance(along(ray, hit->t), patches[hit->primitive].evaluate(hit->at)),
                      1e-9 * diagonal);
            EXPECT_NEAR(std::sqrt(dot(hit->normal, hit->normal)), 1.0, 1e-12);
        }
        // both scenes hold the same surface: the same nearest hit
        EXPECT_NEAR(coarse.intersect(ray)->t, fine.intersect(ray)->t, 1e-9 * diagonal);
    }
}

// Vertices on the patch at the grid points, triangles oriented like the patch (their right-hand
// normal agrees with TriangularPatch::normal at their domain centroid).
TEST(Tessellate, CountsPositionsAndOrientation) {
    std::mt19937_64 rng(test::seed_for("Tessellate.CountsPositionsAndOrientation"));
    const std::vector<TriangularPatch> patches{curved_patch(3, rng), curved_patch(5, rng)};
    for (int segments : {1, 2, 16}) {
        const TriangleSoup soup = tessellate(patches, segments);
        const std::size_t per_patch = static_cast<std::size_t>((segments + 1) * (segments + 2) / 2);
        ASSERT_EQ(soup.vertices.size(), 2 * per_patch);
        ASSERT_EQ(soup.triangles.size(), 2u * segments * segments);
        // the domain point of each vertex (within its patch)
        std::vector<Barycentric> domain(per_patch);
        for (int k = 0; k <= segments; ++k)
            for (int j = 0; j + k <= segments; ++j)
                domain[TriangularPatch::index(segments, j, k)] = {
                    double(segments - j - k) / segments, double(j) / segments,
                    double(k) / segments};
        for (std::size_t v = 0; v < soup.vertices.size(); ++v)
            EXPECT_LT(
                distance(soup.vertices[v], patches[v / per_patch].evaluate(domain[v % per_patch])),
                1e-14);
        for (std::size_t i = 0; i < soup.triangles.size(); ++i) {
            const auto& corners = soup.triangles[i];
            const std::size_t p = i / static_cast<std::size_t>(segments * segments);
            Barycentric centroid{0, 0, 0};
            for (std::uint32_t v : corners) {
                ASSERT_EQ(v / per_patch, p);
                for (std::size_t q = 0; q < 3; ++q)
                    centroid[q] += domain[v % per_patch][q] / 3;
            }
            const Point &a = soup.vertices[corners[0]], &b = soup.vertices[corners[1]],
                        &c = soup.vertices[corners[2]];
            Point normal = cross({b[0] - a[0], b[1] - a[1], b[2] - a[2]},
                                 {c[0] - a[0], c[1] - a[1], c[2] - a[2]});
            const double length = std::sqrt(dot(normal, normal));
            ASSERT_GT(length, 0);
            for (double& x : normal)
                x /= length;
            // fine triangles follow the tangent plane; the coarse ones only face the same side
            EXPECT_GT(dot(normal, patches[p].normal(centroid)), segments == 16 ? 0.9 : 0.0)
                << "triangle " << i;
        }
    }
    EXPECT_THROW(tessellate(patches, 0), std::invalid_argument);
}

// z = s^2 over (x, y) = (s, t): along an edge of length h in s the flat triangle misses the
// parabola by h^2 / 4 at its midpoint and less elsewhere, so the error of n segments is
// 1 / (4 n^2) and the smallest n for an error e is ceil(sqrt(1 / (4 e))).
TEST(Tessellate, SegmentsForErrorOfAParabolicPatch) {
    // control points of (s, t, s^2) in degree 2: (j/2, k/2, [j == 2])
    const std::vector<TriangularPatch> parabola{TriangularPatch(
        2, {{0, 0, 0}, {0.5, 0, 0}, {1, 0, 1}, {0, 0.5, 0}, {0.5, 0.5, 0}, {0, 1, 0}})};
    EXPECT_EQ(segments_for_error(parabola, 1.0), 1);
    EXPECT_EQ(segments_for_error(parabola, 1 / (4 * 7.5 * 7.5)), 8);
    EXPECT_EQ(segments_for_error(parabola, 1.0000001e-6), 500);
    // a caller's bound: returned when nothing up to it is fine enough, else the count itself
    EXPECT_EQ(segments_for_error(parabola, 1.0000001e-6, 64), 64);
    EXPECT_EQ(segments_for_error(parabola, 1 / (4 * 7.5 * 7.5), 64), 8);
    // measured independently at random points of the tessellation's triangles
    std::mt19937_64 rng(test::seed_for("Tessellate.SegmentsForErrorOfAParabolicPatch"));
    const TriangleSoup soup = tessellate(parabola, 8);
    double worst = 0;
    for (const auto& corners : soup.triangles)
        for (int sample = 0; sample < 20; ++sample) {
            const Barycentric w = random_point(rng);
            Point flat{0, 0, 0};
            for (std::size_t q = 0; q < 3; ++q)
                for (std::size_t v = 0; v < 3; ++v)
                    flat[q] += w[v] * soup.vertices[corners[v]][q];
            // the patch point over the same (x, y): x = s, y = t
            worst = std::max(
                worst,
                distance(flat, parabola[0].evaluate({1 - flat[0] - flat[1], flat[0], flat[1]})));
        }
    EXPECT_LE(worst, 1 / (4 * 7.5 * 7.5));
    EXPECT_THROW(segments_for_error(parabola, 0), std::invalid_argument);
    EXPECT_THROW(segments_for_error(parabola, 1e-30), std::invalid_argument);
}

// The teapot at an error of 1e-3 x its box: the tessellation found keeps within it at random
// points of its triangles (up to the sampling of segments_for_error, which looks at edge
// midpoints and centroids only: 10% slack), and the next coarser one does not.
TEST(Tessellate, TeapotWithinItsErrorBound) {
    const std::vector<TriangularPatch> patches = teapot();
    const double diagonal = Scene::from_triangles(tessellate(patches, 1)).bounds().diagonal();
    const double max_error = 1e-3 * diagonal;
    const int segments = segments_for_error(patches, max_error);
    std::cout << "[ segments ] teapot at error 1e-3 x diagonal: " << segments << std::endl;
    EXPECT_GT(segments, 4);
    std::mt19937_64 rng(test::seed_for("Tessellate.TeapotWithinItsErrorBound"));
    const auto sampled_error = [&](int n, int samples) {
        const TriangleSoup soup = tessellate(patches, n);
        const std::size_t per_patch = static_cast<std::size_t>(n * n);
        const std::size_t per_patch_vertices = static_cast<std::size_t>((n + 1) * (n + 2) / 2);
        std::vector<Barycentric> domain(per_patch_vertices);
        for (int k = 0; k <= n; ++k)
            for (int j = 0; j + k <= n; ++j)
                domain[TriangularPatch::index(n, j, k)] = {double(n - j - k) / n, double(j) / n,
                                                           double(k) / n};
        double worst = 0;
        for (std::size_t i = 0; i < soup.triangles.size(); ++i)
            for (int sample = 0; sample < samples; ++sample) {
                const Barycentric w = random_point(rng);
                Point flat{0, 0, 0};
                Barycentric at{0, 0, 0};
                for (std::size_t v = 0; v < 3; ++v) {
                    const std::uint32_t vertex = soup.triangles[i][v];
                    for (std::size_t q = 0; q < 3; ++q) {
                        flat[q] += w[v] * soup.vertices[vertex][q];
                        at[q] += w[v] * domain[vertex % per_patch_vertices][q];
                    }
                }
                worst = std::max(worst, distance(flat, patches[i / per_patch].evaluate(at)));
            }
        return worst;
    };
    EXPECT_LE(sampled_error(segments, 4), 1.1 * max_error);
    EXPECT_GT(sampled_error(segments - 1, 8), max_error * 0.9);
}

}  // namespace
}  // namespace sxk::bezier
