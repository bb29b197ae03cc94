// The needle's options (needle_options.hpp).
#include "needle_options.hpp"

#include "command_line.hpp"

namespace sxk::needle {

void add_needle_options(CLI::App& app, Options& options, std::string& deform) {
    app.add_option("--deform,--material", deform,
                   "The body: `sxk deform`'s options in one word, e.g. \"--fix x>0.0999 --E 34e3 --nu 0.34 "
                   "--thickness 0.01 --tol 0.01 --rounding 1e-8\" (the elasticity plug-in). Without it the "
                   "needle only refines and tracks its nodes (geometry only)");
    app.add_option("--h-ref", options.h_ref,
                   "Element size around the needle: the mesh is bisected along the tip's path until the "
                   "elements there are of this size (the spacing of a uniform grid of them; thesis h_ref)")
        ->check(number_in(0, false, 1e300, true, "(0, 1e300]"))
        ->capture_default_str();
    app.add_option("--radius", options.radius,
                   "Needle radius: every node within it of the tip's path becomes a needle node and the "
                   "refinement reaches across it (thesis Fig. 6.14: a needle as a jagged surface in the mesh); "
                   "0: a line, the nearest node of each edge or face the tip enters (thesis 6.4)")
        ->check(number_in(0, true, 1e300, true, "[0, 1e300]"))
        ->capture_default_str();
    app.add_option("--friction", options.friction.shaft,
                   "Dynamic friction along the shaft, force per length (N/m; thesis Fig. 6.4)")
        ->check(number_in(0, true, 1e300, true, "[0, 1e300]"))
        ->capture_default_str();
    app.add_option("--tip-friction", options.friction.tip,
                   "Dynamic friction at the tip, force per length (N/m), falling linearly to --friction "
                   "over --tip-length: the cutting force's bulge")
        ->check(number_in(0, true, 1e300, true, "[0, 1e300]"))
        ->capture_default_str();
    app.add_option("--tip-length", options.friction.tip_length, "Length of the bulge behind the tip (m)")
        ->check(number_in(0, true, 1e300, true, "[0, 1e300]"))
        ->capture_default_str();
    app.add_option("--static-ratio", options.friction.static_ratio,
                   "Static friction threshold over the dynamic one (thesis 6.8.1: 2)")
        ->check(number_in(1, true, 1e300, true, "[1, 1e300]"))
        ->capture_default_str();
    app.add_flag("--relocate", options.relocate,
                 "Move intercepted nodes onto the needle (thesis 6.8.6; both positions, unless that would "
                 "invert an element or halve its aspect ratio) instead of keeping their offset from it (6.4)");
    app.add_option("--rearrangements", options.rearrangements,
                   "Solves per step: after each, the nodes' stick/slip grips are rearranged, and a change "
                   "is solved again, at most this many times (the thesis' loop: 1)")
        ->check(whole_number_in(1, 1000000))
        ->capture_default_str();
    app.add_option("--iterations", options.iterations, "CG iterations per solve, at most (a frame's budget)")
        ->check(whole_number_in(1, 100000000))
        ->capture_default_str();
    app.add_option("--local", options.local_vertices,
                   "Solve only around the needle, at most this many vertices (its nodes and their neighbours "
                   "ring by ring), the rest of the body held: a step costs the same on any mesh size, the far "
                   "field lags (0: the whole body every step, as the thesis)")
        ->check(whole_number_in(0, 100000000))
        ->capture_default_str();
    app.add_option("--far", options.far_vertices,
                   "With --local: after each step's solve, one more block of at most this many vertices where "
                   "the far field is most out of balance, so that it follows the needle over the steps (0: it "
                   "waits for --settle)")
        ->check(whole_number_in(0, 100000000))
        ->capture_default_str();
}

}  // namespace sxk::needle
