// The degeneracy plug-in: `sxk degeneracies IN OUT [--aspect A] [--angle RADIANS]
// [--no-cut-free] [--no-flips] [--no-peel] [--boundary-tolerance T] [--json]` runs
// remove_degeneracies() (remove_degeneracies.hpp, thesis §3.2.3) on a mesh file and writes the
// result; and the report printers the command, the tests and the benchmark share.
//
// Text report (print_report): one row per pass, then a summary line.
//
//   pass  kind      needle  spindle  sliver  cap  collapses  splits  flips  peeled  cut free  ...
//      1  collapse       0        0       0    1          1       1      0       0         0  ...
//   found 1 degenerate: removed 1, cracks 0 (cut free), remaining 0
//
// JSON report (to_json): {"passes":[...], "summary":{...}, "remaining":[...]}; the command puts
// "file", "output" and "options" in front. Keys: docs/cli.md "sxk degeneracies".
#pragma once

#include <ostream>
#include <span>

#include <nlohmann/json.hpp>

#include "sxk/plugins/degeneracy.hpp"
#include "remove_degeneracies.hpp"
#include "sxk/plugin.hpp"

// The named entry point (the MODULE's sxk_plugin_entry forwards to it); programs that link
// sxk_plugin_degeneracy_static pass it to PluginHost::add_static.
extern "C" SXK_PLUGIN_EXPORT const sxk_plugin_info* sxk_plugin_entry_degeneracy();

namespace sxk::degeneracy {

// The service of a host with this plug-in linked in, made on first use and kept for the program's
// life: for programs that link sxk_plugin_degeneracy_static and use the service the way a
// plug-in finds it (the snap cutter's tests, benchmarks and fuzz target).
const DegeneracyService* linked_in_service();

// Degenerates removed: those found on the first list minus those remaining at the end (0 when
// the removal created more than it removed).
std::size_t removed(const Report& report);

// The report as JSON:
//   "passes": one object per pass: "pass" (1-based), "kind" (to_string(PassReport::Kind):
//     "collapse", "flip", "peel", "cut free"), "found" {"needle","spindle","sliver","cap",
//     "total"}, "collapses", "splits", "flips", "peeled", "cut_free", "elements"
//     {"before","after"}, "vertices" {"before","after"}, "min_aspect_ratio_after",
//     "min_angle_after", "max_angle_after" (radians; dihedral angles, triangles: angles);
//   "summary": "found", "removed", "cracks" (= elements cut free), "remaining", "collapses",
//     "splits", "flips", "peeled", "elements" {"before","after"}, "vertices" {"before","after"};
//   "remaining": [{"element": id, "reason": why its last attempt was refused, "code": the
//     RefusalCode name (to_string) of the first refusal the reason names, null when none}].
nlohmann::ordered_json to_json(const Report& report);

// The text report: the pass table (angles in degrees; the column reads "dihedral range" for
// tetrahedra, "angle range" for triangles) and the summary line, each line ending in '\n'.
void print_report(std::ostream& out, const Report& report, bool tetrahedra = true);

}  // namespace sxk::degeneracy
