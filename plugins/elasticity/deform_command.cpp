// `sxk deform IN OUT`: a static solve of a tetrahedral mesh, or of a triangle mesh in plane stress,
// under selected constraints and loads, OUT holding the deformed positions (docs/cli.md
// "sxk deform").
#include "deform_command.hpp"

#include <cmath>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "command_line.hpp"
#include "elastic_body.hpp"
#include "line_plot.hpp"
#include "load_shares.hpp"
#include "solve.hpp"
#include "vertex_selector.hpp"

namespace sxk::elasticity {
namespace {

struct Options {
    std::string input, output;
    ReadOptions reading;
    std::vector<std::string> fix, force, displace;
    std::string material = "linear", share = "equal", plot;
    double young = 1e6, poisson = 0.25, tolerance = 1e-6;
    std::optional<double> thickness;
    std::string gravity;
    double density = 1000;
    std::size_t max_iterations = 100000;
    bool json = false;
};

// A selector with a vector: "EXPR:X,Y,Z".
struct Selected {
    VertexSelector selector;
    Vector3 vector{0, 0, 0};
};

std::optional<Options> parse(std::span<const std::string> args, std::ostream& out,
                             std::ostream& err, int& code) {
    Options o;
    CLI::App app(
        "Deforms a tetrahedral mesh, or a triangle mesh in the plane as a slab in plane stress, by "
        "linear "
        "or neo-Hookean elasticity (thesis 3.1, 4.3.3, 6.3): fixed and displaced vertices, loads, "
        "matrix-free linear or nonlinear conjugate gradients; OUT holds the deformed positions",
        "sxk deform");
    app.add_option("IN", o.input, "Input mesh file (tetrahedra in space or triangles in the plane)")
        ->required();
    app.add_option("OUT", o.output,
                   "Output mesh file, format by extension (.mesh .msh .node .ele .off .obj .vtu)")
        ->required();
    app.add_option(
        "--fix", o.fix,
        "Vertices held in place: a selector such as 'x<0.001', 'label=2&boundary' (repeatable)");
    app.add_option("--displace", o.displace,
                   "Vertices moved by a prescribed displacement: 'EXPR:DX,DY,DZ' (repeatable)");
    app.add_option("--force", o.force,
                   "A total force on the selected vertices, shared among them as --share says: "
                   "'EXPR:FX,FY,FZ' "
                   "(repeatable)");
    app.add_option("--share", o.share,
                   "How a --force is shared: equal (the same part each) or area (by the boundary "
                   "area around each "
                   "vertex: a uniform traction on the selected boundary)")
        ->check(CLI::IsMember({"equal", "area"}))
        ->capture_default_str();
    app.add_option("--gravity", o.gravity,
                   "An acceleration on every element's mass, 'GX,GY,GZ' (m/s^2, e.g. 0,-9.8,0): "
                   "each element's weight "
                   "shared equally by its corners");
    app.add_option("--density", o.density, "Mass per volume for --gravity (kg/m^3)")
        ->check(number_in(0, false, 1e300, true, "(0, 1e300]"))
        ->capture_default_str();
    app.add_option("--material", o.material,
                   "Material model: linear (small strains) or neohookean (compressible "
                   "neo-Hookean, large strains, "
                   "nonlinear CG)")
        ->check(CLI::IsMember({"linear", "neohookean"}))
        ->capture_default_str();
    app.add_option("--thickness", o.thickness,
                   "Slab thickness of a triangle mesh in plane stress, > 0 (default 1)")
        ->check(number_in(0, false, 1e300, true, "(0, 1e300]"));
    app.add_option("--E,--young", o.young, "Young's modulus, > 0")
        ->check(number_in(0, false, 1e300, true, "(0, 1e300]"))
        ->capture_default_str();
    app.add_option("--nu,--poisson", o.poisson, "Poisson's ratio, -1 < nu < 0.5")
        ->check(number_in(-1, false, 0.5, false, "(-1, 0.5)"))
        ->capture_default_str();
    app.add_option("--tol", o.tolerance,
                   "Relative tolerance of the residual against the loads and reactions (thesis eq. "
                   "6.9), 0 < tol < 1")
        ->check(number_in(0, false, 1, false, "(0, 1)"))
        ->capture_default_str();
    app.add_option("--max-iterations", o.max_iterations, "Most CG iterations before giving up")
        ->check(CLI::Range(std::size_t{1}, std::size_t{100000000}))
        ->capture_default_str();
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

// Three numbers "A,B,C" of option `option` given as `text`; nullopt with the message printed
// ("expected three numbers NAMES, found 2").
std::optional<Vector3> parse_vector(const std::string& option, const std::string& text,
                                    std::string_view numbers, const char* names,
                                    std::ostream& err) {
    const auto parsed = parse_number_list(numbers);
    if (const std::string* why = std::get_if<std::string>(&parsed)) {
        err << "sxk: deform: " << option << " '" << text << "': " << *why << '\n';
        return std::nullopt;
    }
    const auto& list = std::get<std::vector<double>>(parsed);
    if (list.size() != 3) {
        err << "sxk: deform: " << option << " '" << text << "': expected three numbers " << names
            << ", found " << list.size() << '\n';
        return std::nullopt;
    }
    return Vector3{list[0], list[1], list[2]};
}

// "EXPR" (with_vector false) or "EXPR:X,Y,Z"; nullopt with the message printed.
std::optional<Selected> parse_selected(const std::string& option, const std::string& text,
                                       bool with_vector, std::ostream& err) {
    Selected s;
    std::string expression = text;
    if (with_vector) {
        const std::size_t colon = text.rfind(':');
        if (colon == std::string::npos) {
            err << "sxk: deform: " << option << " '" << text << "': expected SELECTOR:X,Y,Z\n";
            return std::nullopt;
        }
        expression = text.substr(0, colon);
        const std::optional<Vector3> vector = parse_vector(
            option, text, std::string_view(text).substr(colon + 1), "X,Y,Z after ':'", err);
        if (!vector)
            return std::nullopt;
        s.vector = *vector;
    }
    auto selector = parse_vertex_selector(expression);
    if (!selector) {
        err << "sxk: deform: " << option << ": " << selector.reason() << '\n';
        return std::nullopt;
    }
    s.selector = std::move(*selector);
    return s;
}

// Every occurrence of one option; nullopt when one of them does not parse (message printed).
std::optional<std::vector<Selected>> parse_all(const std::string& option,
                                               const std::vector<std::string>& texts,
                                               bool with_vector, std::ostream& err) {
    std::vector<Selected> all;
    for (const std::string& text : texts) {
        std::optional<Selected> s = parse_selected(option, text, with_vector, err);
        if (!s)
            return std::nullopt;
        all.push_back(std::move(*s));
    }
    return all;
}

}  // namespace

std::string_view DeformCommand::summary() const {
    return "deform a tetrahedral or planar triangle mesh by linear or neo-Hookean elasticity: "
           "fixed vertices, loads, "
           "CG (thesis 3.1, 4.3.3, 6.3)";
}

int DeformCommand::run(std::span<const std::string> args, std::ostream& out, std::ostream& err) {
    int code = 0;
    const std::optional<Options> options = parse(args, out, err, code);
    if (!options)
        return code;
    const Options& o = *options;
    const auto fixes = parse_all("--fix", o.fix, false, err);
    const auto displaces = parse_all("--displace", o.displace, true, err);
    const auto forces = parse_all("--force", o.force, true, err);
    if (!fixes || !displaces || !forces)
        return 2;
    Vector3 gravity{0, 0, 0};
    if (!o.gravity.empty()) {
        const std::optional<Vector3> vector =
            parse_vector("--gravity", o.gravity, o.gravity, "GX,GY,GZ", err);
        if (!vector)
            return 2;
        gravity = *vector;
    }
    if (fixes->empty() && displaces->empty()) {
        err << "sxk: deform: nothing holds the body (no --fix or --displace), so it can move "
               "freely and the problem "
               "is singular; fix at least three non-collinear vertices of every connected part\n";
        return 2;
    }
    if (!format_from_extension(o.output)) {
        err << "sxk: " << o.output
            << ":0: unknown output format (known: .mesh .msh .node .ele .off .obj .vtu)\n";
        return 2;
    }
    if (!o.plot.empty() && std::filesystem::path(o.plot).extension() != ".png") {
        err << "sxk: deform: --plot " << o.plot << ": the plot is a PNG picture; name it *.png\n";
        return 2;
    }
    std::optional<Mesh> mesh = load_mesh_for_command(o.input, err, o.reading);
    if (!mesh)
        return 2;
    const bool planar = mesh->topological_dimension() == 2 && mesh->ambient_dimension() == 2;
    if (o.thickness && !planar) {
        err << "sxk: deform: --thickness is for triangle meshes in the plane (plane stress); "
            << o.input << " has " << mesh->topological_dimension() << "-dimensional elements in "
            << mesh->ambient_dimension() << "-dimensional space\n";
        return 2;
    }
    const Model model = o.material == "linear" ? Model::linear : Model::neohookean;
    auto body = ElasticBody::make(*mesh, {.young = o.young, .poisson = o.poisson},
                                  {.model = model, .thickness = o.thickness.value_or(1.0)});
    if (!body) {
        err << "sxk: " << o.input << ":0: " << body.reason() << '\n';
        return 2;
    }
    // selections: one that selects nothing is a mistake worth stopping for (a coordinate off by
    // a unit, a label the file does not have)
    auto select = [&](const std::string& option,
                      const Selected& s) -> std::optional<std::vector<VertexId>> {
        std::vector<VertexId> vertices = select_vertices(*mesh, s.selector);
        if (vertices.empty()) {
            err << "sxk: deform: " << option << " '" << s.selector.text << "' selects no vertex of "
                << o.input << '\n';
            return std::nullopt;
        }
        return vertices;
    };
    std::size_t loaded = 0;
    for (const Selected& s : *fixes) {
        const auto vertices = select("--fix", s);
        if (!vertices)
            return 2;
        for (const VertexId v : *vertices)
            (void)body->fix(v);
    }
    for (const Selected& s : *displaces) {
        const auto vertices = select("--displace", s);
        if (!vertices)
            return 2;
        for (const VertexId v : *vertices)
            (void)body->fix(v, s.vector);
    }
    for (const Selected& s : *forces) {
        const auto vertices = select("--force", s);
        if (!vertices)
            return 2;
        const auto parts =
            load_shares(*mesh, *vertices, o.share == "area" ? Share::area : Share::equal);
        if (!parts) {
            err << "sxk: deform: --force '" << s.selector.text
                << "' --share area: " << parts.reason() << '\n';
            return 2;
        }
        for (std::size_t i = 0; i < vertices->size(); ++i) {
            const double part = (*parts)[i];
            (void)body->add_force((*vertices)[i],
                                  {s.vector[0] * part, s.vector[1] * part, s.vector[2] * part});
        }
    }
    if (!o.gravity.empty()) {
        (void)body->add_body_force(
            {o.density * gravity[0], o.density * gravity[1], o.density * gravity[2]});
    }
    for (VertexId v = 0; v < body->vertex_count(); ++v) {
        const Vector3 f = body->force(v);
        loaded += f[0] != 0 || f[1] != 0 || f[2] != 0;
    }
    const auto report =
        solve(*body, {.tolerance = o.tolerance, .max_iterations = o.max_iterations});
    if (!report) {
        err << "sxk: " << o.input << ":0: " << report.reason() << '\n';
        return 2;
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
            return 1;
        }
    }
    if (!report->converged) {
        err << "sxk: " << o.input << ":0: " << (model == Model::linear ? "CG" : "nonlinear CG")
            << " did not converge in " << report->iterations
            << " iterations (|r| = " << report->residual << ", needed " << report->threshold
            << "); nothing written\n";
        return 1;
    }
    if (auto written = body->write_deformed(*mesh); !written) {
        err << "sxk: " << o.input << ":0: " << written.reason() << "; nothing written\n";
        return 1;
    }
    if (!save_mesh_for_command(*mesh, o.output, err))
        return 1;

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
        nlohmann::ordered_json json;
        json["file"] = o.input;
        json["output"] = o.output;
        json["material"] = {{"model", o.material}, {"young", o.young}, {"poisson", o.poisson}};
        if (planar)
            json["thickness"] = body->thickness();
        json["share"] = o.share;
        json["elements"] = mesh->element_count();
        json["fixed"] = body->constrained_count();
        json["loaded"] = loaded;
        json["tolerance"] = o.tolerance;
        json["iterations"] = report->iterations;
        json["evaluations"] = report->evaluations;
        json["converged"] = report->converged;
        json["residual"] = report->residual;
        json["threshold"] = report->threshold;
        json["energy"] = report->energy;
        json["seconds"] = report->seconds;
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
    return 0;
}

}  // namespace sxk::elasticity
