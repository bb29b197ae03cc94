#include <iostream>
#include <new>
#include <set>
#include <sstream>

#include "cli.hpp"

namespace sxk::cli {

namespace {

// The formats a stream can carry: all but TetGen's set of files.
std::string stream_formats() {
    std::string names;
    for (const Format format : {Format::medit, Format::gmsh, Format::off, Format::obj, Format::vtu, Format::vtk,
                                Format::stl, Format::ply})
        names += (names.empty() ? "" : ", ") + std::string(to_string(format));
    return names;
}

// The format --format names for "-", or the message.
std::variant<Format, std::string> stream_format(const Context& context, bool output) {
    const char* stream = output ? "standard output" : "standard input";
    if (context.format.empty())
        return std::string("-:0: ") + stream + " needs --format (" + stream_formats() + ")";
    const std::optional<Format> format = format_from_name(context.format);
    if (!format || *format == Format::tetgen)
        return "-:0: --format " + context.format + ": not a format " + stream + " can carry (" + stream_formats() + ")";
    return *format;
}

}  // namespace

std::optional<std::string> unknown_format(const Context& context, const std::string& file, bool output) {
    if (file == "-") {
        const auto format = stream_format(context, output);
        if (const std::string* why = std::get_if<std::string>(&format)) return *why;
        return std::nullopt;
    }
    return output ? unknown_output_format(file) : std::nullopt;  // an input's extension: the reader says
}

std::optional<Mesh> load_mesh(Context& context, const std::string& file, const ReadOptions& options,
                              ReadReport* report) {
    ReadOptions chosen = options;
    if (context.strict) chosen.split_pinched = chosen.drop_stray_faces = false;
    if (file != "-") {
        std::optional<Mesh> mesh = load_mesh_for_command(file, context.err, chosen, report);
        if (!mesh) context.exit_code = exit_usage;
        return mesh;
    }
    ReadReport own;
    if (!report) report = &own;
    const auto format = stream_format(context, false);
    std::string why;
    if (const std::string* refused = std::get_if<std::string>(&format)) {
        why = *refused;
    } else {
        try {
            Mesh mesh = read_mesh(std::cin, std::get<Format>(format), "-", chosen, report);
            print_read_warnings(context.err, file, *report);
            return mesh;
        } catch (const std::exception& error) {
            why = error.what();
        }
    }
    context.err << "sxk: " << why << '\n';
    context.exit_code = exit_usage;
    return std::nullopt;
}

bool save_mesh(Context& context, const Mesh& mesh, const std::string& file, const WriteOptions& options) {
    if (file == "-") {
        const auto format = stream_format(context, true);
        if (const std::string* why = std::get_if<std::string>(&format)) {
            context.err << "sxk: " << *why << '\n';
            return false;
        }
        WriteOptions checked = options;
        checked.refuse_invalid = true;
        try {
            write_mesh(mesh, context.out, std::get<Format>(format), "-", checked);
        } catch (const std::exception& error) {
            context.err << "sxk: " << write_error_line("-", error) << '\n';
            return false;
        }
        context.out_taken = true;
        return true;
    }
    return save_mesh_for_command(mesh, file, context.err, options);
}

bool read_word_lines(Context& context, const std::string& file,
                     const std::function<std::string(std::size_t line, const std::vector<std::string>& words)>& take) {
    // as a mesh file is read, not an ifstream that takes a directory for an empty list
    std::string text;
    try {
        text = read_text_file(file);
    } catch (const InputError& error) {
        context.err << "sxk: " << error.what() << '\n';
        return false;
    }
    std::istringstream in(text);
    std::string line;
    for (std::size_t number = 1; std::getline(in, line); ++number) {
        if (const auto hash = line.find('#'); hash != std::string::npos) line.resize(hash);
        std::istringstream words(line);
        std::vector<std::string> list;
        for (std::string word; words >> word;) list.push_back(word);
        if (list.empty()) continue;
        if (const std::string reason = take(number, list); !reason.empty()) {
            context.err << "sxk: " << file << ':' << number << ": " << reason << '\n';
            return false;
        }
    }
    return true;
}

std::optional<Format> format_of(const Context& context, const std::string& file) {
    return file == "-" ? format_from_name(context.format) : format_from_extension(file);
}

Written written_of(const Mesh& mesh, Format format) {
    const bool triangles_only =
        format == Format::off || format == Format::obj || format == Format::stl || format == Format::ply;
    if (!triangles_only || mesh.topological_dimension() != 3) return {mesh.vertex_count(), mesh.element_count(), false};
    const std::vector<FaceId> boundary = mesh.boundary_faces();
    std::set<VertexId> on_boundary;
    for (const FaceId f : boundary)
        for (const VertexId v : mesh.face_simplex(f).vertices()) on_boundary.insert(v);
    return {on_boundary.size(), boundary.size(), true};
}

std::string written_text(const Mesh& mesh, const Written& written) {
    if (!written.surface) return std::to_string(mesh.vertex_count()) + " vertices, " + element_count_text(mesh);
    return std::to_string(written.vertices) + " vertices, " + std::to_string(written.elements) +
           (written.elements == 1 ? " triangle" : " triangles") + " (the boundary of " + element_count_text(mesh) + ")";
}

std::string element_count_text(const Mesh& mesh, std::size_t count) {
    const bool tetrahedra = mesh.topological_dimension() == 3;
    const char* noun = count == 1 ? (tetrahedra ? "tetrahedron" : "triangle") : (tetrahedra ? "tetrahedra" : "triangles");
    return std::to_string(count) + ' ' + noun;
}

std::string element_count_text(const Mesh& mesh) { return element_count_text(mesh, mesh.element_count()); }

const char* element_kind(const Mesh& mesh) {
    return mesh.topological_dimension() == 3 ? "tetrahedron" : "triangle";
}

}  // namespace sxk::cli
