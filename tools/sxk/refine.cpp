// sxk refine IN OUT --around X,Y[,Z] --size H [--rule longest-edge|amp] [--json]: refines by
// edge bisection until the element containing the point has edges no longer than H (thesis
// §6.5 refine-around; sxk/ops/refine_around.hpp for triangle meshes,
// sxk/ops/refine_around_tetrahedra.hpp and sxk/ops/tet_bisection.hpp for tetrahedra).
#include <algorithm>
#include <memory>

#include <nlohmann/json.hpp>

#include "cli.hpp"
#include "progress.hpp"
#include "sxk/ops/refine_around.hpp"
#include "sxk/ops/refine_around_tetrahedra.hpp"
#include "sxk/ops/tet_bisection.hpp"

namespace sxk::cli {
namespace {

struct RefineOptions {
    std::string input;
    std::string output;
    std::string around;
    double size = 0;
    std::string rule = "longest-edge";
    bool json = false;
};

// "X,Y" or "X,Y,Z" (Z defaults to 0), each a finite number; an error message for anything else.
std::string parse_point(const std::string& text, Point& point) {
    point = {0, 0, 0};
    auto numbers = parse_number_list(text);
    if (const std::string* error = std::get_if<std::string>(&numbers))
        return *error + " (expected X,Y or X,Y,Z)";
    const std::vector<double>& coordinates = std::get<std::vector<double>>(numbers);
    if (coordinates.size() > 3)
        return "'" + text + "' has more than three coordinates (expected X,Y or X,Y,Z)";
    if (coordinates.size() < 2)
        return "'" + text + "' has one coordinate (expected X,Y or X,Y,Z)";
    std::copy(coordinates.begin(), coordinates.end(), point.begin());
    return {};
}

int run_refine(Context& context, const RefineOptions& options) {
    if (const auto unknown = unknown_format(context, options.output, true)) {
        context.err << "sxk: " << *unknown << '\n';
        return exit_usage;
    }
    Point x{};
    (void)parse_point(options.around, x);  // validated by the option's check
    std::optional<Mesh> mesh = load_mesh(context, options.input);
    if (!mesh)
        return exit_usage;

    std::size_t bisections = 0;
    if (mesh->topological_dimension() == 3) {
        // longest-edge bisection (the general rule of TetBisection; Maubach's on Kuhn meshes
        // bisects the same edges), state-less: its marks are computed from the positions
        // or Arnold-Mukherjee-Pouly's marks (bounded shapes), which need a bisection state
        Outcome<std::size_t> refined = std::size_t{0};
        {
            Progress progress("refining " + options.input);
            if (options.rule == "amp") {
                auto state = TetBisection::with_amp_marking(*mesh);
                refined = state ? refine_around_tetrahedra(*state, x, options.size)
                                : Outcome<std::size_t>(state.refusal());
            } else {
                refined = refine_around_tetrahedra(*mesh, x, options.size);
            }
        }
        if (!refined) {
            context.err << "sxk: " << refined.reason() << '\n';
            return exit_refused;
        }
        bisections = *refined;
    } else {
        Outcome<RefineAroundResult> refined = RefineAroundResult{};
        {
            Progress progress("refining " + options.input);
            refined = refine_around(*mesh, x, options.size);
        }
        if (!refined) {
            context.err << "sxk: " << refined.reason() << '\n';
            return exit_refused;
        }
        bisections = refined->bisections;
    }
    if (!save_mesh(context, *mesh, options.output)) return exit_refused;
    if (options.json) {
        nlohmann::ordered_json json;
        json["input"] = options.input;
        json["output"] = options.output;
        json["bisections"] = bisections;
        json["vertices"] = mesh->vertex_count();
        json["elements"] = mesh->element_count();
        context.report() << json.dump(2) << '\n';
        return exit_success;
    }
    context.report() << options.input << " -> " << options.output << ": " << bisections
                << (bisections == 1 ? " bisection, " : " bisections, ") << mesh->vertex_count()
                << " vertices, " << element_count_text(*mesh) << '\n';
    return exit_success;
}

}  // namespace

void add_refine_command(CLI::App& app, Context& context) {
    auto options = std::make_shared<RefineOptions>();
    CLI::App* command = app.add_subcommand("refine",
                                           "Bisect edges until the element containing a point has "
                                           "edges no longer than a size (thesis §6.5)");
    command->add_option("IN", options->input, "Input mesh file")->required();
    command->add_option("OUT", options->output, "Output mesh file")->required();
    command
        ->add_option("--around", options->around,
                     "The point X,Y (planar meshes) or X,Y,Z, reference positions")
        ->required()
        ->check(CLI::Validator(
            [](std::string& text) {
                Point ignored{};
                return parse_point(text, ignored);
            },
            "X,Y[,Z]"));
    command->add_option("--size", options->size, "Largest edge length H > 0 around the point")
        ->required()
        ->check(CLI::Validator(
            [](std::string& text) {
                const std::optional<double> value = parse_finite_number(text);
                if (!value)
                    return not_a_finite_number(text);
                if (!(*value > 0))
                    return "'" + text + "' is not a positive number";
                return std::string();
            },
            "H > 0"));
    command
        ->add_option("--rule", options->rule,
                     "Tetrahedra: longest-edge (default, no state) or amp (Arnold-Mukherjee-Pouly "
                     "marks: boundedly many shapes); triangles always use the hypotenuse rule")
        ->check(CLI::IsMember({"longest-edge", "amp"}));
    command->add_flag("--json", options->json, "Print one JSON object instead of text");
    command->callback([&context, options] { context.exit_code = run_refine(context, *options); });
}

}  // namespace sxk::cli
