// What the snap cutter's tests share: a host with the degeneracy plug-in linked in (its service
// is how a session removes flat elements), sessions on Kuhn cubes, and straight scalpel paths.
#pragma once

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

}  // namespace sxk::test
