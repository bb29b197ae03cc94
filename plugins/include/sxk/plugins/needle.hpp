// The needle's tool "needle" (thesis chapter 6): a rigid needle moved through an elastic body,
// the mesh bisected around the tip's path, stick-slip friction along the shaft. Installed:
//
//     sxk::needle::Options needle;                      // the thesis' h6 refinement by default
//     needle.h_ref = 0.1 / 128;
//     auto session = host.begin_tool(mesh, needle, {.simulation = body});
//     (*session)->step(pose);   // one undoable movement: the needle's tip at pose.position, pointing
//                               // along pose.axes[2] (unit, base to tip), pose.length long
//
// The body is the application's simulation (ToolContext::simulation, sxk/simulation.hpp: the
// elasticity plug-in's, solved to rest before the first step); without one the session refines
// and tracks its needle nodes but nothing moves (geometry only). `sxk needle` reads the same
// options from its words (docs/cli.md).
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "sxk/mesh.hpp"
#include "sxk/outcome.hpp"
#include "sxk/plugins/option_checks.hpp"
#include "sxk/tool_session.hpp"

namespace sxk::needle {

// Where the needle is: the end held (base) and the tip, in the deformed positions (the world the
// needle moves in). A planar mesh ignores z.
struct Needle {
    Point base{0, 0, 0};
    Point tip{0, 0, 0};
    bool operator==(const Needle&) const = default;
};

// The friction along the shaft (thesis Fig. 6.4, after DiMaio and Salcudean): the dynamic
// friction force per length of shaft, in N/m, at distance s behind the tip: `tip` at the tip,
// falling linearly to `shaft` at s = tip_length (the bulge that stands for the cutting force),
// `shaft` further back. The thesis gives the curve only as a picture; these defaults are ours
// (docs/needle.md). The static threshold is static_ratio times the dynamic one (§6.8.1: twice).
struct Friction {
    double shaft = 20;
    double tip = 60;
    double tip_length = 0.005;
    double static_ratio = 2;
    // N/m at s >= 0 behind the tip.
    double density(double s) const {
        if (s >= tip_length || tip_length <= 0) return shaft;
        return tip + (shaft - tip) * std::max(s, 0.0) / tip_length;
    }
    // The force of the stretch [s0, s1] behind the tip (0 <= s0 <= s1), in N.
    double force(double s0, double s1) const {
        s0 = std::max(s0, 0.0);
        s1 = std::max(s1, s0);
        // the profile is linear on [0, tip_length] and constant beyond: the trapezoid rule on each
        // part is exact
        const double knee = std::clamp(tip_length, s0, s1);
        return 0.5 * (density(s0) + density(knee)) * (knee - s0) + shaft * (s1 - knee);
    }
};

struct Options {
    static constexpr std::string_view tool_name = "needle";
    static constexpr std::uint32_t options_version = 1;

    // Refinement around the tip's path to elements of this size (the thesis' h_ref; sizes as in
    // shaft_refinement.hpp: the spacing of a uniform grid of such elements), in the mesh's units
    // (reference positions). The default is the thesis' h6 on its 0.1 m slab.
    double h_ref = 0.1 / 64;
    Friction friction;
    // Intercepted nodes are moved onto the needle (thesis §6.8.6: "nodes selected as needle nodes
    // are projected orthogonally onto the needle"): both positions shift by -d_perp, so that the
    // displacement stays, and d_perp = 0. A move that would invert or flatten an element in either
    // position set, or halve the aspect ratio of one (thesis §6.4: relocation "can easily lead to
    // flattened elements"), is not made (the node keeps its offset; the step report counts it). Off by
    // default, as in the thesis (§6.4: "nodes are not moved within the mesh", which keeps the
    // bisection's triangles congruent).
    bool relocate = false;
    // The needle's radius, in the mesh's units. 0: a line, the thesis' 2D needle (§6.4), whose
    // nodes are the nearest node of each edge (face) the tip enters. Above 0 (thesis Fig. 6.14: a
    // 1 mm needle in a 10 cm cube, "represented in the mesh by a jagged surface"): every node
    // within the radius of the tip's path becomes a needle node too, keeping its offset from the
    // axis, and the refinement reaches across the radius (shaft_refinement.hpp). Friction is still
    // shared along the axis (friction.hpp): the nodes at one cross-section split its stretch.
    // With `relocate`, a node outside the radius goes onto the needle's surface, one inside stays.
    double radius = 0;
    // Solve and rearrange at most this many times per step (the thesis' loop: once).
    std::size_t rearrangements = 1;
    // CG iterations per solve, at most (a frame's budget; the body's options bound them too).
    std::size_t iterations = 100000;
    // Solve only around the needle: its nodes and their neighbours ring by ring, up to this many
    // vertices, the rest of the body held where it is (Simulation::relax_near): the solve's cost is
    // bounded by this, whatever the mesh's size, and the far field lags behind until a solve over
    // the whole body (docs/needle.md "Local solve"). 0: every step solves the whole body, as the
    // thesis does.
    std::size_t local_vertices = 0;
    // With local_vertices: after the step's local solve, one block of up to this many vertices of
    // the far field where it is most out of balance (Simulation::relax_far): the far field follows
    // the needle over the frames, at a bounded cost per step. 0: the far field waits for settle().
    std::size_t far_vertices = 0;

    // The ranges, bad_argument naming the field ("needle: h_ref 0 is not in (0, 1e+300]").
    Outcome<Done> check() const {
        using namespace option_checks;
        return first_refusal({
            in(tool_name, "h_ref", h_ref, {0, 1e300, true, false}),
            in(tool_name, "radius", radius, {0, 1e300}),
            in(tool_name, "friction.shaft", friction.shaft, {0, 1e300}),
            in(tool_name, "friction.tip", friction.tip, {0, 1e300}),
            in(tool_name, "friction.tip_length", friction.tip_length, {0, 1e300}),
            in(tool_name, "friction.static_ratio", friction.static_ratio, {1, 1e300}),
            in(tool_name, "rearrangements", rearrangements, 1, 1000000),
            in(tool_name, "iterations", iterations, 1, 100000000),
            in(tool_name, "local_vertices", local_vertices, 0, 100000000),
            in(tool_name, "far_vertices", far_vertices, 0, 100000000),
        });
    }
};

}  // namespace sxk::needle
