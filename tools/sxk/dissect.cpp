// sxk dissect IN OUT --faces FILE: opens the mesh along the listed (d-1)-faces (thesis §7.3,
// dissection by (v,C)-connected components; see sxk/ops/dissect.hpp).
//
// FILE lists one face per line as whitespace-separated vertex ids, 0-based in the mesh's own
// numbering (a Medit or Gmsh file numbers from 1: file vertex k is id k-1), in either
// orientation. '#' starts a comment; blank lines are skipped. FILE is read as mesh files are
// (read_text_file): a directory, a device, binary data or a read error is refused. A bad line
// gives "sxk: FILE:LINE: reason" and exit code 2, like any other input error.
#include <charconv>
#include <memory>

#include <nlohmann/json.hpp>

#include "cli.hpp"
#include "progress.hpp"
#include "sxk/components.hpp"
#include "sxk/ops/dissect.hpp"

namespace sxk::cli {
namespace {

struct DissectCommand {
    std::string input;
    std::string output;
    std::string faces;
    int cut_label = default_cut_label;
    bool no_cut_label = false;
    bool json = false;
};

struct FaceList {
    std::vector<Simplex> faces;
    std::vector<std::size_t> lines;  // line number of each face, for messages
};

// Reads the face list; on an unreadable file or a bad line prints the error and returns nullopt.
std::optional<FaceList> read_faces(Context& context, const std::string& file, const Mesh& mesh) {
    const std::size_t wanted = static_cast<std::size_t>(mesh.topological_dimension());
    FaceList list;
    const bool read = read_word_lines(context, file, [&](std::size_t number, const std::vector<std::string>& words) {
        std::vector<VertexId> vertices;
        for (const std::string& word : words) {
            VertexId v = 0;
            const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), v);
            if (error != std::errc() || end != word.data() + word.size()) return "'" + word + "' is not a vertex id";
            if (v >= mesh.vertex_count())
                return "vertex " + word + " does not exist (ids are 0-based, the mesh has " +
                       std::to_string(mesh.vertex_count()) + " vertices)";
            vertices.push_back(v);
        }
        if (vertices.size() != wanted)
            return "a face of a " + std::string(element_kind(mesh)) + " mesh has " + std::to_string(wanted) +
                   " vertices, this line has " + std::to_string(vertices.size());
        list.faces.emplace_back(+1, vertices);
        list.lines.push_back(number);
        return std::string();
    });
    if (!read) return std::nullopt;
    return list;
}

int run_dissect(Context& context, const DissectCommand& options) {
    if (const auto unknown = unknown_format(context, options.output, true)) {
        context.err << "sxk: " << *unknown << '\n';
        return exit_usage;
    }
    std::optional<Mesh> mesh = load_mesh(context, options.input);
    if (!mesh) return exit_usage;
    std::optional<FaceList> list = read_faces(context, options.faces, *mesh);
    if (!list) return exit_usage;

    Outcome<DissectResult> result = DissectResult{};
    {
        Progress progress("dissecting " + options.input);
        DissectOptions dissecting;
        if (options.no_cut_label) dissecting.cut_label.reset();
        else dissecting.cut_label = options.cut_label;
        result = dissect(*mesh, list->faces, dissecting);
    }
    if (!result.ok()) {
        const std::size_t item = result.refusal().item;
        if (item < list->lines.size()) {  // a face of the file: an input error on its line
            context.err << "sxk: " << options.faces << ':' << list->lines[item] << ": " << result.reason() << '\n';
            return exit_usage;
        }
        context.err << "sxk: " << result.reason() << '\n';
        return exit_refused;
    }
    if (!save_mesh(context, *mesh, options.output)) return exit_refused;
    const std::size_t components = connected_components(*mesh).count;
    if (options.json) {
        nlohmann::ordered_json json;
        json["input"] = options.input;
        json["output"] = options.output;
        json["faces"] = options.faces;
        json["cut_faces"] = list->faces.size();
        json["new_vertices"] = result->new_vertices.size();
        json["boundary_faces_on_cut"] = result->opened.size();
        json["components"] = components;
        json["vertices"] = mesh->vertex_count();
        json["elements"] = mesh->element_count();
        context.report() << json.dump(2) << '\n';
        return exit_success;
    }
    context.report() << options.input << " -> " << options.output << ": " << list->faces.size() << " cut faces, "
                << result->new_vertices.size() << " new vertices, " << result->opened.size()
                << " boundary faces on the cut, " << components << " components\n";
    return exit_success;
}

}  // namespace

void add_dissect_command(CLI::App& app, Context& context) {
    auto options = std::make_shared<DissectCommand>();
    CLI::App* command = app.add_subcommand(
        "dissect", "Open the mesh along a list of faces, splitting vertices by (v,C)-connected components");
    command->add_option("IN", options->input, "Input mesh file")->required();
    command->add_option("OUT", options->output, "Output mesh file")->required();
    command->add_option("--faces", options->faces,
                        "Text file: one face per line, 0-based vertex ids of the mesh, '#' comments")
        ->required();
    command->add_option("--cut-label", options->cut_label,
                        "Face label of the boundary faces the cut makes (those without a label of their own), "
                        "written by the formats with face labels and drawn as cut faces by sxk render")
        ->check(whole_number("LABEL"))
        ->capture_default_str();
    command->add_flag("--no-cut-label", options->no_cut_label, "Leave the faces the cut makes unlabelled");
    command->add_flag("--json", options->json, "Print one JSON object instead of the summary line");
    command->callback([&context, options] { context.exit_code = run_dissect(context, *options); });
}

}  // namespace sxk::cli
