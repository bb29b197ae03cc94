// What `sxk cut snap` prints: a table of the steps and a summary, or one JSON object.
//
//   step   time  edges  selected  dissected  snapped  refused  degenerate  collapses  cut free  pieces  elements  vertices    ms
//      2   0.10     31        12         12       14        0           9          7         0       0      3072       745  0.41
//   ...
//   14 steps: 108 faces dissected, 143 degenerate (99 collapses, 13 cut free), 3072 -> 3034 elements, 729 -> 823 vertices
//
// JSON: {"steps": [...], "summary": {...}} (the command puts "file", "path", "output" and
// "options" in front); the keys are docs/cli.md's "sxk cut snap".
#pragma once

#include <cstddef>
#include <optional>
#include <ostream>
#include <vector>

#include <nlohmann/json.hpp>

#include "sxk/simulation.hpp"
#include "snap_cut.hpp"

namespace sxk::snapcut {

struct ReplayStep {
    double time = 0;
    std::size_t line = 0;  // of the path file
    CutStepReport report;
};

struct ReplayRecord {
    std::vector<ReplayStep> steps;
    bool deformed = false;                    // --deform: a simulation ran
    RelaxReport initial_relax;    // its solve before the first step
    bool initial_solved = false;              // initial_relax holds the solve's figures (not refused)
    // why the cut did not start: the solve before it was refused, or its shape could not be shown
    // (the JSON's initial_relax.refusal; the command then exits 1 and writes nothing)
    std::optional<Refusal> initial_refusal;
    std::size_t undone = 0;
    std::size_t elements_before = 0, elements_after = 0;
    std::size_t vertices_before = 0, vertices_after = 0;  // vertices in some element
};

nlohmann::ordered_json to_json(const CutStepReport& report);
nlohmann::ordered_json to_json(const Options& options, bool degeneracy_service);
nlohmann::ordered_json to_json(const ReplayRecord& record);
void print_replay(std::ostream& out, const ReplayRecord& record);

}  // namespace sxk::snapcut
