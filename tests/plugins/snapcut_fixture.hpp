// What the snap cutter's tests share: a host with the degeneracy plug-in linked in (its service
// is how a session removes flat elements), sessions on Kuhn cubes, and straight scalpel paths.
#pragma once

#include <algorithm>
#include <cmath>
#include <iostream>
#include <numbers>
#include <random>
#include <memory>
#include <vector>

#include <gtest/gtest.h>

#include "core/fixtures.hpp"
#include "degeneracy_plugin.hpp"
#include "snap_cut.hpp"
#include "sxk/generators.hpp"
#include "sxk/traversal.hpp"

namespace sxk::test {

// Valid, with no element inverted or flat in either position set.
inline void expect_valid(const Mesh& mesh) {
    const auto valid = mesh.validate({.orientation = true, .flat_is_invalid = true});
    EXPECT_TRUE(valid) << valid.reason();
}

// The 2 x 2 x 2 Kuhn cube of the selection and marks tests: vertex (i,j,k) has id (3k + j) 3 + i,
// every edge climbs in x, y and z.
inline VertexId kuhn2_vertex(int i, int j, int k) { return static_cast<VertexId>((3 * k + j) * 3 + i); }

// The first element (by id) whose four faces are interior (the 2-cube has some at its centre),
// or invalid_id.
inline ElementId interior_element(const Mesh& mesh) {
    for (const ElementId t : elements(mesh)) {
        bool interior = true;
        for (int i = 0; i < 4; ++i) interior = interior && mesh.mate(mesh.face(t, i)) != invalid_id;
        if (interior) return t;
    }
    return invalid_id;
}

inline std::vector<ElementId> all_elements(const Mesh& mesh) {
    std::vector<ElementId> all;
    for (const ElementId t : elements(mesh)) all.push_back(t);
    return all;
}

// A sweep in the plane x = c, large enough to cross the whole 2-cube.
inline snapcut::Sweep plane_x(double c) { return {{c, -1, -1}, {c, 5, -1}, {c, -1, 5}}; }

// The degeneracy service of a host that links the plug-in in (one per test program).
inline const degeneracy::DegeneracyService* degeneracy_service() { return degeneracy::linked_in_service(); }

// A blade from `handle_height` down to `tip_height` (z), standing in the plane through (x0, y0)
// with direction (dx, dy), moved in `steps` equal steps from parameter s0 to s1.
inline std::vector<snapcut::Scalpel> straight_path(Point start, Point direction, double length, double tip_height,
                                                   double handle_height, int steps) {
    std::vector<snapcut::Scalpel> path;
    for (int i = 0; i <= steps; ++i) {
        const double s = length * i / steps;
        const double x = start[0] + s * direction[0], y = start[1] + s * direction[1];
        path.push_back({{x, y, handle_height}, {x, y, tip_height}});
    }
    return path;
}

// A blade lying in the plane through p0 with normal n, tilted with it: the blade runs along w
// (in the plane, upward), the scalpel moves along u (in the plane, horizontal), from s = from to
// s = to in `steps` steps; the tip is at p0 + s u + tip w, the handle `blade` further along w.
inline std::vector<snapcut::Scalpel> plane_path(Point p0, Point n, double from, double to, double tip, double blade,
                                                int steps) {
    auto unit = [](Point v) {
        const double l = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
        return Point{v[0] / l, v[1] / l, v[2] / l};
    };
    auto cross = [](const Point& a, const Point& b) {
        return Point{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    };
    n = unit(n);
    const Point u = unit(cross(n, {0, 0, 1}));
    Point w = unit(cross(n, u));
    if (w[2] < 0) w = {-w[0], -w[1], -w[2]};
    std::vector<snapcut::Scalpel> path;
    for (int i = 0; i <= steps; ++i) {
        const double s = from + (to - from) * i / steps;
        snapcut::Scalpel scalpel;
        for (std::size_t k = 0; k < 3; ++k) {
            scalpel.tip[k] = p0[k] + s * u[k] + tip * w[k];
            scalpel.handle[k] = scalpel.tip[k] + blade * w[k];
        }
        path.push_back(scalpel);
    }
    return path;
}

// The tilted plane of the thesis-like diagonal cut of the cube (the snapped cube's plane,
// snapped_cube.hpp): through (3.85, 4, 3.5), normal (1, -0.95, 0.97).
inline constexpr Point diagonal_point{3.85, 4.0, 3.5};
inline constexpr Point diagonal_normal{1, -0.95, 0.97};

struct Box {
    Point low, high;
};

inline Box bounding_box(const Mesh& mesh) {
    Box box{mesh.reference(0), mesh.reference(0)};
    for (VertexId v = 0; v < mesh.vertex_count(); ++v)
        for (std::size_t k = 0; k < 3; ++k) {
            box.low[k] = std::min(box.low[k], mesh.reference(v)[k]);
            box.high[k] = std::max(box.high[k], mesh.reference(v)[k]);
        }
    return box;
}

// A random curved path through the point `through` (its middle sample's blade passes through it):
// the tip moves in xy in small steps whose direction turns a little each time, both ways from
// there; the blade (about the box's height, z) tilts as it goes. On a cube every extent is the
// size; on the femur (long in z) the blade stands along the bone and the steps are fractions of
// its width. (Paths started anywhere in the box missed the thin femur: 6 of them in a run cut
// nothing, seed 3048458026.)
inline std::vector<snapcut::Scalpel> random_path(const Box& box, const Point& through, int steps,
                                                std::mt19937_64& random) {
    std::uniform_real_distribution<double> unit(0, 1), turn(-0.4, 0.4);
    double size = 0;
    Point extent;
    for (std::size_t k = 0; k < 3; ++k) {
        extent[k] = box.high[k] - box.low[k];
        size = std::max(size, extent[k]);
    }
    const double across = std::max(extent[0], extent[1]);
    const double heading = 2 * std::numbers::pi * unit(random), tilt = 0.6 * (unit(random) - 0.5);
    const double step = across * (0.01 + 0.09 * unit(random));
    const double blade = size * (0.3 + 0.9 * unit(random));
    const double below = blade * (0.1 + 0.8 * unit(random));  // of the blade under `through`
    // the blade's tips from `through` on, one way (+1) or the other (-1), turning as they go
    auto walk = [&](double direction, int movements) {
        std::vector<std::pair<Point, double>> tips;  // tip, tilt
        Point tip{through[0], through[1], through[2] - below};
        double h = heading + (direction > 0 ? 0 : std::numbers::pi), t = tilt;
        for (int i = 0; i < movements; ++i) {
            tip[0] += step * std::cos(h);
            tip[1] += step * std::sin(h);
            tip[2] += step * 0.3 * turn(random) * extent[2] / across;
            h += turn(random);
            t += 0.2 * turn(random);
            tips.emplace_back(tip, t);
        }
        return tips;
    };
    std::vector<std::pair<Point, double>> tips = walk(-1, steps / 2);
    std::reverse(tips.begin(), tips.end());
    tips.emplace_back(Point{through[0], through[1], through[2] - below}, tilt);
    for (const auto& later : walk(+1, steps - steps / 2)) tips.push_back(later);
    std::vector<snapcut::Scalpel> path;
    for (const auto& [tip, t] : tips) {
        const Point up{std::sin(t) * std::cos(heading + std::numbers::pi / 2),
                       std::sin(t) * std::sin(heading + std::numbers::pi / 2), std::cos(t)};
        snapcut::Scalpel scalpel{tip, tip};
        for (std::size_t k = 0; k < 3; ++k) scalpel.handle[k] += blade * up[k];
        path.push_back(scalpel);
    }
    return path;
}

// `count` points uniform in the unit cube, from a stream of their own made from a run's `seed`: the
// one seed_for of a test that draws both a mesh and paths, so that one SXK_SEED replays both.
inline std::vector<Point> random_points(std::uint64_t seed, int count) {
    std::mt19937_64 random(seed ^ 0x9e3779b97f4a7c15ULL);
    std::uniform_real_distribution<double> coordinate(0, 1);
    std::vector<Point> points;
    for (int i = 0; i < count; ++i) points.push_back({coordinate(random), coordinate(random), coordinate(random)});
    return points;
}

// Random curved paths (random_path) on `original`, `paths` of `steps` movements, each a session with
// random options: every step kept and the mesh valid, no element inverted or flat; every path
// cancelled gives `original` back. `seed` (seed_for(name)) seeds the run. `dissected`: the faces the
// run dissected, for the caller to assert on.
inline void check_random_cuts(const char* name, std::uint64_t seed, const Mesh& original, int paths, int steps,
                              std::size_t& dissected) {
    std::mt19937_64 random(seed);
    const Box box = bounding_box(original);
    std::vector<ElementId> all;
    for (const ElementId t : elements(original)) all.push_back(t);
    std::size_t taken = 0;
    dissected = 0;
    for (int p = 0; p < paths; ++p) {
        Mesh mesh = original;
        snapcut::Options options;
        options.snap = random() % 4 != 0;
        options.remove_loose_pieces = random() % 3 == 0;
        auto session = snapcut::SnapCutSession::make(mesh, options, {degeneracy_service()}).value();
        const Simplex inside = original.simplex(all[random() % all.size()]);
        Point through{};
        for (const VertexId v : inside.vertices())
            for (std::size_t k = 0; k < 3; ++k) through[k] += original.deformed(v)[k] / 4;
        for (const snapcut::Scalpel& scalpel : random_path(box, through, steps, random)) {
            const auto stepped = session->cut(scalpel);
            ASSERT_TRUE(stepped) << "path " << p << " step " << taken << ": " << stepped.reason();
            ++taken;
            dissected += session->last_step().faces_dissected;
            const auto valid = mesh.validate({.orientation = true, .flat_is_invalid = true});
            ASSERT_TRUE(valid) << "path " << p << ": " << valid.reason();
        }
        ASSERT_TRUE(session->cancel());
        expect_same_state(mesh, original);
        if (::testing::Test::HasFatalFailure()) return;
    }
    std::cout << "[ steps    ] " << name << ": " << taken << " steps, " << dissected << " faces dissected\n";
}
inline void check_random_cuts(const char* name, const Mesh& original, int paths, int steps, std::size_t& dissected) {
    check_random_cuts(name, seed_for(name), original, paths, steps, dissected);
}

}  // namespace sxk::test
