// `sxk deform IN OUT`: a static solve of a tetrahedral mesh, or of a triangle mesh in plane stress,
// under selected constraints and loads, OUT holding the deformed positions (docs/cli.md
// "sxk deform").
#include "deform_command.hpp"

#include <cmath>
#include <filesystem>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "body_setup.hpp"
#include "body_words.hpp"
#include "command_line.hpp"
#include "elastic_body.hpp"
#include "line_plot.hpp"
#include "solve.hpp"
#include "vertex_selector.hpp"

namespace sxk::elasticity {
namespace {

struct CommandOptions {
    std::string input, output;
    ReadOptions reading;
    cli::BodyWords body;
    std::string plot;
    bool json = false;
};

std::optional<CommandOptions> parse(std::span<const std::string> args, std::ostream& out,
                             std::ostream& err, int& code) {
    CommandOptions o;
    CLI::App app(
        "Deforms a tetrahedral mesh, or a triangle mesh in the plane as a slab in plane stress, by "
        "linear "
        "or neo-Hookean elasticity (thesis 3.1, 4.3.3, 6.3): fixed and displaced vertices, loads, "
        "matrix-free linear or nonlinear conjugate gradients; OUT holds the deformed positions",
        "sxk deform");
    app.add_option("IN", o.input, "Input mesh file (tetrahedra in space or triangles in the plane)")
        ->required();
    app.add_option("OUT", o.output,
                   "Output mesh file, format by extension (" + std::string(known_mesh_extensions()) + ")")
        ->required();
    cli::add_body_options(app, o.body);
    app.add_flag("--json", o.json,
                 "Print one JSON object (with the residual history) instead of the summary");
    app.add_option(
        "--plot", o.plot,
        "Also draw the convergence (residual per iteration, log scale) to this PNG file");
    add_read_options(app, o.reading);
    if (const std::optional<int> done = parse_command_line(app, args, "deform", out, err)) {
        code = *done;
        return std::nullopt;
    }
    return o;
}

}  // namespace

std::string_view DeformCommand::summary() const {
    return "deform a tetrahedral or planar triangle mesh by linear or neo-Hookean elasticity: "
           "fixed vertices, loads, "
           "CG (thesis 3.1, 4.3.3, 6.3)";
}

int DeformCommand::run(std::span<const std::string> args, std::ostream& out, std::ostream& err) {
    int code = 0;
    const std::optional<CommandOptions> options = parse(args, out, err, code);
    if (!options)
        return code;
    const CommandOptions& o = *options;
    // the options alone before the mesh is read: a mistake in the words is said at once
    const Outcome<Options> setup = cli::body_options(o.body);
    if (!setup) {
        err << "sxk: " << setup.reason() << '\n';
        return cli::exit_usage;
    }
    if (auto checked = check_body(*setup); !checked) {
        err << "sxk: " << checked.reason() << '\n';
        return cli::exit_usage;
    }
    if (const auto unknown = unknown_output_format(o.output)) {
        err << "sxk: " << *unknown << '\n';
        return cli::exit_usage;
    }
    if (!o.plot.empty() && std::filesystem::path(o.plot).extension() != ".png") {
        err << "sxk: deform: --plot " << o.plot << ": the plot is a PNG picture; name it *.png\n";
        return cli::exit_usage;
    }
    std::optional<Mesh> mesh = load_mesh_for_command(o.input, err, o.reading);
    if (!mesh)
        return cli::exit_usage;
    Outcome<BuiltBody> built = build_body(*mesh, o.input, *setup);
    if (!built) {
        err << "sxk: " << built.reason() << '\n';
        return cli::exit_usage;
    }
    ElasticBody* body = built->body.get();
    const bool planar = built->planar;
    const Model model = built->model;
    const std::size_t loaded = built->loaded;
    // --json: one object whatever the verdict (docs/cli.md "sxk deform"): the setup, then the
    // solve's figures when it ran, `converged`, and `refusal` when the solve was refused
    auto json_of = [&](const SolveReport* solved, const Refusal* refusal) {
        nlohmann::ordered_json json;
        json["file"] = o.input;
        json["output"] = o.output;
        json["material"] = {{"model", o.body.material}, {"young", o.body.young}, {"poisson", o.body.poisson}};
        if (planar)
            json["thickness"] = body->thickness();
        json["share"] = o.body.share;
        json["elements"] = mesh->element_count();
        json["fixed"] = body->constrained_count();
        json["loaded"] = loaded;
        json["tolerance"] = o.body.tolerance;
        if (solved) {
            json["iterations"] = solved->iterations;
            json["evaluations"] = solved->evaluations;
        }
        json["converged"] = solved != nullptr && solved->converged;
        if (solved) {
            json["residual"] = solved->residual;
            json["threshold"] = solved->threshold;
            json["energy"] = solved->energy;
            json["seconds"] = solved->seconds;
        }
        if (refusal)
            json["refusal"] = {{"code", to_string(refusal->code)}, {"reason", refusal->reason}};
        return json;
    };
    // exit 1, nothing written: `why` on stderr, and the JSON object on stdout with --json
    auto refuse = [&](const std::string& why, const SolveReport* solved, const Refusal* refusal) {
        err << "sxk: " << o.input << ":0: " << why << "; nothing written\n";
        if (o.json) {
            nlohmann::ordered_json json = json_of(solved, refusal);
            if (solved)
                json["history"] = solved->history;
            out << json.dump(2) << '\n';
        }
        return cli::exit_refused;
    };
    const auto report =
        solve(*body, {.tolerance = o.body.tolerance,
                      .max_iterations = o.body.max_iterations,
                      .stop = o.body.stop == "external" ? StopCriterion::external_force : StopCriterion::with_reactions,
                      .rounding = o.body.rounding});
    if (!report) {
        // a refused solve is a refused operation (exit 1, docs/cli.md): loads whose norm
        // overflows, a residual that is not finite, displacements that invert an element even
        // in the linear answer
        const Refusal refusal = report.refusal();
        return refuse(refusal.reason, nullptr, &refusal);
    }
    if (!o.plot.empty()) {
        // drawn before the verdict: a solve that did not converge is the one worth looking at
        pictures::Plot plot;
        plot.title = (model == Model::linear ? "linear CG, " : "nonlinear CG, ") +
                     std::filesystem::path(o.input).filename().string();
        plot.x_label = "iteration";
        plot.y_label = "|r| (projected residual)";
        plot.log_y = true;
        pictures::Series residual;
        residual.label = "|r|";
        for (std::size_t i = 0; i < report->history.size(); ++i) {
            residual.x.push_back(static_cast<double>(i));
            residual.y.push_back(report->history[i]);
        }
        plot.series.push_back(std::move(residual));
        plot.levels.push_back({"stop threshold", report->threshold});
        try {
            pictures::write_png(o.plot, pictures::draw(plot));
        } catch (const std::exception& e) {
            err << "sxk: " << e.what() << '\n';
            return cli::exit_refused;
        }
    }
    if (!report->converged) {
        std::ostringstream why;
        why << (model == Model::linear ? "CG" : "nonlinear CG") << " did not converge in " << report->iterations
            << " iterations (|r| = " << report->residual << ", needed " << report->threshold << ")";
        return refuse(why.str(), &*report, nullptr);
    }
    if (auto written = body->write_deformed(*mesh); !written) {
        const Refusal refusal = written.refusal();
        return refuse(refusal.reason, &*report, &refusal);
    }
    if (!save_mesh_for_command(*mesh, o.output, err))
        return cli::exit_refused;

    VertexId largest = 0;
    double largest_norm = -1;
    for (VertexId v = 0; v < body->vertex_count(); ++v) {
        const Vector3 u = body->displacement(v);
        if (const double n = std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]); n > largest_norm) {
            largest_norm = n;
            largest = v;
        }
    }
    if (o.json) {
        nlohmann::ordered_json json = json_of(&*report, nullptr);
        const Vector3 u = body->displacement(largest);
        json["largest_displacement"] = {
            {"vertex", largest}, {"length", largest_norm}, {"vector", {u[0], u[1], u[2]}}};
        json["history"] = report->history;
        out << json.dump(2) << '\n';
    } else {
        out << o.input << " -> " << o.output << ": " << mesh->element_count()
            << (planar ? " triangles, " : " tetrahedra, ") << body->constrained_count()
            << " vertices held, " << loaded << " loaded\n"
            << (model == Model::linear ? "CG: " : "nonlinear CG: ") << report->iterations
            << " iterations, |r| " << report->residual << " <= " << report->threshold << ", energy "
            << report->energy << ", " << report->seconds << " s\n"
            << "largest displacement " << largest_norm << " at vertex " << largest << '\n';
    }
    return cli::exit_success;
}

}  // namespace sxk::elasticity
