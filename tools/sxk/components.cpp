// sxk components MESH [--json]: the face-connected components (elements joined through shared
// (d-1)-faces; touching at a vertex or an edge does not join) and their sizes in elements.
#include <memory>

#include <nlohmann/json.hpp>

#include "cli.hpp"
#include "progress.hpp"
#include "sxk/components.hpp"

namespace sxk::cli {
namespace {

struct ComponentsOptions {
    std::string mesh;
    bool json = false;
};

int run_components(Context& context, const ComponentsOptions& options) {
    std::optional<Mesh> mesh = load_mesh(context, options.mesh);
    if (!mesh) return exit_usage;
    Components components;
    {
        Progress progress("components of " + options.mesh);
        components = connected_components(*mesh);
    }
    std::vector<std::size_t> sizes(components.count, 0);
    for (ElementId t : elements(*mesh)) ++sizes[components.element_component[t]];

    if (options.json) {
        nlohmann::ordered_json json;
        json["file"] = options.mesh;
        json["components"] = components.count;
        json["sizes"] = sizes;
        context.out << json.dump(2) << '\n';
        return exit_success;
    }
    context.out << "components: " << components.count << '\n';
    for (std::size_t c = 0; c < sizes.size(); ++c)
        context.out << "  " << c << ": " << element_count_text(*mesh, sizes[c]) << '\n';
    return exit_success;
}

}  // namespace

void add_components_command(CLI::App& app, Context& context) {
    auto options = std::make_shared<ComponentsOptions>();
    CLI::App* command = app.add_subcommand(
        "components", "Face-connected components and their sizes (numbered by smallest element id)");
    command->add_option("MESH", options->mesh, "Mesh file (" + std::string(known_mesh_extensions()) + ")")->required();
    command->add_flag("--json", options->json, "Print one JSON object instead of text");
    command->callback([&context, options] { context.exit_code = run_components(context, *options); });
}

}  // namespace sxk::cli
