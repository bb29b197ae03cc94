// The snap cutter's tool "snapcut" (thesis chapter 3, §3.2): its options, and the scalpel as a
// pose. Installed; an application begins a session through the plug-in host:
//
//     sxk::PluginHost host;
//     host.load_default_folders();
//     sxk::snapcut::Options cut;                        // the thesis' thresholds by default
//     cut.largest_crumb = 8;
//     auto session = host.begin_tool(mesh, cut, {.simulation = body});   // body may be null
//     (*session)->step(sxk::snapcut::to_pose({handle, tip}));  // places the scalpel
//     (*session)->step(sxk::snapcut::to_pose({handle2, tip2}));  // a movement: one undoable cut
//
// With a simulation (ToolContext::simulation, sxk/simulation.hpp) the session holds the pieces a
// step cuts loose and relaxes the body after every step; without, it cuts the shape as it is. The
// degeneracy removal is the degeneracy plug-in's, when the host has loaded it. `sxk cut snap`
// reads the same options from its words (docs/cli.md).
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "sxk/mesh.hpp"
#include "sxk/outcome.hpp"
#include "sxk/plugins/option_checks.hpp"
#include "sxk/quality.hpp"
#include "sxk/tool_session.hpp"

namespace sxk::snapcut {

// The scalpel: a line segment from the handle end to the tip (deformed positions).
struct Scalpel {
    Point handle{};
    Point tip{};
    bool operator==(const Scalpel&) const = default;
};

// The pose a session's step takes for a scalpel: position = tip, axes[2] along the blade (handle
// to tip), length = the blade's length. (A zero-length blade gives axes[2] = z.)
inline ToolPose to_pose(const Scalpel& scalpel) {
    ToolPose pose;
    pose.position = scalpel.tip;
    Point along{};
    for (std::size_t i = 0; i < 3; ++i) along[i] = scalpel.tip[i] - scalpel.handle[i];
    pose.length = std::hypot(along[0], along[1], along[2]);
    if (pose.length > 0)
        for (std::size_t i = 0; i < 3; ++i) pose.axes[2][i] = along[i] / pose.length;
    return pose;
}

// The scalpel of a pose (to_pose's inverse, up to rounding).
inline Scalpel scalpel_of(const ToolPose& pose) {
    Scalpel scalpel{pose.position, pose.position};
    for (std::size_t i = 0; i < 3; ++i) scalpel.handle[i] -= pose.length * pose.axes[2][i];
    return scalpel;
}

struct Options {
    static constexpr std::string_view tool_name = "snapcut";
    static constexpr std::uint32_t options_version = 1;

    bool snap = true;                  // move the selected faces' corners onto the sweep (§3.2.2)
    bool remove_degeneracies = true;   // through the degeneracy service, when there is one
    // Shape thresholds of the degeneracy removal (thesis §3.3: 0.01 and 0.99 pi).
    double aspect_ratio = 0.01;
    double large_angle = 0.99 * pi;
    // A snap is refused (the node stays) when it would make an element of its star inverted or
    // flat in either position set, or give it an aspect ratio below this (0: only inverted and
    // flat are refused; degeneracy removal then deals with the thin elements, as in the thesis).
    double min_snap_aspect_ratio = 0;
    // Crumbs: a step does not cut loose a piece of at most this many elements (0: any piece may
    // come loose). Where the incision folds around a tetrahedron or two at its rim, one of the
    // faces about to open stays closed instead (loose_pieces.hpp, keep_crumbs_attached; so it does
    // for a film of up to largest_layer elements with every corner snapped, "Layers"). A piece
    // that comes loose all the same with no more material than this many elements of the mean
    // volume, and fewer than a hundredth of the mesh's elements (a layer of flat elements along
    // the cut, or a crumb the degeneracy removal cut loose), is removed and counted as cut free.
    std::size_t largest_crumb = 4;
    // Long edges: an edge the sweep crosses whose nearer end is farther than this from where the
    // blade has swept, in mean edge lengths of the mesh (deformed, measured when the session
    // begins), is split where the sweep crosses it before the selection (split_far_crossings.hpp):
    // the cut runs through the new node instead of a node the snapping may not be able to move
    // that far, or would put beyond where the blade went. The bound is half an edge, and
    // at 0.5 the deforming femur's cut stays within it (docs/snapcut.md "The femur"). 0: never
    // split (the thesis' snap cut, which only moves nodes). Only with `snap`.
    double split_beyond = 0.5;
    // The face label of the cut surface (DissectOptions::cut_label).
    int cut_label = 9999;
    // Remove the pieces a step cuts loose (they are reported either way). A simulation fixes
    // them instead (thesis §3.3: every unfixed component is fixed on a face).
    bool remove_loose_pieces = false;
    // With a simulation: CG iterations after each step (a frame's worth; warm started).
    std::size_t relax_iterations = 100;
    // With a simulation: relax only around what the step changed (the vertices of the elements it
    // edited and the nodes it moved, then their neighbours ring by ring, up to this many
    // vertices), the rest of the body held (Simulation::relax_near): a step's relaxation then
    // costs the same on any mesh size, and the far field lags until a whole-body relaxation (the
    // needle's Options::local_vertices, docs/elasticity.md "Local relaxation"). 0: the whole
    // body every step.
    std::size_t local_vertices = 0;
    // With local_vertices: after each step's relaxation one more block of at most this many
    // vertices where the far field is most out of balance (Simulation::relax_far). 0: none.
    std::size_t far_vertices = 0;
    // Find a sweep's elements from those the blade lay in before it (blade_track.hpp); false:
    // ask the spatial index along the whole blade every sweep. The cut is the same either way
    // (tests/plugins/snapcut_track_test.cpp); following costs less on large meshes.
    bool follow_blade = true;

    // The ranges above; bad_argument naming the field ("snapcut: aspect_ratio 2 is not in (0, 1)").
    Outcome<Done> check() const {
        using namespace option_checks;
        return first_refusal({
            in(tool_name, "aspect_ratio", aspect_ratio, {0, 1, true, true}),
            in(tool_name, "large_angle", large_angle, {pi / 2, pi, true, true}, "pi/2", "pi"),
            in(tool_name, "min_snap_aspect_ratio", min_snap_aspect_ratio, {0, 1, false, true}),
            in(tool_name, "split_beyond", split_beyond, {0, 1000}),
            in(tool_name, "largest_crumb", largest_crumb, 0, 1000),
            in(tool_name, "relax_iterations", relax_iterations, 1, 100000000),
            in(tool_name, "local_vertices", local_vertices, 0, 100000000),
            in(tool_name, "far_vertices", far_vertices, 0, 100000000),
            far_vertices > 0 && local_vertices == 0
                ? std::optional<Refusal>(Refusal{RefusalCode::bad_argument,
                                                 "snapcut: far_vertices needs local_vertices > 0 (it relaxes the far "
                                                 "field that a local relaxation leaves)"})
                : std::nullopt,
        });
    }
};


}  // namespace sxk::snapcut
