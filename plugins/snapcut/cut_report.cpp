// The snap cut's reports (cut_report.hpp).
#include "cut_report.hpp"

#include <cstdio>
#include <cstring>
#include <string>

namespace sxk::snapcut {

nlohmann::ordered_json to_json(const CutStepReport& r) {
    nlohmann::ordered_json json;
    json["sweeps"] = r.sweeps;
    json["repeats"] = r.repeats;
    json["elements_searched"] = r.elements_searched;
    json["edges_hit"] = r.edges_hit;
    json["edges_split"] = r.edges_split;
    json["splits_refused"] = r.splits_refused;
    json["faces_selected"] = r.faces_selected;
    json["faces_dissected"] = r.faces_dissected;
    json["placement_error"] = r.placement_error;
    json["placement_error_local"] = r.placement_error_local;
    json["incision_error"] = r.incision_error;
    json["incision_error_local"] = r.incision_error_local;
    json["nodes_snapped"] = r.nodes_snapped;
    json["nodes_partly_snapped"] = r.nodes_partly_snapped;
    json["nodes_refused"] = r.nodes_refused;
    json["refusals"] = nlohmann::ordered_json::array();
    for (const auto& [node, reason] : r.refusals) json["refusals"].push_back({{"node", node}, {"reason", reason}});
    json["incomplete"] = r.incomplete;
    json["degeneracy_removal"] = r.degeneracy_removal_ran;
    json["degenerates_found"] = r.degenerates_found;
    json["collapses"] = r.collapses;
    json["splits"] = r.splits;
    json["flips"] = r.flips;
    json["peeled"] = r.peeled;
    json["cut_free"] = r.cut_free;
    json["degenerates_remaining"] = r.degenerates_remaining;
    json["loose_pieces"] = r.loose_pieces;
    if (r.relaxed) {
        nlohmann::ordered_json relax;
        relax["iterations"] = r.relax_iterations;
        relax["converged"] = r.relax_converged;
        relax["residual"] = r.relax_residual;
        relax["shown"] = r.relax_shown;
        relax["pieces_held"] = r.pieces_held;
        relax["region_vertices"] = r.relax_region_vertices;
        relax["far_vertices"] = r.relax_far_vertices;
        if (!r.relax_not_shown.empty()) relax["not_shown"] = r.relax_not_shown;
        if (!r.relax_refusal.empty()) relax["refusal"] = r.relax_refusal;
        json["relax"] = relax;
    }
    json["elements"] = r.elements;
    json["vertices"] = r.vertices;
    json["seconds"] = r.seconds;
    json["phase_seconds"] = {{"select", r.seconds_select},       {"snap", r.seconds_snap},
                             {"dissect", r.seconds_dissect},     {"degeneracy", r.seconds_degeneracy},
                             {"pieces", r.seconds_pieces},       {"relax", r.seconds_relax}};
    return json;
}

nlohmann::ordered_json to_json(const Options& options, bool degeneracy_service) {
    nlohmann::ordered_json json;
    json["snap"] = options.snap;
    json["degeneracy_removal"] = options.remove_degeneracies && degeneracy_service;
    json["aspect_ratio"] = options.aspect_ratio;
    json["large_angle"] = options.large_angle;
    json["snap_min_aspect_ratio"] = options.min_snap_aspect_ratio;
    json["remove_loose"] = options.remove_loose_pieces;
    json["cut_label"] = options.cut_label;
    json["split_beyond"] = options.split_beyond;
    json["relax_iterations"] = options.relax_iterations;
    json["local_vertices"] = options.local_vertices;
    json["far_vertices"] = options.far_vertices;
    return json;
}

namespace {

struct Totals {
    std::size_t edges = 0, edges_split = 0, selected = 0, dissected = 0, snapped = 0, refused = 0, degenerate = 0,
                collapses = 0, splits = 0, flips = 0, peeled = 0, cut_free = 0, pieces = 0;
    double seconds = 0;
};

Totals totals_of(const ReplayRecord& record) {
    Totals t;
    for (const ReplayStep& step : record.steps) {
        const CutStepReport& r = step.report;
        t.edges += r.edges_hit;
        t.edges_split += r.edges_split;
        t.selected += r.faces_selected;
        t.dissected += r.faces_dissected;
        t.snapped += r.nodes_snapped;
        t.refused += r.nodes_refused;
        t.degenerate += r.degenerates_found;
        t.collapses += r.collapses;
        t.splits += r.splits;
        t.flips += r.flips;
        t.peeled += r.peeled;
        t.cut_free += r.cut_free;
        t.pieces += r.loose_pieces.size();
        t.seconds += r.seconds;
    }
    return t;
}

}  // namespace

nlohmann::ordered_json to_json(const ReplayRecord& record) {
    nlohmann::ordered_json json;
    json["steps"] = nlohmann::ordered_json::array();
    for (std::size_t i = 0; i < record.steps.size(); ++i) {
        nlohmann::ordered_json step;
        step["step"] = i + 1;
        step["time"] = record.steps[i].time;
        step["line"] = record.steps[i].line;
        const nlohmann::ordered_json report = to_json(record.steps[i].report);  // named: items() is a view
        for (const auto& [key, value] : report.items()) step[key] = value;
        json["steps"].push_back(step);
    }
    const Totals t = totals_of(record);
    if (record.deformed) {
        nlohmann::ordered_json initial;
        if (record.initial_solved) {
            initial["iterations"] = record.initial_relax.iterations;
            initial["converged"] = record.initial_relax.converged;
            initial["residual"] = record.initial_relax.residual;
            initial["shown"] = record.initial_relax.shown;
            initial["seconds"] = record.initial_relax.seconds;
        } else {
            initial["converged"] = false;
        }
        if (record.initial_refusal)
            initial["refusal"] = {{"code", to_string(record.initial_refusal->code)},
                                  {"reason", record.initial_refusal->reason}};
        json["initial_relax"] = initial;
    }
    nlohmann::ordered_json summary;
    summary["steps"] = record.steps.size();
    summary["undone"] = record.undone;
    summary["edges_hit"] = t.edges;
    summary["edges_split"] = t.edges_split;
    summary["faces_selected"] = t.selected;
    summary["faces_dissected"] = t.dissected;
    summary["nodes_snapped"] = t.snapped;
    summary["nodes_refused"] = t.refused;
    summary["degenerates_found"] = t.degenerate;
    summary["collapses"] = t.collapses;
    summary["splits"] = t.splits;
    summary["flips"] = t.flips;
    summary["peeled"] = t.peeled;
    summary["cut_free"] = t.cut_free;
    summary["loose_pieces"] = t.pieces;
    summary["elements"] = {{"before", record.elements_before}, {"after", record.elements_after}};
    summary["vertices"] = {{"before", record.vertices_before}, {"after", record.vertices_after}};
    summary["seconds"] = t.seconds;
    json["summary"] = summary;
    return json;
}

void print_replay(std::ostream& out, const ReplayRecord& record) {
    char line[256];
    out << "step    time  edges  selected  dissected  snapped  refused  degenerate  collapses  cut free  pieces"
           "  elements  vertices      ms"
        << (record.deformed ? "     CG" : "") << '\n';
    for (std::size_t i = 0; i < record.steps.size(); ++i) {
        const CutStepReport& r = record.steps[i].report;
        std::snprintf(line, sizeof line, "%4zu %7.3f %6zu %9zu %10zu %8zu %8zu %11zu %10zu %9zu %7zu %9zu %9zu %7.2f\n",
                      i + 1, record.steps[i].time, r.edges_hit, r.faces_selected, r.faces_dissected,
                      r.nodes_snapped, r.nodes_refused, r.degenerates_found, r.collapses, r.cut_free,
                      r.loose_pieces.size(), r.elements, r.vertices, r.seconds * 1e3);
        out << std::string(line, std::strlen(line) - 1);
        if (record.deformed) {
            std::snprintf(line, sizeof line, " %6zu", r.relax_iterations);
            out << line;
        }
        out << '\n';
    }
    const Totals t = totals_of(record);
    out << record.steps.size() << " steps: " << t.dissected << " faces dissected, " << t.edges_split
        << " long edges split where crossed, " << t.snapped << " nodes snapped ("
        << t.refused << " refused), " << t.degenerate << " degenerate (" << t.collapses << " collapses, " << t.cut_free
        << " cut free), " << t.pieces << " loose pieces; " << record.elements_before << " -> "
        << record.elements_after << " elements, " << record.vertices_before << " -> " << record.vertices_after
        << " vertices";
    if (record.deformed)
        out << "; CG " << record.initial_relax.iterations << " iterations before the cut, then per step as listed";
    if (record.undone > 0) out << "; " << record.undone << " steps undone";
    out << '\n';
}

}  // namespace sxk::snapcut
