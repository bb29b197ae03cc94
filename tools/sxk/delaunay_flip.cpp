// sxk delaunay-flip IN OUT [--json]: Lawson's edge flips until every interior edge is locally
// Delaunay (thesis §5.2.1; sxk/ops/make_delaunay_by_flips.hpp). Planar triangle meshes only.
#include <memory>

#include <nlohmann/json.hpp>

#include "cli.hpp"
#include "progress.hpp"
#include "sxk/ops/make_delaunay_by_flips.hpp"

namespace sxk::cli {
namespace {

struct DelaunayFlipOptions {
    std::string input;
    std::string output;
    bool json = false;
};

int run_delaunay_flip(Context& context, const DelaunayFlipOptions& options) {
    if (const auto unknown = unknown_format(context, options.output, true)) {
        context.err << "sxk: " << *unknown << '\n';
        return exit_usage;
    }
    std::optional<Mesh> mesh = load_mesh(context, options.input);
    if (!mesh)
        return exit_usage;
    if (mesh->topological_dimension() != 2 || mesh->ambient_dimension() != 2) {
        context.err << "sxk: delaunay-flip needs a planar triangle mesh; " << options.input
                    << " is a "
                    << (mesh->topological_dimension() == 3 ? "tetrahedral mesh"
                                                           : "triangle surface in 3D")
                    << '\n';
        return exit_refused;
    }
    Outcome<std::size_t> flips = std::size_t{0};
    {
        Progress progress("flipping " + options.input);
        flips = make_delaunay_by_flips(*mesh);
    }
    if (!flips) {
        context.err << "sxk: " << flips.reason() << '\n';
        return exit_refused;
    }
    if (!save_mesh(context, *mesh, options.output)) return exit_refused;
    if (options.json) {
        nlohmann::ordered_json json;
        json["input"] = options.input;
        json["output"] = options.output;
        json["flips"] = *flips;
        json["elements"] = mesh->element_count();
        context.report() << json.dump(2) << '\n';
        return exit_success;
    }
    context.report() << options.input << " -> " << options.output << ": " << *flips
                << (*flips == 1 ? " flip, " : " flips, ") << element_count_text(*mesh) << '\n';
    return exit_success;
}

}  // namespace

void add_delaunay_flip_command(CLI::App& app, Context& context) {
    auto options = std::make_shared<DelaunayFlipOptions>();
    CLI::App* command = app.add_subcommand(
        "delaunay-flip",
        "Flip edges (Lawson) until a planar triangle mesh is Delaunay; prints the number of flips");
    command->add_option("IN", options->input, "Input mesh file (planar triangles)")->required();
    command->add_option("OUT", options->output, "Output mesh file")->required();
    command->add_flag("--json", options->json, "Print one JSON object instead of text");
    command->callback(
        [&context, options] { context.exit_code = run_delaunay_flip(context, *options); });
}

}  // namespace sxk::cli
