// sxk convert IN OUT [--reorient] [--reorder] [--gmsh-version 22|41] [--encoding E] [--json]: the
// formats follow the extensions; --reorder renumbers the vertices by reverse Cuthill-McKee and
// orders the elements by their lowest vertex before writing. What is reported is what OUT holds: a
// tetrahedral mesh written to a format of triangles (.off .obj .stl .ply) is its boundary surface.
#include <memory>

#include <nlohmann/json.hpp>

#include "cli.hpp"
#include "progress.hpp"
#include "sxk/ops/reorder_vertices.hpp"

namespace sxk::cli {
namespace {

struct ConvertOptions {
    std::string input;
    std::string output;
    bool reorient = false;
    bool reorder = false;
    int gmsh_version = 41;
    std::string encoding = "standard";
    bool json = false;
};

int run_convert(Context& context, const ConvertOptions& options) {
    // refuse an unknown output format before spending time on the input
    if (const auto unknown = unknown_format(context, options.output, true)) {
        context.err << "sxk: " << *unknown << '\n';
        return exit_usage;
    }
    // a format with one encoding would silently ignore the request
    const Format format = *format_of(context, options.output);  // checked above
    const bool has_encodings = format == Format::gmsh || format == Format::vtu || format == Format::vtk ||
                               format == Format::stl || format == Format::ply;
    if (options.encoding == "binary" && !has_encodings) {
        context.err << "sxk: convert: --encoding binary: " << to_string(format)
                    << " files are text only (binary: .msh .vtu .vtk .stl .ply)\n";
        return exit_usage;
    }
    ReadOptions read_options;
    read_options.reorient = options.reorient;
    ReadReport report;
    std::optional<Mesh> mesh = load_mesh(context, options.input, read_options, &report);
    if (!mesh) return exit_usage;

    std::size_t bandwidth_before = 0;
    if (options.reorder) {
        Progress progress("reordering " + options.input);
        bandwidth_before = vertex_bandwidth(*mesh);
        *mesh = renumbered(*mesh, cuthill_mckee_order(*mesh));
    }

    WriteOptions write_options;
    write_options.gmsh_version = options.gmsh_version;
    write_options.encoding = *encoding_from_string(options.encoding);  // checked by CLI11
    if (!save_mesh(context, *mesh, options.output, write_options)) return exit_refused;
    const Written written = written_of(*mesh, format);
    if (options.json) {
        nlohmann::ordered_json json;
        json["input"] = options.input;
        json["output"] = options.output;
        json["format"] = to_string(format);
        json["vertices"] = mesh->vertex_count();
        json["elements"] = mesh->element_count();
        json["element_kind"] = element_kind(*mesh);
        json["written"] = {{"vertices", written.vertices},
                           {"elements", written.elements},
                           {"element_kind", written.surface ? "triangle" : element_kind(*mesh)},
                           {"boundary_surface", written.surface}};
        if (options.reorient) json["reoriented"] = report.reoriented;
        if (options.reorder) json["bandwidth"] = {{"before", bandwidth_before}, {"after", vertex_bandwidth(*mesh)}};
        context.report() << json.dump(2) << '\n';
        return exit_success;
    }
    context.report() << options.input << " -> " << options.output << ": " << written_text(*mesh, written);
    if (options.reorient) context.report() << ", " << report.reoriented << " reoriented";
    if (options.reorder)
        context.report() << ", bandwidth " << bandwidth_before << " -> " << vertex_bandwidth(*mesh);
    context.report() << '\n';
    return exit_success;
}

}  // namespace

void add_convert_command(CLI::App& app, Context& context) {
    auto options = std::make_shared<ConvertOptions>();
    CLI::App* command = app.add_subcommand(
        "convert", "Convert between formats by extension: " + std::string(known_mesh_extensions()));
    command->add_option("IN", options->input, "Input mesh file")->required();
    command->add_option("OUT", options->output, "Output mesh file")->required();
    command->add_flag("--reorient", options->reorient, "Flip inverted elements instead of refusing the input");
    command->add_flag("--reorder", options->reorder,
                      "Renumber vertices by reverse Cuthill-McKee (smaller bandwidth), elements by their lowest vertex");
    command->add_option("--gmsh-version", options->gmsh_version, "Gmsh ASCII format version of a .msh output")
        ->check(CLI::IsMember({22, 41}))
        ->capture_default_str();
    command
        ->add_option("--encoding", options->encoding,
                     "standard: each format's usual (.vtu zlib-compressed binary, .msh and .vtk ASCII, .stl and "
                     ".ply binary); ascii; binary (.msh file type 1, .vtu raw appended, .vtk big-endian)")
        ->check(CLI::IsMember({"standard", "ascii", "binary"}))
        ->capture_default_str();
    command->add_flag("--json", options->json, "Print one JSON object instead of the summary line");
    command->callback([&context, options] { context.exit_code = run_convert(context, *options); });
}

}  // namespace sxk::cli
