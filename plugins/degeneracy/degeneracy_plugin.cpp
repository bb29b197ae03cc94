#include "degeneracy_plugin.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <new>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <CLI/CLI.hpp>

#include "command_line.hpp"
#include "degeneracy_brush.hpp"
#include "progress_line.hpp"
#include "sxk/io.hpp"
#include "sxk/plugin_host.hpp"

namespace sxk::degeneracy {

namespace {

// The classes a pass reports, in table order (DegenerateClass::none is never on the list).
constexpr DegenerateClass reported_classes[] = {DegenerateClass::needle, DegenerateClass::spindle,
                                                DegenerateClass::sliver, DegenerateClass::cap};

std::size_t found_of(const PassReport& pass, DegenerateClass c) {
    return pass.found[static_cast<std::size_t>(c)];
}

nlohmann::ordered_json before_after(std::size_t before, std::size_t after) {
    nlohmann::ordered_json json;
    json["before"] = before;
    json["after"] = after;
    return json;
}

std::string format(const char* pattern, double value) {
    char text[64];
    std::snprintf(text, sizeof text, pattern, value);
    return text;
}

std::string arrow(std::size_t before, std::size_t after) {
    return std::to_string(before) + " -> " + std::to_string(after);
}

std::string plural(std::size_t count, const char* one, const char* many) {
    return std::to_string(count) + ' ' + (count == 1 ? one : many);
}

}  // namespace

const DegeneracyService* linked_in_service() {
    static PluginHost host = [] {
        PluginHost h;
        h.add_static(sxk_plugin_entry_degeneracy(), "linked-in degeneracy");
        return h;
    }();
    return host.service<DegeneracyService>().value();
}

std::size_t removed(const Report& report) {
    return report.found >= report.remaining ? report.found - report.remaining : 0;
}

nlohmann::ordered_json to_json(const Report& report) {
    nlohmann::ordered_json json;
    json["passes"] = nlohmann::ordered_json::array();
    for (std::size_t index = 0; index < report.passes.size(); ++index) {
        const PassReport& pass = report.passes[index];
        nlohmann::ordered_json row;
        row["pass"] = index + 1;
        row["kind"] = to_string(pass.kind);
        nlohmann::ordered_json found;
        for (DegenerateClass c : reported_classes)
            found[std::string(sxk::to_string(c))] = found_of(pass, c);
        found["total"] = pass.found_total();
        row["found"] = found;
        row["collapses"] = pass.collapses;
        row["splits"] = pass.splits;
        row["flips"] = pass.flips;
        row["peeled"] = pass.peeled;
        row["cut_free"] = pass.cut_free;
        row["elements"] = before_after(pass.elements_before, pass.elements_after);
        row["vertices"] = before_after(pass.vertices_before, pass.vertices_after);
        row["min_aspect_ratio_after"] = pass.min_aspect_ratio_after;
        row["min_angle_after"] = pass.min_angle_after;
        row["max_angle_after"] = pass.max_angle_after;
        json["passes"].push_back(row);
    }
    nlohmann::ordered_json summary;
    summary["found"] = report.found;
    summary["removed"] = removed(report);
    summary["cracks"] = report.cut_free;
    summary["remaining"] = report.remaining;
    summary["collapses"] = report.collapses;
    summary["splits"] = report.splits;
    summary["flips"] = report.flips;
    summary["peeled"] = report.peeled;
    summary["elements"] = before_after(report.elements_before, report.elements_after);
    summary["vertices"] = before_after(report.vertices_before, report.vertices_after);
    json["summary"] = summary;
    json["remaining"] = nlohmann::ordered_json::array();
    for (std::size_t index = 0; index < report.remaining_elements.size(); ++index) {
        nlohmann::ordered_json entry;
        entry["element"] = report.remaining_elements[index];
        entry["reason"] =
            index < report.remaining_reasons.size() ? report.remaining_reasons[index] : "";
        // the refusal code of the first attempt the reason names; null when none was made
        if (index < report.remaining_codes.size() && report.remaining_codes[index])
            entry["code"] = std::string(sxk::to_string(*report.remaining_codes[index]));
        else
            entry["code"] = nullptr;
        json["remaining"].push_back(entry);
    }
    return json;
}

void print_report(std::ostream& out, const Report& report, bool tetrahedra) {
    if (!report.passes.empty()) {
        // the kind column (second) is left-aligned, the others right-aligned
        std::vector<std::vector<std::string>> rows;
        rows.push_back({"pass", "kind", "needle", "spindle", "sliver", "cap", "collapses", "splits",
                        "flips", "peeled", "cut free", "elements", "vertices", "min aspect",
                        tetrahedra ? "dihedral range" : "angle range"});
        constexpr double degrees = 180.0 / pi;
        for (std::size_t index = 0; index < report.passes.size(); ++index) {
            const PassReport& pass = report.passes[index];
            std::vector<std::string> row{std::to_string(index + 1), to_string(pass.kind)};
            for (DegenerateClass c : reported_classes)
                row.push_back(std::to_string(found_of(pass, c)));
            row.push_back(std::to_string(pass.collapses));
            row.push_back(std::to_string(pass.splits));
            row.push_back(std::to_string(pass.flips));
            row.push_back(std::to_string(pass.peeled));
            row.push_back(std::to_string(pass.cut_free));
            row.push_back(arrow(pass.elements_before, pass.elements_after));
            row.push_back(arrow(pass.vertices_before, pass.vertices_after));
            row.push_back(format("%.4f", pass.min_aspect_ratio_after));
            row.push_back(format("%.1f", pass.min_angle_after * degrees) + " .. " +
                          format("%.1f", pass.max_angle_after * degrees) + " deg");
            rows.push_back(std::move(row));
        }
        std::vector<std::size_t> widths(rows.front().size(), 0);
        for (const auto& row : rows)
            for (std::size_t column = 0; column < row.size(); ++column)
                widths[column] = std::max(widths[column], row[column].size());
        for (const auto& row : rows) {
            std::string line;
            for (std::size_t column = 0; column < row.size(); ++column) {
                const std::string padding(widths[column] - row[column].size(), ' ');
                if (column > 0)
                    line += "  ";
                line += column == 1 ? row[column] + padding : padding + row[column];
            }
            line.erase(line.find_last_not_of(' ') + 1);
            out << line << '\n';
        }
    }
    out << "found " << plural(report.found, "degenerate", "degenerates") << ": removed "
        << removed(report) << ", cracks " << report.cut_free << " (cut free), remaining "
        << report.remaining << '\n';
}

namespace {

struct CommandOptions {
    std::string input;
    std::string output;
    ReadOptions reading;  // --strict
    Options removal;
    bool no_cut_free = false;
    bool no_flips = false;
    bool no_peel = false;
    bool json = false;
};

// Parses the command's arguments (without IN and OUT when `with_files` is false:
// run_on_mutable_mesh); nullopt with `code` set when the command is done already (--help
// printed: 0; usage error reported: 2).
std::optional<CommandOptions> parse(std::span<const std::string> args, std::ostream& out,
                                    std::ostream& err, int& code, bool with_files = true) {
    CommandOptions options;
    CLI::App app("Removes degenerate (flat) elements by splits, edge collapses and flips; what "
                 "remains is cut free (thesis §3.2.3)",
                 "sxk degeneracies");
    if (with_files) {
        app.add_option("IN", options.input, "Input mesh file")->required();
        app.add_option("OUT", options.output,
                       "Output mesh file, format by extension (" + std::string(known_mesh_extensions()) + ")")
            ->required();
    }
    app.add_option("--aspect", options.removal.aspect_ratio,
                   "Aspect ratio threshold A, 0 < A < 1: below it an element is degenerate")
        ->check(number_in(0, false, 1, false, "(0, 1)"))
        ->capture_default_str();
    app.add_option(
           "--angle", options.removal.large_angle,
           "Large angle threshold in radians, pi/2 < x < pi (default 0.99 pi): the number of "
           "dihedral angles above it gives the class")
        ->check(number_in(pi / 2, false, pi, false, "(pi/2, pi)"));
    app.add_flag(
        "--no-cut-free", options.no_cut_free,
        "Do not cut free what no collapse, flip or peel removed; it is reported as remaining");
    app.add_flag("--no-flips", options.no_flips,
                 "Do not try 2-3, 3-2 and 4-4 flips before cutting free");
    app.add_flag("--no-peel", options.no_peel,
                 "Do not peel off flat elements lying on the boundary before cutting free");
    app.add_option(
           "--boundary-tolerance", options.removal.boundary_tolerance,
           "How far, relative to its longest edge, a boundary face may leave its plane when a "
           "collapse moves its vertex, 0 <= T < 1")
        ->check(number_in(0, true, 1, false, "[0, 1)"))
        ->capture_default_str();
    app.add_flag("--json", options.json, "Print one JSON object instead of the table");
    if (with_files) add_read_options(app, options.reading);
    if (const std::optional<int> done = parse_command_line(app, args, "degeneracies", out, err)) {
        code = *done;
        return std::nullopt;
    }
    options.removal.cut_free = !options.no_cut_free;
    options.removal.flips = !options.no_flips;
    options.removal.peel = !options.no_peel;
    return options;
}

nlohmann::ordered_json options_json(const Options& options) {
    nlohmann::ordered_json json;
    json["aspect_ratio"] = options.aspect_ratio;
    json["large_angle"] = options.large_angle;
    json["flips"] = options.flips;
    json["peel"] = options.peel;
    json["cut_free"] = options.cut_free;
    json["boundary_tolerance"] = options.boundary_tolerance;
    return json;
}

constexpr std::size_t remaining_listed = 10;  // text output: the first few remaining elements

class DegeneraciesCommand final : public PluginCommand {
public:
    std::string_view name() const override { return "degeneracies"; }
    std::string_view summary() const override {
        return "remove flat elements: split, collapse, flip, cut free (thesis 3.2.3)";
    }

    int run(std::span<const std::string> args, std::ostream& out, std::ostream& err) override {
        int code = 0;
        const std::optional<CommandOptions> options = parse(args, out, err, code);
        if (!options)
            return code;
        if (const auto unknown = unknown_output_format(options->output)) {
            err << "sxk: " << *unknown << '\n';
            return cli::exit_usage;
        }
        std::optional<Mesh> mesh = load_mesh_for_command(options->input, err, options->reading);
        if (!mesh)
            return cli::exit_usage;

        // a spinner with the pass and its count while it works (nothing unless stderr is a
        // terminal), gone before the report
        const Outcome<Report> report = [&] {
            const std::string what = "removing degeneracies from " + options->input;
            ProgressLine progress(what);
            Options removal = options->removal;
            if (progress.drawing())  // a label per element only where someone sees it
                removal.progress = [&](const Progress& p) {
                    progress.set_label(what + ": pass " + std::to_string(p.pass) + " (" + p.stage + "), " +
                                       std::to_string(p.done) + " of " + std::to_string(p.listed));
                };
            return remove_degeneracies(*mesh, removal);
        }();
        if (!report) {
            err << "sxk: " << options->input << ": " << report.reason() << '\n';
            return cli::exit_refused;
        }
        // remove_degeneracies edits by checked transactions only; the writer's validation is
        // the oracle that keeps a broken or empty mesh from being written
        // collapses leave their `from` vertices in no element: the file numbers the rest
        WriteOptions writing;
        writing.drop_unused_vertices = true;
        if (!save_mesh_for_command(*mesh, options->output, err, writing))
            return cli::exit_refused;

        print_result(*mesh, *options, *report, options->input + " -> " + options->output, out);
        return cli::exit_success;
    }

    // The removal on a mesh the application holds: one step of its journal when it has one.
    bool edits_mesh() const override { return true; }
    int run_on_mutable_mesh(Mesh& mesh, std::string_view mesh_name, std::span<const std::string> args,
                            std::ostream& out, std::ostream& err) override {
        int code = 0;
        std::optional<CommandOptions> options = parse(args, out, err, code, false);
        if (!options)
            return code;
        options->input = std::string(mesh_name);
        const Outcome<Report> report = remove_degeneracies(mesh, options->removal);
        if (!report) {
            err << "sxk: " << mesh_name << ": " << report.reason() << '\n';
            return cli::exit_refused;
        }
        print_result(mesh, *options, *report, std::string(mesh_name), out);
        return cli::exit_success;
    }

private:
    // The report: JSON (with "file", "output" when there are files) or the table, the first
    // remaining elements and a last line "WHAT: N tetrahedra, M vertices in elements".
    static void print_result(const Mesh& mesh, const CommandOptions& options, const Report& report,
                             const std::string& what, std::ostream& out) {
        const bool tetrahedra = mesh.topological_dimension() == 3;
        if (options.json) {
            nlohmann::ordered_json json;
            json["file"] = options.input;
            if (!options.output.empty()) json["output"] = options.output;
            json["options"] = options_json(options.removal);
            const nlohmann::ordered_json body = to_json(report);  // named: items() is a view
            for (const auto& [key, value] : body.items())
                json[key] = value;
            out << json.dump(2) << '\n';
            return;
        }
        print_report(out, report, tetrahedra);
        const std::size_t listed = std::min(remaining_listed, report.remaining_elements.size());
        for (std::size_t index = 0; index < listed; ++index) {
            out << "  remaining: element " << report.remaining_elements[index];
            if (index < report.remaining_reasons.size())
                out << ": " << report.remaining_reasons[index];
            out << '\n';
        }
        if (report.remaining_elements.size() > listed)
            out << "  ... and " << report.remaining_elements.size() - listed << " more\n";
        out << what << ": "
            << plural(mesh.element_count(), tetrahedra ? "tetrahedron" : "triangle",
                      tetrahedra ? "tetrahedra" : "triangles")
            << ", " << plural(report.vertices_after, "vertex", "vertices") << " in elements\n";
    }
};

class DegeneracyPlugin final : public Plugin {
public:
    std::span<PluginCommand* const> commands() override { return m_commands; }
    ServiceOffer offer(std::string_view service_id) override {
        if (service_id == DegeneracyService::service_id) return offer_of(&m_service);
        if (service_id == ToolFactory::service_id) return offer_of<ToolFactory>(&m_tools);
        return {};
    }

private:
    DegeneraciesCommand m_degeneracies;
    PluginCommand* m_commands[1] = {&m_degeneracies};
    DegeneracyService m_service{
        static_cast<Outcome<Report> (*)(Mesh&, const Options&)>(&remove_degeneracies),
        static_cast<Outcome<Report> (*)(Mesh&, std::span<const ElementId>, const Options&)>(
            &remove_degeneracies),
        &classify};
    ToolFactoryOf<BrushOptions> m_tools{
        [](Mesh& mesh, const BrushOptions& brush, const ToolContext&) -> Outcome<std::unique_ptr<ToolSession>> {
            return std::unique_ptr<ToolSession>(std::make_unique<DegeneracyBrush>(mesh, brush.radius, brush.removal));
        }};
};

}  // namespace
}  // namespace sxk::degeneracy

SXK_PLUGIN(degeneracy, sxk::degeneracy::DegeneracyPlugin, "0.1.0",
           "removes flat elements: split, collapse, flip, cut free (thesis 3.2.3)");
