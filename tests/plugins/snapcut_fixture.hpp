// What the snap cutter's tests share: a host with the degeneracy plug-in linked in (its service
// is how a session removes flat elements), sessions on Kuhn cubes, and straight scalpel paths.
#pragma once

#include <cmath>
#include <memory>
#include <vector>

#include <gtest/gtest.h>

#include "degeneracy_plugin.hpp"
#include "snap_cut.hpp"
#include "sxk/generators.hpp"
#include "sxk/plugin_host.hpp"

namespace sxk::test {

// The degeneracy service of a host that links the plug-in in (one per test program).
inline const degeneracy::DegeneracyService* degeneracy_service() {
    static PluginHost host = [] {
        PluginHost h;
        h.add_static(sxk_plugin_entry_degeneracy(), "linked-in degeneracy");
        return h;
    }();
    return host.service<degeneracy::DegeneracyService>().value();
}

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

}  // namespace sxk::test
