// `sxk needle`'s table and JSON (needle_report.hpp).
#include "needle_report.hpp"

#include <algorithm>
#include <cstdio>
#include <numeric>
#include <string>

namespace sxk::needle {

nlohmann::ordered_json to_json(const Options& options) {
    nlohmann::ordered_json json;
    json["h_ref"] = options.h_ref;
    json["friction"] = options.friction.shaft;
    json["tip_friction"] = options.friction.tip;
    json["tip_length"] = options.friction.tip_length;
    json["static_ratio"] = options.friction.static_ratio;
    json["radius"] = options.radius;
    json["relocate"] = options.relocate;
    json["rearrangements"] = options.rearrangements;
    json["iterations"] = options.iterations;
    json["local_vertices"] = options.local_vertices;
    json["far_vertices"] = options.far_vertices;
    return json;
}

nlohmann::ordered_json to_json(const Replay& replay) {
    nlohmann::ordered_json json;
    json["geometry_only"] = replay.geometry_only;
    json["start_bisections"] = replay.start_bisections;
    json["elements_before"] = replay.elements_before;
    json["vertices_before"] = replay.vertices_before;
    nlohmann::ordered_json steps = nlohmann::ordered_json::array();
    for (const ReplayStep& step : replay.steps) {
        const NeedleStepReport& r = step.report;
        nlohmann::ordered_json s;
        s["time"] = step.time;
        s["line"] = step.line;
        s["tip_inside"] = r.tip_inside;
        s["bisections"] = r.bisections;
        s["intercepted"] = r.intercepted;
        s["relocated"] = r.relocated;
        s["not_relocated"] = r.not_relocated;
        s["released"] = r.released;
        s["stick"] = r.stick;
        s["slip"] = r.slip;
        s["needle_nodes"] = r.stick + r.slip;
        s["loosened"] = r.loosened;
        s["gripped"] = r.gripped;
        s["solves"] = r.solves;
        s["iterations"] = r.iterations;
        s["solved_vertices"] = r.solved_vertices;
        s["far_vertices"] = r.far_vertices;
        s["converged"] = r.converged;
        s["shown"] = r.shown;
        s["axial_force"] = r.axial_force;
        s["lateral_force"] = r.lateral_force;
        s["elements"] = r.elements;
        s["vertices"] = r.vertices;
        s["refine_seconds"] = r.refine_seconds;
        s["intercept_seconds"] = r.intercept_seconds;
        s["solve_seconds"] = r.solve_seconds;
        s["seconds"] = r.seconds;
        steps.push_back(std::move(s));
    }
    json["steps"] = std::move(steps);
    json["undone"] = replay.undone;
    json["elements_after"] = replay.elements_after;
    json["vertices_after"] = replay.vertices_after;
    return json;
}

void print_replay(std::ostream& out, const Replay& replay) {
    char line[256];
    out << "step      time  inside  bisect  nodes stick/slip  iters   axial N  lateral N  elements     ms\n";
    for (std::size_t i = 0; i < replay.steps.size(); ++i) {
        const ReplayStep& step = replay.steps[i];
        const NeedleStepReport& r = step.report;
        std::snprintf(line, sizeof line, "%4zu %9.4g  %6s  %6zu  %5zu %5zu/%-4zu  %5zu  %8.4f  %9.4f  %8zu  %5.2f\n",
                      i + 1, step.time, r.tip_inside ? "yes" : "no", r.bisections, r.stick + r.slip, r.stick, r.slip,
                      r.iterations, r.axial_force, r.lateral_force, r.elements, r.seconds * 1000);
        out << line;
    }
    std::vector<double> ms;
    for (const ReplayStep& step : replay.steps) ms.push_back(step.report.seconds * 1000);
    std::sort(ms.begin(), ms.end());
    const double total = std::accumulate(ms.begin(), ms.end(), 0.0);
    if (!ms.empty()) {
        std::snprintf(line, sizeof line, "%zu steps in %.1f ms: median %.3f ms, p99 %.3f ms, %.0f steps/s\n", ms.size(),
                      total, ms[ms.size() / 2], ms[std::min(ms.size() - 1, ms.size() * 99 / 100)],
                      total > 0 ? 1000.0 * double(ms.size()) / total : 0.0);
        out << line;
    }
    if (replay.geometry_only) out << "geometry only (no --deform): nothing moved\n";
    if (replay.start_bisections > 0)
        out << "--h-start: " << replay.start_bisections << " bisections before the first step\n";
    out << "elements " << replay.elements_before << " -> " << replay.elements_after << ", vertices "
        << replay.vertices_before << " -> " << replay.vertices_after;
    if (replay.undone > 0) out << " (" << replay.undone << " steps undone)";
    out << '\n';
}

}  // namespace sxk::needle
