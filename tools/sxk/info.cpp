// sxk info MESH [--json]: counts (vertices, elements, boundary faces, face-connected
// components), dimensions and the labels present.
#include <memory>
#include <map>
#include <set>

#include <nlohmann/json.hpp>

#include "cli.hpp"
#include "progress.hpp"
#include "sxk/components.hpp"

namespace sxk::cli {
namespace {

struct InfoOptions {
    std::string mesh;
    bool json = false;
};

int run_info(Context& context, const InfoOptions& options) {
    std::optional<Mesh> mesh = load_mesh(context, options.mesh);
    if (!mesh) return exit_usage;

    std::size_t components = 0;
    {
        Progress progress("components of " + options.mesh);
        components = connected_components(*mesh).count;
    }
    std::set<int> element_labels;
    for (ElementId t : elements(*mesh)) element_labels.insert(mesh->label(t));
    std::set<int> face_labels;
    for (const auto& [face, label] : mesh->face_labels()) face_labels.insert(label);

    if (options.json) {
        nlohmann::ordered_json json;
        json["file"] = options.mesh;
        json["vertices"] = mesh->vertex_count();
        json["elements"] = mesh->element_count();
        json["element_kind"] = element_kind(*mesh);
        json["boundary_faces"] = mesh->boundary_face_count();
        json["components"] = components;
        json["topological_dimension"] = mesh->topological_dimension();
        json["ambient_dimension"] = mesh->ambient_dimension();
        json["element_labels"] = element_labels;
        json["face_labels"] = face_labels;
        // names of labels, as files carry them (Gmsh $PhysicalNames): {"7": "bone"}
        auto names = [](const std::map<int, std::string>& given) {
            nlohmann::ordered_json object = nlohmann::ordered_json::object();
            for (const auto& [label, name] : given) object[std::to_string(label)] = name;
            return object;
        };
        json["element_label_names"] = names(mesh->label_names().elements);
        json["face_label_names"] = names(mesh->label_names().faces);
        context.out << json.dump(2) << '\n';
        return exit_success;
    }
    auto list = [](const std::set<int>& labels) {
        std::string text;
        for (int label : labels) text += (text.empty() ? "" : " ") + std::to_string(label);
        return text.empty() ? std::string("none") : text;
    };
    context.out << "file: " << options.mesh << '\n'
                << "vertices: " << mesh->vertex_count() << '\n'
                << "elements: " << element_count_text(*mesh) << '\n'
                << "boundary faces: " << mesh->boundary_face_count() << '\n'
                << "components: " << components << '\n'
                << "topological dimension: " << mesh->topological_dimension() << '\n'
                << "ambient dimension: " << mesh->ambient_dimension() << '\n'
                << "element labels: " << list(element_labels) << '\n'
                << "face labels: " << list(face_labels) << '\n';
    auto named = [&](const char* what, const std::map<int, std::string>& given) {
        if (given.empty()) return;
        context.out << what;
        const char* separator = " ";
        for (const auto& [label, name] : given) {
            context.out << separator << label << " \"" << name << '"';
            separator = ", ";
        }
        context.out << '\n';
    };
    named("element label names:", mesh->label_names().elements);
    named("face label names:", mesh->label_names().faces);
    return exit_success;
}

}  // namespace

void add_info_command(CLI::App& app, Context& context) {
    auto options = std::make_shared<InfoOptions>();
    CLI::App* command = app.add_subcommand(
        "info", "Counts (vertices, elements, boundary faces, face-connected components), dimensions, labels");
    command->add_option("MESH", options->mesh, "Mesh file (" + std::string(known_mesh_extensions()) + ")")->required();
    command->add_flag("--json", options->json, "Print one JSON object instead of text");
    command->callback([&context, options] { context.exit_code = run_info(context, *options); });
}

}  // namespace sxk::cli
