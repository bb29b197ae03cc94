// The Delaunay cutter's tool "delaunaycut" (thesis chapter 5): a point scalpel cuts a planar
// triangle mesh (Delaunay cutting, §5.2, or the subdivision baseline of §5.4), or a triangulated
// surface in space (§5.6). Installed:
//
//     sxk::delaunaycut::Options cut;               // the thesis' thresholds: h/3, h/6, h/6
//     auto session = host.begin_tool(mesh, cut);
//     (*session)->step(pose);   // the scalpel's point at pose.position: the first step places it,
//                               // each further step is one undoable movement
//
// `sxk cut delaunay` reads the same options from its words (docs/cli.md).
#pragma once

#include <cstdint>
#include <string_view>

#include "sxk/outcome.hpp"
#include "sxk/plugins/option_checks.hpp"

namespace sxk::delaunaycut {

enum class Method { delaunay, subdivision };

struct Options {
    static constexpr std::string_view tool_name = "delaunaycut";
    static constexpr std::uint32_t options_version = 1;

    Method method = Method::delaunay;
    // The thesis' thresholds (§5.4), in mean edge lengths of the mesh (deformed positions,
    // measured when the session begins): an interior node nearer the active node than eps_edge is
    // removed; the incision is made once the active node is eps_entry from where the scalpel
    // entered; the cut is finished once the scalpel's extrapolated movement meets the boundary
    // within eps_exit. The thesis' defaults: h/3, h/6, h/6. Delaunay cutting only.
    double eps_edge = 1.0 / 3;
    // Thesis §5.5's scale-independent criterion instead of eps_edge, when > 0 (degrees): an interior
    // node next to the active node is removed when the edge between them is "too short", every
    // angle opposite that edge in its two triangles below this.
    double short_angle = 0;
    double eps_entry = 1.0 / 6;
    double eps_exit = 1.0 / 6;
    // The nodes an incision split (Fig. 5.5) and the entry fix-up insert, one on each side of the
    // incision, are moved this fraction of the way from the scalpel's path towards the node
    // opposite them ("dilated slightly", so that the incision's two sides never touch).
    double dilation = 0.05;
    // The face label of the cut (DissectOptions::cut_label).
    int cut_label = 9999;

    // The ranges, bad_argument naming the field ("delaunaycut: eps_edge 0 is not in (0, 10]").
    Outcome<Done> check() const {
        using namespace option_checks;
        return first_refusal({
            in(tool_name, "eps_edge", eps_edge, {0, 10, true, false}),
            in(tool_name, "short_angle", short_angle, {0, 90, false, true}),
            in(tool_name, "eps_entry", eps_entry, {0, 10, true, false}),
            in(tool_name, "eps_exit", eps_exit, {0, 10, true, false}),
            in(tool_name, "dilation", dilation, {0, 0.5, false, true}),
        });
    }
};

}  // namespace sxk::delaunaycut
